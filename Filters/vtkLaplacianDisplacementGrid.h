/**
 * @class   vtkLaplacianDisplacementGrid
 * @brief   a warp's displacement as a grid over space, to warp images and label maps with it
 *
 * The input is a warped point set with its Displacement point array (the output of
 * vtkLaplacianLandmarkWarp, vtkLaplacianDeformationFilter or vtkLaplacianVolumeDeformationFilter
 * with OutputDisplacement on): its points minus their displacement are the rest positions. The
 * output is a vtkImageData whose point array Displacement (also the active scalars) is a
 * continuous displacement field over space, defined inside and outside the surface: trilinear in
 * each voxel, fit to the points' displacements where they are and harmonic between and beyond
 * them (Numerics/DisplacementLattice). vtkGridTransform takes it (SetDisplacementGridData).
 * With Inverse on, the field is the way back, from the warped shape to the rest, over the
 * warped positions: what vtkImageReslice takes as its reslice transform to warp an image or a
 * label map as the surface was warped, without inverting a transform voxel by voxel.
 *
 * The grid spans the rest positions' bounds (the warped ones' with Inverse), padded by Padding
 * of their extent on each side,
 * with Dimensions nodes; or, with an image on input port 1, that image's geometry (origin,
 * spacing and extent), as SlicerMorph samples its warps on a volume's grid.
 *
 * @sa vtkLaplacianLandmarkWarp vtkGridTransform vtkImageReslice
 */
#ifndef vtkLaplacianDisplacementGrid_h
#define vtkLaplacianDisplacementGrid_h

#include "vtkImageAlgorithm.h"
#include "vtkLaplacianEditingFiltersModule.h" // for export macro

class vtkAlgorithmOutput;

class VTKLAPLACIANEDITINGFILTERS_EXPORT vtkLaplacianDisplacementGrid : public vtkImageAlgorithm
{
public:
  static vtkLaplacianDisplacementGrid* New();
  vtkTypeMacro(vtkLaplacianDisplacementGrid, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Nodes along x, y and z, without a reference image. Default 48 each. */
  vtkSetVector3Macro(Dimensions, int);
  vtkGetVector3Macro(Dimensions, int);

  /** Margin around the rest bounds, a fraction of their extent on each side. Default 0.1. */
  vtkSetClampMacro(Padding, double, 0.0, 10.0);
  vtkGetMacro(Padding, double);

  /**
   * How smooth the field is against how closely it meets the points: the weight of its
   * Laplacian, relative to the points' mean weight per node. Default 0.01.
   */
  vtkSetClampMacro(Smoothness, double, 1e-9, 1e9);
  vtkGetMacro(Smoothness, double);

  /**
   * Whether the field maps the warped shape back to the rest (over the warped positions) instead
   * of the rest to the warped shape. Default off.
   */
  vtkSetMacro(Inverse, vtkTypeBool);
  vtkGetMacro(Inverse, vtkTypeBool);
  vtkBooleanMacro(Inverse, vtkTypeBool);

  /** An image whose geometry the grid takes, on input port 1 (optional). */
  void SetReferenceImageConnection(vtkAlgorithmOutput* image) { this->SetInputConnection(1, image); }
  void SetReferenceImageData(vtkDataObject* image);

protected:
  vtkLaplacianDisplacementGrid();
  ~vtkLaplacianDisplacementGrid() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Dimensions[3] = { 48, 48, 48 };
  double Padding = 0.1;
  double Smoothness = 0.01;
  vtkTypeBool Inverse = 0;

private:
  vtkLaplacianDisplacementGrid(const vtkLaplacianDisplacementGrid&) = delete;
  void operator=(const vtkLaplacianDisplacementGrid&) = delete;
};

#endif
