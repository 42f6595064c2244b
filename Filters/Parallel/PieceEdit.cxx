#include "PieceEdit.h"

#include "LaplacianEditor.h"
#include "SurfaceAdapter.h"

#include "vtkDataArray.h"
#include "vtkPolyData.h"

#include <unordered_map>

namespace le = LaplacianEditing;

namespace LaplacianEditing
{
namespace Parallel
{
using Pipeline::EditState;
using Pipeline::MovedPoints;
using Pipeline::NormalRefresher;
using Pipeline::OutputEdit;
using Pipeline::SurfaceAdapter;

namespace
{
// A message is a sequence of arrays, each its length and then its values.
template <typename T>
void PackArray(std::vector<double>& message, const std::vector<T>& values)
{
  message.push_back(static_cast<double>(values.size()));
  message.insert(message.end(), values.begin(), values.end());
}

struct MessageReader
{
  const double* Next;
  const double* End;
  bool Ok = true;

  template <typename T>
  void operator()(std::vector<T>& values)
  {
    const double size = this->Ok && this->Next < this->End ? *this->Next++ : -1.0;
    this->Ok = size >= 0.0 && size <= static_cast<double>(this->End - this->Next);
    values.clear();
    if (this->Ok)
    {
      values.assign(this->Next, this->Next + static_cast<std::size_t>(size));
      this->Next += static_cast<std::size_t>(size);
    }
  }
};

std::vector<double> Flatten(const Eigen::MatrixXd& matrix)
{
  std::vector<double> values = { static_cast<double>(matrix.cols()) };
  values.insert(values.end(), matrix.data(), matrix.data() + matrix.size());
  return values;
}

bool Unflatten(const std::vector<double>& values, Eigen::MatrixXd& matrix)
{
  const Eigen::Index cols = values.empty() ? 0 : static_cast<Eigen::Index>(values[0]);
  const Eigen::Index size = static_cast<Eigen::Index>(values.size()) - 1;
  if (cols < 0 || (cols == 0 && size > 0) || (cols > 0 && size % cols != 0))
  {
    return false;
  }
  matrix = cols > 0 ? Eigen::Map<const Eigen::MatrixXd>(values.data() + 1, size / cols, cols)
                    : Eigen::MatrixXd();
  return true;
}
}

void PieceEdit::Build(const EditState& edit, const Range& piece, bool affine)
{
  const SurfaceAdapter& surface = *edit.Surface;
  const le::EditRegion& region = edit.Editor->GetRegion();
  auto inPiece = [](vtkDataArray* ids, vtkIdType first, vtkIdType count) {
    return [=](vtkIdType id) {
      return id >= first && id < first + count ? static_cast<vtkIdType>(ids->GetComponent(id, 0)) : -1;
    };
  };
  const auto pointId = inPiece(piece.PointIds, piece.FirstPoint, piece.NumberOfPoints);
  std::vector<int> vertices;
  this->Normals = edit.Normals->Restrict(
    pointId, inPiece(piece.CellIds, piece.FirstCell, piece.NumberOfCells), vertices);
  std::unordered_map<int, int> indexOfVertex;
  for (std::size_t i = 0; i < vertices.size(); ++i)
  {
    indexOfVertex.emplace(vertices[i], static_cast<int>(i));
  }
  // The moved points' vertices are in the index already, unless a point has no triangle.
  this->Moved = MovedPoints();
  std::vector<int> movedVertices;
  const MovedPoints& regionPoints = surface.GetRegionPoints();
  for (std::size_t i = 0; i < regionPoints.Ids.size(); ++i)
  {
    const vtkIdType id = pointId(regionPoints.Ids[i]);
    if (id >= 0)
    {
      const int v = region.Vertices[regionPoints.Rows[i]];
      if (indexOfVertex.emplace(v, static_cast<int>(vertices.size())).second)
      {
        vertices.push_back(v);
      }
      this->Moved.Ids.push_back(id);
      movedVertices.push_back(indexOfVertex[v]);
      this->Moved.Roles.push_back(regionPoints.Roles[i]);
    }
  }
  const le::SurfaceMesh& mesh = *surface.GetMesh();
  const std::vector<int>& rowOfVertex = surface.GetRowOfVertex();
  this->Rows.clear();
  this->Rest.clear();
  this->SlotOfVertex.clear();
  for (const int v : vertices)
  {
    this->Rest.push_back(mesh.GetPositions()[v]);
    this->SlotOfVertex.push_back(rowOfVertex[v] >= 0 ? static_cast<int>(this->Rows.size()) : -1);
    if (rowOfVertex[v] >= 0)
    {
      this->Rows.push_back(rowOfVertex[v]);
    }
  }
  for (const int index : movedVertices)
  {
    this->Moved.Rows.push_back(this->SlotOfVertex[index]);
  }
  this->Center = surface.GetCenter();
  this->Scale = surface.GetScale();
  this->Affine = affine ? edit.Editor->GetAffineRows(this->Rows) : le::AffineRows();
  ++this->Version;
}

bool PieceEdit::GetAffineParameters(
  const EditState& edit, Eigen::VectorXd& parameters)
{
  if (!edit.Editor->IsAffineInHandleMaps())
  {
    return false;
  }
  parameters = le::HandleMapParameters(*edit.Maps, edit.Editor->GetRegion().NumberOfHandleGroups);
  return true;
}

le::Positions PieceEdit::GetRowPositions(
  const EditState& edit, const std::vector<int>& rows)
{
  le::Positions positions(static_cast<Eigen::Index>(rows.size()), 3);
  for (std::size_t i = 0; i < rows.size(); ++i)
  {
    positions.row(i) = edit.Solution->row(rows[i]);
  }
  return positions;
}

std::vector<double> PieceEdit::Pack() const
{
  std::vector<double> message = { this->Center[0], this->Center[1], this->Center[2], this->Scale };
  std::vector<double> rest;
  for (const le::Vector3& p : this->Rest)
  {
    rest.insert(rest.end(), p.data(), p.data() + 3);
  }
  PackArray(message, rest);
  PackArray(message, this->Rows);
  PackArray(message, this->SlotOfVertex);
  PackArray(message, this->Moved.Ids);
  PackArray(message, this->Moved.Rows);
  PackArray(message, this->Moved.Roles);
  this->Normals.VisitArrays([&](const auto& values) { PackArray(message, values); });
  PackArray(message, Flatten(this->Affine.Offsets));
  PackArray(message, Flatten(this->Affine.Responses));
  message.push_back(this->Affine.Coupled ? 1.0 : 0.0);
  return message;
}

bool PieceEdit::Unpack(const std::vector<double>& message)
{
  if (message.size() < 4)
  {
    return false;
  }
  this->Center = le::Vector3(message[0], message[1], message[2]);
  this->Scale = message[3];
  MessageReader read{ message.data() + 4, message.data() + message.size() };
  std::vector<double> rest, offsets, responses;
  read(rest);
  read(this->Rows);
  read(this->SlotOfVertex);
  read(this->Moved.Ids);
  read(this->Moved.Rows);
  read(this->Moved.Roles);
  ++this->Version;
  this->Normals.VisitArrays(read);
  read(offsets);
  read(responses);
  this->Affine.Coupled = read.Next < read.End && *read.Next++ != 0.0;
  Eigen::MatrixXd matrix;
  if (!read.Ok || read.Next != read.End || rest.size() != 3 * this->SlotOfVertex.size() ||
    !Unflatten(offsets, matrix) || (matrix.size() > 0 && matrix.cols() != 3))
  {
    return false;
  }
  this->Affine.Offsets = matrix;
  this->Rest.resize(this->SlotOfVertex.size());
  for (std::size_t i = 0; i < this->Rest.size(); ++i)
  {
    this->Rest[i] = le::Vector3(rest[3 * i], rest[3 * i + 1], rest[3 * i + 2]);
  }
  return Unflatten(responses, this->Affine.Responses) &&
    this->Affine.Responses.rows() == (this->Affine.Coupled ? 3 : 1) * this->Affine.Offsets.rows();
}

bool PieceEdit::GetEdit(
  const le::Positions& positions, OutputEdit& edit) const
{
  // A piece whose index holds no region vertex keeps its points and normals.
  if (this->Rows.empty() || positions.rows() != static_cast<Eigen::Index>(this->Rows.size()))
  {
    return false;
  }
  edit.Moved = &this->Moved;
  edit.Solution = &positions;
  edit.Center = this->Center;
  edit.Scale = this->Scale;
  edit.Normals = &this->Normals;
  edit.VertexRest = &this->Rest;
  edit.VertexRows = &this->SlotOfVertex;
  edit.RegionVersion = this->Version;
  return true;
}
}
}
