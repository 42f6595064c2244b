// A label image warped with a surface: the rest surface's inside voxelized, the landmark warp's
// inverse displacement grid (vtkLaplacianDisplacementGrid, warped to rest) as a
// vtkGridTransform, and the label image resliced through it, as SlicerMorph warps volumes. The tests measure it
// against the warped surface voxelized the same way (Dice), and draw it.
#ifndef ImageWarp_h
#define ImageWarp_h

#include "vtkLaplacianDisplacementGrid.h"

#include "vtkGridTransform.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkImageReslice.h"
#include "vtkImageStencil.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkPolyDataToImageStencil.h"
#include "vtkSmartPointer.h"

namespace ImageWarp
{
/// An image of `dimensions` voxels a side over `bounds`, 1 inside the closed `surface`, 0 outside.
inline vtkSmartPointer<vtkImageData> Voxelize(vtkPolyData* surface, const double bounds[6], int dimensions)
{
  vtkNew<vtkImageData> ones;
  ones->SetDimensions(dimensions, dimensions, dimensions);
  ones->SetOrigin(bounds[0], bounds[2], bounds[4]);
  ones->SetSpacing((bounds[1] - bounds[0]) / (dimensions - 1), (bounds[3] - bounds[2]) / (dimensions - 1),
    (bounds[5] - bounds[4]) / (dimensions - 1));
  ones->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  ones->GetPointData()->GetScalars()->Fill(1);
  vtkNew<vtkPolyDataToImageStencil> stencil;
  stencil->SetInputData(surface);
  stencil->SetOutputOrigin(ones->GetOrigin());
  stencil->SetOutputSpacing(ones->GetSpacing());
  stencil->SetOutputWholeExtent(ones->GetExtent());
  vtkNew<vtkImageStencil> inside;
  inside->SetInputData(ones);
  inside->SetStencilConnection(stencil->GetOutputPort());
  inside->SetBackgroundValue(0);
  inside->Update();
  auto labels = vtkSmartPointer<vtkImageData>::New();
  labels->DeepCopy(inside->GetOutput());
  return labels;
}

/// `labels` warped by `warped` (a warp's output with its Displacement array): nearest-neighbour
/// samples of the rest image through the inverse displacement grid (warped to rest).
inline vtkSmartPointer<vtkImageData> WarpLabels(vtkImageData* labels, vtkPointSet* warped)
{
  vtkNew<vtkLaplacianDisplacementGrid> grid;
  grid->SetInputData(warped);
  grid->InverseOn();
  grid->Update();
  vtkNew<vtkGridTransform> transform;
  transform->SetDisplacementGridData(grid->GetOutput());
  transform->SetInterpolationModeToLinear();
  vtkNew<vtkImageReslice> reslice;
  reslice->SetInputData(labels);
  reslice->SetInformationInput(labels);
  reslice->SetResliceTransform(transform);
  reslice->SetInterpolationModeToNearestNeighbor();
  reslice->Update();
  auto result = vtkSmartPointer<vtkImageData>::New();
  result->DeepCopy(reslice->GetOutput());
  return result;
}

/// Dice's coefficient of two label images of one geometry: 2 |A and B| / (|A| + |B|).
inline double Dice(vtkImageData* a, vtkImageData* b)
{
  vtkDataArray* x = a->GetPointData()->GetScalars();
  vtkDataArray* y = b->GetPointData()->GetScalars();
  double both = 0.0, sum = 0.0;
  for (vtkIdType i = 0; i < x->GetNumberOfTuples(); ++i)
  {
    const bool in = x->GetTuple1(i) > 0.5, inToo = y->GetTuple1(i) > 0.5;
    both += in && inToo;
    sum += in + inToo;
  }
  return sum > 0.0 ? 2.0 * both / sum : 1.0;
}
}

#endif
