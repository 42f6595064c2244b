#include "SmoothNormals.h"

#include "GeodesicDistance.h"

#include <algorithm>
#include <numeric>

namespace LaplacianEditing
{
namespace
{
// The paper's fall-off p(t) = 2t^3 - 3t^2 + 1 for t = distance / radius in [0, 1].
double FallOff(double distance, double radius)
{
  const double t = distance / radius;
  return 2.0 * t * t * t - 3.0 * t * t + 1.0;
}

using Reached = std::vector<std::vector<std::pair<int, double>>>;

// Mesh vertices numbered in order of first use: the support, then the one-ring around it.
struct ExtendedIndex
{
  std::vector<int> OfVertex; // -1 where not numbered
  std::vector<int> Vertices;

  int operator()(int v)
  {
    if (this->OfVertex[v] < 0)
    {
      this->OfVertex[v] = static_cast<int>(this->Vertices.size());
      this->Vertices.push_back(v);
    }
    return this->OfVertex[v];
  }
};

// Greedy cover: an uncovered ROI vertex becomes a sample, and covers the ROI vertices within
// the spacing. Returns the samples' ROI rows.
std::vector<int> ChooseSamples(const SurfaceMesh& mesh, const std::vector<int>& vertices,
  const std::vector<int>& roiRow, double spacing, DistanceMethod method)
{
  std::vector<int> sampleRows;
  std::vector<char> covered(vertices.size(), 0);
  GeodesicSearch search(mesh, method);
  // A tolerance keeps vertices at exactly the spacing (regular grids) covered whatever the
  // last bits of their coordinates.
  const double reach = spacing * (1.0 + 1e-6);
  for (std::size_t row = 0; row < vertices.size(); ++row)
  {
    if (covered[row])
    {
      continue;
    }
    sampleRows.push_back(static_cast<int>(row));
    search.Visit({ vertices[row] }, reach, [&](int v, double) {
      if (roiRow[v] >= 0)
      {
        covered[roiRow[v]] = 1;
      }
    });
  }
  return sampleRows;
}

// Each sample's kernel: its weights over the support (numbered by `extended`), written straight
// into the matrix's compressed rows: at 30k vertices they are 1.3M weights, and building them
// through triplets cost more than the searches.
void FillKernels(const Reached& reached, const ExtendedIndex& extended, Eigen::Index entries,
  double radius, Eigen::SparseMatrix<double, Eigen::RowMajor>& kernels)
{
  const int samples = static_cast<int>(reached.size());
  kernels.resize(samples, static_cast<Eigen::Index>(extended.Vertices.size()));
  kernels.resizeNonZeros(entries);
  std::vector<std::pair<int, double>> kernel;
  int entry = 0;
  for (int sample = 0; sample < samples; ++sample)
  {
    kernel.clear();
    for (const auto& [v, d] : reached[sample])
    {
      kernel.emplace_back(extended.OfVertex[v], FallOff(d, radius));
    }
    std::sort(kernel.begin(), kernel.end());
    kernels.outerIndexPtr()[sample] = entry;
    for (const auto& [column, value] : kernel)
    {
      kernels.innerIndexPtr()[entry] = column;
      kernels.valuePtr()[entry++] = value;
    }
  }
  kernels.outerIndexPtr()[samples] = entry;
}

// The samples each ROI vertex blends, within `blendRadius`; `blendStart` holds each row's count
// at the next row's slot.
void FillBlends(const Reached& reached, const std::vector<int>& roiRow, std::vector<int> blendStart,
  double blendRadius, Eigen::SparseMatrix<double, Eigen::RowMajor>& blends)
{
  const int n = static_cast<int>(blendStart.size()) - 1;
  std::partial_sum(blendStart.begin(), blendStart.end(), blendStart.begin());
  blends.resize(n, static_cast<Eigen::Index>(reached.size()));
  blends.resizeNonZeros(blendStart.back());
  std::copy(blendStart.begin(), blendStart.end(), blends.outerIndexPtr());
  std::vector<int> next(blendStart.begin(), blendStart.end() - 1);
  for (std::size_t sample = 0; sample < reached.size(); ++sample) // rows' samples increase
  {
    for (const auto& [v, d] : reached[sample])
    {
      if (roiRow[v] >= 0 && d < blendRadius)
      {
        const int slot = next[roiRow[v]]++;
        blends.innerIndexPtr()[slot] = static_cast<int>(sample);
        blends.valuePtr()[slot] = FallOff(d, blendRadius);
      }
    }
  }
}
}

void SmoothNormals::Build(const SurfaceMesh& mesh, const std::vector<int>& vertices,
  double radius, DistanceMethod method, const ParallelFor& loop)
{
  this->Radius = radius;
  const int n = static_cast<int>(vertices.size());
  const double blendRadius = 0.5 * radius;
  std::vector<int> roiRow(mesh.GetNumberOfVertices(), -1);
  for (int row = 0; row < n; ++row)
  {
    roiRow[vertices[row]] = row;
  }
  // Only the cover's short searches are sequential; the samples' kernels need searches of the
  // full radius, which are independent and run through `loop`.
  const std::vector<int> sampleRows = ChooseSamples(mesh, vertices, roiRow, 0.25 * radius, method);
  const int samples = static_cast<int>(sampleRows.size());
  Reached reached(samples);
  loop(0, samples, [&](int first, int last) {
    GeodesicSearch search(mesh, method);
    for (int sample = first; sample < last; ++sample)
    {
      search.Visit({ vertices[sampleRows[sample]] }, radius,
        [&](int v, double d) { reached[sample].emplace_back(v, d); });
    }
  });
  // The support is numbered in order of discovery, as a serial cover would.
  ExtendedIndex extended{ std::vector<int>(mesh.GetNumberOfVertices(), -1), {} };
  Eigen::Index kernelEntries = 0;
  std::vector<int> blendStart(n + 1, 0);
  for (const auto& visited : reached)
  {
    kernelEntries += static_cast<Eigen::Index>(visited.size());
    for (const auto& [v, d] : visited)
    {
      extended(v);
      if (roiRow[v] >= 0 && d < blendRadius)
      {
        ++blendStart[roiRow[v] + 1];
      }
    }
  }
  this->NumberOfSupportVertices = static_cast<int>(extended.Vertices.size());
  FillKernels(reached, extended, kernelEntries, radius, this->SampleWeights);
  FillBlends(reached, roiRow, std::move(blendStart), blendRadius, this->BlendWeights);
  this->IndexSupportTriangles(mesh, extended.OfVertex, extended.Vertices);
  this->ExtendedRoiRow.resize(extended.Vertices.size());
  this->ExtendedRest.resize(static_cast<Eigen::Index>(extended.Vertices.size()), 3);
  for (std::size_t e = 0; e < extended.Vertices.size(); ++e)
  {
    this->ExtendedRoiRow[e] = roiRow[extended.Vertices[e]];
    this->ExtendedRest.row(e) = mesh.GetPositions()[extended.Vertices[e]].transpose();
  }
}

void SmoothNormals::IndexSupportTriangles(
  const SurfaceMesh& mesh, std::vector<int>& extended, std::vector<int>& extendedVertices)
{
  // Area normals of the support need the triangles around it, and their corners, which join
  // the extended index.
  ExtendedIndex index{ std::move(extended), std::move(extendedVertices) };
  std::vector<char> seen(mesh.GetNumberOfTriangles(), 0);
  this->Triangles.clear();
  for (int s = 0; s < this->NumberOfSupportVertices; ++s)
  {
    const int v = index.Vertices[s];
    for (const int* t = mesh.TrianglesBegin(v); t != mesh.TrianglesEnd(v); ++t)
    {
      if (!seen[*t])
      {
        seen[*t] = 1;
        const auto& tri = mesh.GetTriangles()[*t];
        this->Triangles.push_back({ index(tri[0]), index(tri[1]), index(tri[2]) });
      }
    }
  }
  std::vector<std::vector<int>> around(this->NumberOfSupportVertices);
  for (std::size_t t = 0; t < this->Triangles.size(); ++t)
  {
    for (int corner : this->Triangles[t])
    {
      if (corner < this->NumberOfSupportVertices)
      {
        around[corner].push_back(static_cast<int>(t));
      }
    }
  }
  this->SupportTriangleOffsets.assign(this->NumberOfSupportVertices + 1, 0);
  this->SupportTriangles.clear();
  for (int s = 0; s < this->NumberOfSupportVertices; ++s)
  {
    this->SupportTriangles.insert(this->SupportTriangles.end(), around[s].begin(), around[s].end());
    this->SupportTriangleOffsets[s + 1] = static_cast<int>(this->SupportTriangles.size());
  }
  extended = std::move(index.OfVertex);
  extendedVertices = std::move(index.Vertices);
}

Positions SmoothNormals::Compute(const Positions& roiPositions, const ParallelFor& loop) const
{
  // Rows are gathered through index lists: row-major keeps each row in one cache line.
  using Rows3 = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
  Rows3 current = this->ExtendedRest;
  for (Eigen::Index e = 0; e < current.rows(); ++e)
  {
    if (this->ExtendedRoiRow[e] >= 0)
    {
      current.row(e) = roiPositions.row(this->ExtendedRoiRow[e]);
    }
  }
  // Triangle normals (twice the area, which the normalizations cancel), then their sums at the
  // support vertices, then the two weighted averages: every loop is over independent rows.
  Rows3 triangleNormals(static_cast<Eigen::Index>(this->Triangles.size()), 3);
  loop(0, static_cast<int>(this->Triangles.size()), [&](int first, int last) {
    for (int t = first; t < last; ++t)
    {
      const auto& tri = this->Triangles[t];
      triangleNormals.row(t) =
        (current.row(tri[1]) - current.row(tri[0])).cross(current.row(tri[2]) - current.row(tri[0]));
    }
  });
  Rows3 areaNormals(this->NumberOfSupportVertices, 3);
  loop(0, this->NumberOfSupportVertices, [&](int first, int last) {
    for (int s = first; s < last; ++s)
    {
      Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
      for (int k = this->SupportTriangleOffsets[s]; k < this->SupportTriangleOffsets[s + 1]; ++k)
      {
        sum += triangleNormals.row(this->SupportTriangles[k]);
      }
      areaNormals.row(s) = sum;
    }
  });
  auto average = [&](const Eigen::SparseMatrix<double, Eigen::RowMajor>& weights,
                   const Rows3& values) {
    Rows3 result(weights.rows(), 3);
    loop(0, static_cast<int>(weights.rows()), [&](int first, int last) {
      for (int row = first; row < last; ++row)
      {
        Eigen::RowVector3d sum = Eigen::RowVector3d::Zero();
        for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(weights, row); it; ++it)
        {
          sum += it.value() * values.row(it.col());
        }
        result.row(row) = sum.normalized();
      }
    });
    return result;
  };
  return average(this->BlendWeights, average(this->SampleWeights, areaNormals));
}
}
