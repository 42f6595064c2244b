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
}

void SmoothNormals::Build(const SurfaceMesh& mesh, const std::vector<int>& vertices,
  double radius, DistanceMethod method, const ParallelFor& loop)
{
  this->Radius = radius;
  this->Method = method;
  const auto& positions = mesh.GetPositions();
  const int n = static_cast<int>(vertices.size());
  const double spacing = 0.25 * radius;
  const double blendRadius = 0.5 * radius;
  std::vector<int> roiRow(mesh.GetNumberOfVertices(), -1);
  for (int row = 0; row < n; ++row)
  {
    roiRow[vertices[row]] = row;
  }

  // Extended index: support vertices first (in order of discovery), then their one-ring.
  std::vector<int> extended(mesh.GetNumberOfVertices(), -1);
  std::vector<int> extendedVertices;
  auto extend = [&](int v) {
    if (extended[v] < 0)
    {
      extended[v] = static_cast<int>(extendedVertices.size());
      extendedVertices.push_back(v);
    }
    return extended[v];
  };

  // Greedy cover: an uncovered ROI vertex becomes a sample, and covers the ROI vertices within
  // the spacing. Only that short search is sequential; the samples' kernels need searches of
  // the full radius, which are independent and run through `loop`.
  std::vector<int> sampleRows;
  {
    std::vector<char> covered(n, 0);
    GeodesicSearch search(mesh, method);
    // A tolerance keeps vertices at exactly the spacing (regular grids) covered whatever the
    // last bits of their coordinates.
    const double reach = spacing * (1.0 + 1e-6);
    for (int row = 0; row < n; ++row)
    {
      if (covered[row])
      {
        continue;
      }
      sampleRows.push_back(row);
      search.Visit({ vertices[row] }, reach, [&](int v, double) {
        if (roiRow[v] >= 0)
        {
          covered[roiRow[v]] = 1;
        }
      });
    }
  }
  const int samples = static_cast<int>(sampleRows.size());
  std::vector<std::vector<std::pair<int, double>>> reached(samples);
  loop(0, samples, [&](int first, int last) {
    GeodesicSearch search(mesh, method);
    for (int sample = first; sample < last; ++sample)
    {
      search.Visit({ vertices[sampleRows[sample]] }, radius,
        [&](int v, double d) { reached[sample].emplace_back(v, d); });
    }
  });
  // Each sample's kernel, and the ROI vertices it blends into, written straight into the
  // matrices' compressed rows: at 30k vertices they are 1.3M weights, and building them through
  // triplets cost more than the searches. The support is numbered in order of discovery, as a
  // serial cover would.
  Eigen::Index kernelEntries = 0;
  std::vector<int> blendStart(n + 1, 0);
  for (const auto& visited : reached)
  {
    kernelEntries += static_cast<Eigen::Index>(visited.size());
    for (const auto& [v, d] : visited)
    {
      extend(v);
      if (roiRow[v] >= 0 && d < blendRadius)
      {
        ++blendStart[roiRow[v] + 1];
      }
    }
  }
  this->NumberOfSupportVertices = static_cast<int>(extendedVertices.size());
  auto& kernels = this->SampleWeights;
  kernels.resize(samples, this->NumberOfSupportVertices);
  kernels.resizeNonZeros(kernelEntries);
  std::vector<std::pair<int, double>> kernel;
  int entry = 0;
  for (int sample = 0; sample < samples; ++sample)
  {
    kernel.clear();
    for (const auto& [v, d] : reached[sample])
    {
      kernel.emplace_back(extended[v], FallOff(d, radius));
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

  std::partial_sum(blendStart.begin(), blendStart.end(), blendStart.begin());
  auto& blends = this->BlendWeights;
  blends.resize(n, samples);
  blends.resizeNonZeros(blendStart.back());
  std::copy(blendStart.begin(), blendStart.end(), blends.outerIndexPtr());
  std::vector<int> next(blendStart.begin(), blendStart.end() - 1);
  for (int sample = 0; sample < samples; ++sample) // each row's samples in increasing order
  {
    for (const auto& [v, d] : reached[sample])
    {
      if (roiRow[v] >= 0 && d < blendRadius)
      {
        const int slot = next[roiRow[v]]++;
        blends.innerIndexPtr()[slot] = sample;
        blends.valuePtr()[slot] = FallOff(d, blendRadius);
      }
    }
  }

  // Area normals of the support need the triangles around it, and their corners.
  std::vector<char> seen(mesh.GetNumberOfTriangles(), 0);
  this->Triangles.clear();
  for (int s = 0; s < this->NumberOfSupportVertices; ++s)
  {
    const int v = extendedVertices[s];
    for (const int* t = mesh.TrianglesBegin(v); t != mesh.TrianglesEnd(v); ++t)
    {
      if (!seen[*t])
      {
        seen[*t] = 1;
        const auto& tri = mesh.GetTriangles()[*t];
        this->Triangles.push_back({ extend(tri[0]), extend(tri[1]), extend(tri[2]) });
      }
    }
  }
  this->SupportTriangleOffsets.assign(this->NumberOfSupportVertices + 1, 0);
  this->SupportTriangles.clear();
  {
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
    for (int s = 0; s < this->NumberOfSupportVertices; ++s)
    {
      this->SupportTriangles.insert(this->SupportTriangles.end(), around[s].begin(), around[s].end());
      this->SupportTriangleOffsets[s + 1] = static_cast<int>(this->SupportTriangles.size());
    }
  }
  this->ExtendedRoiRow.resize(extendedVertices.size());
  this->ExtendedRest.resize(static_cast<Eigen::Index>(extendedVertices.size()), 3);
  for (std::size_t e = 0; e < extendedVertices.size(); ++e)
  {
    this->ExtendedRoiRow[e] = roiRow[extendedVertices[e]];
    this->ExtendedRest.row(e) = positions[extendedVertices[e]].transpose();
  }
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
