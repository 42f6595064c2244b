/**
 * @class   vtkBumpyPlaneSource
 * @brief   a unit square height field with a regular grid of smooth bumps
 *
 * The test shape of the paper's Fig. 6 (top): a triangulated square [0,1] x [0,1] in the xy
 * plane, with BumpsPerSide x BumpsPerSide bumps of height BumpHeight. Each bump is a smooth
 * compactly supported cosine cap of radius BumpRadius. Used by the demo, the tests and the
 * examples as a mesh that needs no data files.
 */
#ifndef vtkBumpyPlaneSource_h
#define vtkBumpyPlaneSource_h

#include "vtkLaplacianEditingModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class VTKLAPLACIANEDITING_EXPORT vtkBumpyPlaneSource : public vtkPolyDataAlgorithm
{
public:
  static vtkBumpyPlaneSource* New();
  vtkTypeMacro(vtkBumpyPlaneSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Quads per side of the grid (each split into two triangles). Default 80.
   */
  vtkSetClampMacro(Resolution, int, 1, 4096);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /**
   * Bumps per side, their height and radius. Defaults 5, 0.04 and 0.06.
   */
  vtkSetClampMacro(BumpsPerSide, int, 0, 64);
  vtkGetMacro(BumpsPerSide, int);
  vtkSetMacro(BumpHeight, double);
  vtkGetMacro(BumpHeight, double);
  vtkSetClampMacro(BumpRadius, double, 0.0, 1.0);
  vtkGetMacro(BumpRadius, double);
  ///@}

  /**
   * Centre (x, y) of bump `i` of BumpsPerSide^2, row by row.
   */
  void GetBumpCenter(int i, double center[2]);

protected:
  vtkBumpyPlaneSource();
  ~vtkBumpyPlaneSource() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Resolution = 80;
  int BumpsPerSide = 5;
  double BumpHeight = 0.04;
  double BumpRadius = 0.06;

private:
  vtkBumpyPlaneSource(const vtkBumpyPlaneSource&) = delete;
  void operator=(const vtkBumpyPlaneSource&) = delete;
};

#endif
