// The reference edits the quality benchmark and tests share, on ../shared/data:
//  - cactus: CGAL's cactus.off with cactus.sel (0 fixed, 1 ROI, 2 handle) and the 70-degree
//    turn of cactus.def;
//  - twist: stanford-bunny.obj with unused vertices dropped; the handle is the highest vertex
//    (an ear tip), with an edge-path ROI of 0.15 and a handle of 0.03 of the diagonal, turned
//    120 degrees about the ear's long axis (the ROI's principal axis) through its centroid;
//  - bend: bumps.obj, a large region: the quarter of the sheet at its low x fixed, the strip of
//    its last 2% at high x the handle, turned 60 degrees about the z axis (the strip's
//    direction) through the handle's centroid and lifted by 1% of the sheet's width. The
//    rotation must travel across three quarters of the sheet, which ARAP does slowly.
#ifndef ReferenceEdits_h
#define ReferenceEdits_h

#include "MeshReader.h"

#include "EditMeasures.h"
#include "SurfaceMesh.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCleanPolyData.h"
#include "vtkDataArray.h"
#include "vtkIntArray.h"
#include "vtkLaplacianDeformationFilter.h"
#include "SurfaceAdapter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkTransform.h"

#include <Eigen/Eigenvalues>

#include <cstdint>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace ReferenceEdits
{
namespace le = LaplacianEditing;

// One edit: a welded mesh, per-point labels (0 fixed, 1 ROI, 2 handle) and the handle's map.
struct Edit
{
  std::string Name;
  vtkSmartPointer<vtkPolyData> Mesh;
  vtkSmartPointer<vtkIntArray> Labels;
  vtkNew<vtkTransform> Handle;
};

inline vtkSmartPointer<vtkPolyData> Weld(vtkPolyData* mesh)
{
  // One vertex per position, and unused points dropped: CGAL cannot weld.
  vtkNew<vtkCleanPolyData> weld;
  weld->SetInputData(mesh);
  weld->PointMergingOn();
  weld->SetTolerance(0.0);
  weld->Update();
  return weld->GetOutput();
}

// Lines of numbers, skipping '#' comments (the .sel and .def formats).
inline std::vector<double> ReadNumbers(const std::string& path)
{
  std::ifstream file(path);
  std::vector<double> numbers;
  for (std::string line; std::getline(file, line);)
  {
    std::istringstream words(line.substr(0, line.find('#')));
    for (double value; words >> value;)
    {
      numbers.push_back(value);
    }
  }
  return numbers;
}

inline bool LoadCactus(const std::string& data, Edit& edit)
{
  std::string error;
  edit.Mesh = MeshReader::Read(data + "/cactus.off", error);
  const std::vector<double> labels = ReadNumbers(data + "/cactus.sel");
  const std::vector<double> matrix = ReadNumbers(data + "/cactus.def");
  if (!edit.Mesh || static_cast<vtkIdType>(labels.size()) != edit.Mesh->GetNumberOfPoints() ||
    matrix.size() != 16)
  {
    std::cerr << "error: cannot read the cactus edit " << error << "\n";
    return false;
  }
  edit.Labels = vtkSmartPointer<vtkIntArray>::New();
  edit.Labels->SetName("Selection");
  for (double label : labels)
  {
    edit.Labels->InsertNextValue(static_cast<int>(label));
  }
  edit.Handle->SetMatrix(matrix.data());
  return true;
}

// Labels (0 fixed, 1 ROI, 2 handle) from the filter's EditRole array, so that every mode and
// CGAL edit the same vertex sets; nullptr without a region.
inline vtkSmartPointer<vtkIntArray> LabelsFromRoles(vtkDataArray* roles)
{
  if (!roles)
  {
    return nullptr;
  }
  auto labels = vtkSmartPointer<vtkIntArray>::New();
  labels->SetName("Selection");
  for (vtkIdType i = 0; i < roles->GetNumberOfTuples(); ++i)
  {
    const int role = static_cast<int>(roles->GetTuple1(i));
    labels->InsertNextValue(role == vtkLaplacianDeformationFilter::ROLE_HANDLE ? 2
        : role == vtkLaplacianDeformationFilter::ROLE_FIXED                   ? 0
                                                                              : 1);
  }
  return labels;
}

/// `bend`: turn about the ROI's second principal axis (bending the ear over) instead of its
/// long axis.
inline bool LoadTwist(const std::string& data, Edit& edit, double degrees = 120.0, bool bend = false)
{
  std::string error;
  vtkSmartPointer<vtkPolyData> bunny = MeshReader::Read(data + "/stanford-bunny.obj", error);
  if (!bunny)
  {
    std::cerr << "error: " << error << "\n";
    return false;
  }
  edit.Mesh = Weld(bunny);
  vtkPoints* points = edit.Mesh->GetPoints();
  vtkIdType tip = 0;
  for (vtkIdType i = 1; i < points->GetNumberOfPoints(); ++i)
  {
    tip = points->GetPoint(i)[1] > points->GetPoint(tip)[1] ? i : tip;
  }
  // The region, by the filter's own geodesic selection.
  vtkNew<vtkLaplacianDeformationFilter> select;
  select->SetInputData(edit.Mesh);
  select->SetHandleCenter(points->GetPoint(tip));
  select->SetROIRadius(0.15 * edit.Mesh->GetLength());
  select->SetHandleRadius(0.03 * edit.Mesh->GetLength());
  select->Update();
  edit.Labels = LabelsFromRoles(select->GetOutput()->GetPointData()->GetArray("EditRole"));
  if (!edit.Labels)
  {
    std::cerr << "error: the twist's region is empty\n";
    return false;
  }
  Eigen::Vector3d roiMean = Eigen::Vector3d::Zero(), handleMean = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector3d> roi;
  int handles = 0;
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    const int label = edit.Labels->GetValue(i);
    const Eigen::Vector3d p(points->GetPoint(i));
    if (label > 0)
    {
      roi.push_back(p);
      roiMean += p;
    }
    if (label == 2)
    {
      handleMean += p;
      ++handles;
    }
  }
  if (roi.empty() || handles == 0)
  {
    std::cerr << "error: the twist's region is empty\n";
    return false;
  }
  roiMean /= static_cast<double>(roi.size());
  handleMean /= handles;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const auto& p : roi)
  {
    covariance += (p - roiMean) * (p - roiMean).transpose();
  }
  const Eigen::Vector3d axis =
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(covariance).eigenvectors().col(bend ? 1 : 2);
  edit.Handle->PostMultiply();
  edit.Handle->Translate(-handleMean[0], -handleMean[1], -handleMean[2]);
  edit.Handle->RotateWXYZ(degrees, axis.data());
  edit.Handle->Translate(handleMean.data());
  return true;
}

// The bumpy sheet bent: see the top of this file.
inline bool LoadBend(const std::string& data, Edit& edit)
{
  std::string error;
  vtkSmartPointer<vtkPolyData> bumps = MeshReader::Read(data + "/bumps.obj", error);
  if (!bumps)
  {
    std::cerr << "error: " << error << "\n";
    return false;
  }
  edit.Mesh = Weld(bumps);
  const double* bounds = edit.Mesh->GetBounds();
  const double width = bounds[1] - bounds[0];
  edit.Labels = vtkSmartPointer<vtkIntArray>::New();
  edit.Labels->SetName("Selection");
  Eigen::Vector3d handleMean = Eigen::Vector3d::Zero();
  int handles = 0;
  for (vtkIdType i = 0; i < edit.Mesh->GetNumberOfPoints(); ++i)
  {
    const Eigen::Vector3d p(edit.Mesh->GetPoint(i));
    const double x = (p.x() - bounds[0]) / width;
    const int label = x < 0.25 ? 0 : x > 0.98 ? 2 : 1;
    edit.Labels->InsertNextValue(label);
    if (label == 2)
    {
      handleMean += p;
      ++handles;
    }
  }
  handleMean /= std::max(handles, 1);
  edit.Handle->PostMultiply();
  edit.Handle->Translate(-handleMean[0], -handleMean[1], -handleMean[2]);
  edit.Handle->RotateZ(60.0);
  edit.Handle->Translate(handleMean[0], handleMean[1] + 0.01 * width, handleMean[2]);
  return handles > 0;
}

// Armadillo's hand: the handle at vertex 0 (a fingertip), an edge-path ROI of 0.25 and a handle
// of 0.04 of the diagonal, translated by 0.01 of the diagonal away from the mesh's centre.
inline bool LoadArmadilloHand(const std::string& data, Edit& edit)
{
  std::string error;
  vtkSmartPointer<vtkPolyData> armadillo = MeshReader::Read(data + "/Armadillo.ply", error);
  if (!armadillo)
  {
    std::cerr << "error: " << error << "\n";
    return false;
  }
  edit.Mesh = Weld(armadillo);
  const double diagonal = edit.Mesh->GetLength();
  double tip[3], center[3];
  edit.Mesh->GetPoint(0, tip);
  edit.Mesh->GetCenter(center);
  vtkNew<vtkLaplacianDeformationFilter> select;
  select->SetInputData(edit.Mesh);
  select->SetHandleCenter(tip);
  select->SetROIRadius(0.25 * diagonal);
  select->SetHandleRadius(0.04 * diagonal);
  select->Update();
  edit.Labels = LabelsFromRoles(select->GetOutput()->GetPointData()->GetArray("EditRole"));
  const Eigen::Vector3d out = (Eigen::Vector3d(tip) - Eigen::Vector3d(center)).normalized();
  edit.Handle->Translate((0.01 * diagonal * out).eval().data());
  return edit.Labels != nullptr;
}

// The filter set up for an edit: array selection on its labels, the handle not yet moved.
inline void Configure(const Edit& edit, vtkLaplacianDeformationFilter* filter)
{
  vtkNew<vtkPolyData> input;
  input->ShallowCopy(edit.Mesh);
  input->GetPointData()->AddArray(edit.Labels);
  filter->SetInputData(input);
  filter->SetSelectionModeToArray();
  filter->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, "Selection");
}

// The core's view of a welded mesh, for the measures.
struct Measured
{
  le::SurfaceMesh Mesh;
  std::vector<int> Region;

  Measured(vtkPolyData* mesh, vtkIntArray* labels)
  {
    std::vector<le::Vector3> points(mesh->GetNumberOfPoints());
    for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
    {
      points[i] = le::Vector3(mesh->GetPoint(i));
    }
    std::vector<std::int64_t> offsets, connectivity;
    LaplacianEditing::Pipeline::SurfaceAdapter::GetPolygons(mesh, offsets, connectivity);
    this->Mesh = le::SurfaceMesh::FromPolygons(points, offsets, connectivity, false);
    for (vtkIdType i = 0; i < labels->GetNumberOfTuples(); ++i)
    {
      if (labels->GetValue(i) > 0)
      {
        this->Region.push_back(static_cast<int>(i));
      }
    }
  }

  // The farthest move of a vertex outside the handle, over the handle's largest move.
  double FreeMotionRatio(const std::vector<le::Vector3>& deformed, vtkIntArray* labels) const
  {
    double handle = 0.0, free = 0.0;
    for (int v : this->Region)
    {
      const double move = (deformed[v] - this->Mesh.GetPositions()[v]).norm();
      double& largest = labels->GetValue(v) >= 2 ? handle : free;
      largest = std::max(largest, move);
    }
    return handle > 0.0 ? free / handle : 0.0;
  }

  // The area of the triangles with a region vertex (all of them if `wholeSurface`).
  double Area(bool wholeSurface) const
  {
    std::vector<char> inRegion(this->Mesh.GetNumberOfVertices(), wholeSurface ? 1 : 0);
    for (int v : this->Region)
    {
      inRegion[v] = 1;
    }
    const std::vector<le::Vector3>& p = this->Mesh.GetPositions();
    double area = 0.0;
    for (const std::array<int, 3>& t : this->Mesh.GetTriangles())
    {
      if (inRegion[t[0]] || inRegion[t[1]] || inRegion[t[2]])
      {
        area += 0.5 * (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).norm();
      }
    }
    return area;
  }

  // The root-mean-square distance between two results over the region.
  double Distance(const std::vector<le::Vector3>& a, const std::vector<le::Vector3>& b) const
  {
    double sum = 0.0;
    for (int v : this->Region)
    {
      sum += (a[v] - b[v]).squaredNorm();
    }
    return std::sqrt(sum / this->Region.size());
  }

  std::string Json(const std::vector<le::Vector3>& deformed) const
  {
    const le::EditMeasures measures = le::MeasureEdit(this->Mesh, this->Region, deformed);
    std::ostringstream json;
    json << std::setprecision(5) << "\"energy\": " << measures.Energy
         << ", \"area_ratio\": " << measures.AreaRatio
         << ", \"turned_over\": " << measures.TurnedOverFaces;
    return json.str();
  }
};

inline std::vector<le::Vector3> PointsOf(vtkPolyData* mesh)
{
  std::vector<le::Vector3> points(mesh->GetNumberOfPoints());
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    points[i] = le::Vector3(mesh->GetPoint(i));
  }
  return points;
}

}

#endif
