#include "RegionProxy.h"

#include "GeodesicDistance.h"
#include "SimdClones.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>

namespace LaplacianEditing
{
namespace
{
// Nodes cover their cells at about this density: the area of a cell over the square of the
// spacing (a hexagonal packing gives 0.87; a greedy sampling leaves gaps between discs).
constexpr double CellAreaOverSpacingSquared = 1.1;
// A vertex's weights reach the nodes within this many of their spacings.
constexpr double SupportOverSpacing = 1.8;
// The spacing grows with the distance from the handles' borders at this rate, from the surface's
// own edge length to the spacing asked for: the fine shape bends most sharply along those
// borders, where a uniform proxy left 9 times the converged energy (a 143k-vertex region of
// scan:3:Armadillo.ply on 4,632 nodes).
constexpr double Grading = 0.3;
// The band of fixed vertices sampled around the ROI, in spacings.
constexpr double BandOverSpacing = 2.5;

// Rows [first, last) of the prolongation, x = b + M b + u with (M | u) the rows' weighted sums
// of the nodes' motions (3 x 4 column-major, 12 doubles each); coordinates by column, as
// Positions holds them (`count` rows a column). A row's weights sum to one, so its first node's
// motion plus the others' differences from it, weighted, is the sum: the first weight is never
// read, and where the nodes move alike (a rigid motion) the differences vanish and the blend is
// exact whatever the weights' precision, which lets them be floats. Four doubles at a time: the
// blend is bound by memory (9 weights a row, with their nodes; a 610k-vertex region's drag step
// spent 6 ms here, Documentation/performance.md, "Large regions").
LAPLACIAN_EDITING_SIMD_CLONES
void BlendRows(int first, int last, const int* offsets, const int* nodes, const float* weights,
  const double* motions, const double* base, double* out, int count)
{
#if defined(__GNUC__)
  using Lanes = double __attribute__((vector_size(32), aligned(8)));
#endif
  for (int k = first; k < last; ++k)
  {
    if (offsets[k] == offsets[k + 1]) // no weights (a handle's row, which Prolong writes)
    {
      for (int r = 0; r < 3; ++r)
      {
        out[r * count + k] = base[r * count + k];
      }
      continue;
    }
    double blend[12];
    const double* firstMotion = motions + 12 * nodes[offsets[k]];
#if defined(__GNUC__)
    // The first motion is loaded where it is used: kept in an array of lanes, it went through the
    // stack, its stores stalling the loads that followed.
    Lanes sum[3] = {};
    for (int e = offsets[k] + 1; e < offsets[k + 1]; ++e)
    {
      const double w = weights[e];
      const double* motion = motions + 12 * nodes[e];
      for (int v = 0; v < 3; ++v)
      {
        Lanes part, head;
        std::memcpy(&part, motion + 4 * v, sizeof(part));
        std::memcpy(&head, firstMotion + 4 * v, sizeof(head));
        sum[v] += w * (part - head);
      }
    }
    for (int v = 0; v < 3; ++v)
    {
      Lanes head;
      std::memcpy(&head, firstMotion + 4 * v, sizeof(head));
      sum[v] += head;
    }
    std::memcpy(blend, sum, sizeof(blend));
#else
    std::fill(blend, blend + 12, 0.0);
    for (int e = offsets[k] + 1; e < offsets[k + 1]; ++e)
    {
      for (int c = 0; c < 12; ++c)
      {
        blend[c] += weights[e] * (motions[12 * nodes[e] + c] - firstMotion[c]);
      }
    }
    for (int c = 0; c < 12; ++c)
    {
      blend[c] += firstMotion[c];
    }
#endif
    const double b[3] = { base[k], base[count + k], base[2 * count + k] };
    for (int r = 0; r < 3; ++r)
    {
      out[r * count + k] = b[r] + blend[r] * b[0] + blend[3 + r] * b[1] + blend[6 + r] * b[2] + blend[9 + r];
    }
  }
}

// Wendland's C2 function, 1 at 0, 0 from 1 on.
double Wendland(double t)
{
  if (t >= 1.0)
  {
    return 0.0;
  }
  const double s = 1.0 - t;
  return s * s * s * s * (4.0 * t + 1.0);
}
}

std::string RegionProxy::Build(
  const SurfaceMesh& mesh, const EditRegion& region, int nodes, const ParallelFor& loop)
{
  if (region.GetNumberOfVertices() == 0 || nodes < 4)
  {
    return "a proxy needs a region and at least 4 nodes";
  }
  // The largest spacing from the ROI's area and the nodes asked for; the smallest, the ROI's
  // mean edge length.
  std::vector<char> inRegion(mesh.GetNumberOfVertices(), 0);
  for (int v : region.Vertices)
  {
    inRegion[v] = 1;
  }
  double area = 0.0;
  const auto& p = mesh.GetPositions();
  for (const auto& t : mesh.GetTriangles())
  {
    const int corners = inRegion[t[0]] + inRegion[t[1]] + inRegion[t[2]];
    area += corners / 3.0 * 0.5 * (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]).norm();
  }
  double edges = 0.0;
  long count = 0;
  for (int v : region.Vertices)
  {
    for (const int* w = mesh.NeighborsBegin(v); w != mesh.NeighborsEnd(v); ++w, ++count)
    {
      edges += (p[*w] - p[v]).norm();
    }
  }
  this->EdgeLength = count > 0 ? edges / count : 0.0;
  this->Spacing = std::max(this->EdgeLength, std::sqrt(area / (CellAreaOverSpacingSquared * nodes)));
  const std::vector<char> sampled = this->SampledVertices(mesh, region, BandOverSpacing * this->Spacing);
  this->Sample(mesh, sampled);
  const std::string error = this->Triangulate(mesh, region);
  if (!error.empty())
  {
    return error;
  }
  this->Weigh(mesh, region, loop);
  return {};
}

std::vector<char> RegionProxy::SampledVertices(
  const SurfaceMesh& mesh, const EditRegion& region, double band) const
{
  // The ROI, and the fixed vertices within `band` of it along edges.
  // 2 marks a handle's vertex, 3 one on a handle's border, which Sample takes first.
  std::vector<char> sampled(mesh.GetNumberOfVertices(), 0);
  for (int k = 0; k < region.GetNumberOfVertices(); ++k)
  {
    sampled[region.Vertices[k]] = region.Roles[k] == VertexRole::Handle ? 2 : 1;
  }
  for (int v : region.Vertices)
  {
    for (const int* w = mesh.NeighborsBegin(v); w != mesh.NeighborsEnd(v) && sampled[v] == 2; ++w)
    {
      sampled[v] = sampled[*w] < 2 ? 3 : 2;
    }
  }
  std::vector<int> border;
  for (int v : region.Vertices)
  {
    for (const int* w = mesh.NeighborsBegin(v); w != mesh.NeighborsEnd(v); ++w)
    {
      if (!sampled[*w])
      {
        border.push_back(v);
        break;
      }
    }
  }
  GeodesicSearch search(mesh, DistanceMethod::EdgePaths);
  std::vector<int> reached;
  search.Visit(border, band, [&](int v, double) { reached.push_back(v); },
    [&](int v) { return sampled[v] == 0; });
  for (int v : reached)
  {
    sampled[v] = 1;
  }
  return sampled;
}

void RegionProxy::Sample(const SurfaceMesh& mesh, const std::vector<char>& sampled)
{
  // Each vertex's spacing: Grading times its distance from the handles' borders, between the
  // edge length and Spacing.
  const int n = mesh.GetNumberOfVertices();
  std::vector<double> spacing(n, this->Spacing);
  GeodesicSearch search(mesh, DistanceMethod::EdgePaths);
  std::vector<int> borders;
  for (int v = 0; v < n; ++v)
  {
    if (sampled[v] == 3)
    {
      borders.push_back(v);
    }
  }
  search.Visit(borders, this->Spacing / Grading,
    [&](int v, double d) { spacing[v] = std::max(this->EdgeLength, std::min(this->Spacing, Grading * d)); },
    [&](int v) { return sampled[v] != 0; });
  // Greedy: a vertex farther than its spacing from every node so far becomes a node; a bounded
  // search from it keeps each vertex's nearest node. Its radius reaches every vertex whose
  // spacing it can cover: spacing changes by at most Grading per unit of distance. Handles'
  // borders come first, then the rest of the handles, so that every handle has nodes of its
  // own, along its border; cells do not cross a handle's border.
  std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
  this->Owner.assign(n, -1);
  this->Seeds.clear();
  this->NodeSpacing.clear();
  auto visit = [&](int v) {
    if (nearest[v] <= spacing[v])
    {
      return;
    }
    const int node = static_cast<int>(this->Seeds.size());
    this->Seeds.push_back(v);
    this->NodeSpacing.push_back(spacing[v]);
    search.Visit({ v }, spacing[v] / (1.0 - Grading),
      [&](int w, double d) {
        if (d < nearest[w])
        {
          nearest[w] = d;
          this->Owner[w] = node;
        }
      },
      [&](int w) { return sampled[w] != 0 && (sampled[w] >= 2) == (sampled[v] >= 2); });
  };
  for (const char pass : { 3, 2, 1 })
  {
    for (int v = 0; v < n; ++v)
    {
      if (sampled[v] == pass)
      {
        visit(v);
      }
    }
  }
}

std::string RegionProxy::Triangulate(const SurfaceMesh& mesh, const EditRegion& region)
{
  // Cells that meet no other two at a triangle (a cell inside another) have no place in the
  // dual: their vertices go to the neighbouring cell they share most edges with, until none is
  // left.
  std::vector<std::array<int, 3>> triangles;
  for (int round = 0;; ++round)
  {
    triangles.clear();
    const int count = static_cast<int>(this->Seeds.size());
    std::vector<char> used(count, 0);
    for (const auto& t : mesh.GetTriangles())
    {
      const std::array<int, 3> cells = { this->Owner[t[0]], this->Owner[t[1]], this->Owner[t[2]] };
      if (cells[0] >= 0 && cells[1] >= 0 && cells[2] >= 0 && cells[0] != cells[1] &&
        cells[1] != cells[2] && cells[0] != cells[2])
      {
        // Rotated to start at its smallest node, which keeps its orientation.
        const int first = static_cast<int>(std::min_element(cells.begin(), cells.end()) - cells.begin());
        triangles.push_back({ cells[first], cells[(first + 1) % 3], cells[(first + 2) % 3] });
        used[cells[0]] = used[cells[1]] = used[cells[2]] = 1;
      }
    }
    if (std::all_of(used.begin(), used.end(), [](char u) { return u != 0; }))
    {
      break;
    }
    if (round == 8)
    {
      return "the region's proxy has cells that meet no others; the region is too thin for "
             "its proxy's spacing";
    }
    // Absorb the unused cells, then renumber the nodes.
    std::vector<std::vector<int>> shared(count);
    for (int v = 0; v < mesh.GetNumberOfVertices(); ++v)
    {
      const int cell = this->Owner[v];
      if (cell < 0 || used[cell])
      {
        continue;
      }
      for (const int* w = mesh.NeighborsBegin(v); w != mesh.NeighborsEnd(v); ++w)
      {
        if (this->Owner[*w] >= 0 && this->Owner[*w] != cell)
        {
          shared[cell].push_back(this->Owner[*w]);
        }
      }
    }
    std::vector<int> into(count);
    std::iota(into.begin(), into.end(), 0);
    for (int cell = 0; cell < count; ++cell)
    {
      auto& neighbours = shared[cell];
      if (used[cell] || neighbours.empty())
      {
        continue;
      }
      std::sort(neighbours.begin(), neighbours.end());
      int best = neighbours[0], bestCount = 0;
      for (std::size_t a = 0; a < neighbours.size();)
      {
        std::size_t b = a;
        while (b < neighbours.size() && neighbours[b] == neighbours[a])
        {
          ++b;
        }
        if (static_cast<int>(b - a) > bestCount)
        {
          best = neighbours[a];
          bestCount = static_cast<int>(b - a);
        }
        a = b;
      }
      into[cell] = best;
    }
    std::vector<int> renumbered(count, -1);
    std::vector<int> seeds;
    std::vector<double> spacings;
    for (int cell = 0; cell < count; ++cell)
    {
      if (into[cell] == cell)
      {
        renumbered[cell] = static_cast<int>(seeds.size());
        seeds.push_back(this->Seeds[cell]);
        spacings.push_back(this->NodeSpacing[cell]);
      }
    }
    for (int& owner : this->Owner)
    {
      // An absorbed cell's target may itself be absorbed this round: follow to a kept one.
      int cell = owner;
      for (int hops = 0; cell >= 0 && into[cell] != cell && hops < count; ++hops)
      {
        cell = into[cell];
      }
      owner = cell >= 0 ? renumbered[cell] : -1;
    }
    this->Seeds = std::move(seeds);
    this->NodeSpacing = std::move(spacings);
  }
  std::sort(triangles.begin(), triangles.end(), [](const std::array<int, 3>& a, const std::array<int, 3>& b) {
    std::array<int, 3> x = a, y = b;
    std::sort(x.begin(), x.end());
    std::sort(y.begin(), y.end());
    return x < y;
  });
  triangles.erase(std::unique(triangles.begin(), triangles.end(),
                    [](std::array<int, 3> a, std::array<int, 3> b) {
                      std::sort(a.begin(), a.end());
                      std::sort(b.begin(), b.end());
                      return a == b;
                    }),
    triangles.end());
  std::vector<Vector3> positions(this->Seeds.size());
  for (std::size_t node = 0; node < this->Seeds.size(); ++node)
  {
    positions[node] = mesh.GetPositions()[this->Seeds[node]];
  }
  std::vector<std::int64_t> offsets(triangles.size() + 1), connectivity;
  connectivity.reserve(3 * triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    connectivity.insert(connectivity.end(), triangles[t].begin(), triangles[t].end());
    offsets[t + 1] = static_cast<std::int64_t>(connectivity.size());
  }
  this->Mesh = SurfaceMesh::FromPolygons(positions, offsets, connectivity, false);

  // The proxy's region: the nodes of ROI vertices.
  std::vector<int> roiRow(mesh.GetNumberOfVertices(), -1);
  for (int k = 0; k < region.GetNumberOfVertices(); ++k)
  {
    roiRow[region.Vertices[k]] = k;
  }
  this->Region = EditRegion();
  this->Region.NumberOfHandleGroups = region.NumberOfHandleGroups;
  this->Region.Radius = region.Radius;
  this->Region.BordersFixedPart = region.BordersFixedPart;
  this->RoiRowOfNode.assign(this->Seeds.size(), -1);
  for (std::size_t node = 0; node < this->Seeds.size(); ++node)
  {
    const int row = roiRow[this->Seeds[node]];
    if (row < 0)
    {
      continue;
    }
    const bool handle = region.Roles[row] == VertexRole::Handle;
    this->RoiRowOfNode[node] = this->Region.GetNumberOfVertices();
    this->Region.Vertices.push_back(static_cast<int>(node));
    this->Region.Roles.push_back(handle ? VertexRole::Handle : VertexRole::Free);
    this->Region.HandleGroups.push_back(handle ? region.HandleGroups[row] : -1);
    this->Region.RelativeDistances.push_back(region.RelativeDistances.empty() ? 0.0 : region.RelativeDistances[row]);
  }
  return {};
}

void RegionProxy::Weigh(const SurfaceMesh& mesh, const EditRegion& region, const ParallelFor& loop)
{
  const int n = region.GetNumberOfVertices();
  this->HandleGroups = region.HandleGroups;
  this->Rest.resize(n, 3);
  // Each row's candidates: its cell's node and the nodes two rings around it on the proxy. The
  // fixed ones never move, so their share of a row's weight goes to one still node after the
  // moving ones (BlendRows needs rows that sum to one).
  const int stillNode = this->Region.GetNumberOfVertices();
  std::vector<std::vector<std::pair<int, double>>> rows(n);
  loop(0, n, [&](int first, int last) {
    std::vector<int> candidates;
    for (int k = first; k < last; ++k)
    {
      const int v = region.Vertices[k];
      const Vector3 p = mesh.GetPositions()[v];
      this->Rest.row(k) = p.transpose();
      if (region.HandleGroups[k] >= 0)
      {
        continue;
      }
      const int own = this->Owner[v];
      candidates.assign(1, own);
      for (const int* a = this->Mesh.NeighborsBegin(own); a != this->Mesh.NeighborsEnd(own); ++a)
      {
        candidates.push_back(*a);
        for (const int* b = this->Mesh.NeighborsBegin(*a); b != this->Mesh.NeighborsEnd(*a); ++b)
        {
          candidates.push_back(*b);
        }
      }
      std::sort(candidates.begin(), candidates.end());
      candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
      double total = 0.0;
      double still = 0.0; // the fixed nodes' share
      auto& row = rows[k];
      for (int node : candidates)
      {
        const double w = Wendland(
          (p - this->Mesh.GetPositions()[node]).norm() / (SupportOverSpacing * this->NodeSpacing[node]));
        total += w;
        if (w > 0.0 && this->RoiRowOfNode[node] >= 0)
        {
          row.emplace_back(this->RoiRowOfNode[node], w);
        }
        else
        {
          still += w;
        }
      }
      if (still > 0.0)
      {
        row.emplace_back(stillNode, still);
      }
      for (auto& entry : row)
      {
        entry.second /= total;
      }
    }
  });
  this->HandleRows.clear();
  for (int k = 0; k < n; ++k)
  {
    if (region.HandleGroups[k] >= 0)
    {
      this->HandleRows.push_back(k);
    }
  }
  this->WeightOffsets.assign(n + 1, 0);
  for (int k = 0; k < n; ++k)
  {
    this->WeightOffsets[k + 1] = this->WeightOffsets[k] + static_cast<int>(rows[k].size());
  }
  this->WeightNodes.resize(this->WeightOffsets[n]);
  this->Weights.resize(this->WeightOffsets[n]);
  for (int k = 0; k < n; ++k)
  {
    for (std::size_t e = 0; e < rows[k].size(); ++e)
    {
      this->WeightNodes[this->WeightOffsets[k] + e] = rows[k][e].first;
      this->Weights[this->WeightOffsets[k] + e] = static_cast<float>(rows[k][e].second);
    }
  }
}

RegionProxy::NodeShape RegionProxy::RestShape() const
{
  NodeShape rest;
  const int nodes = this->Region.GetNumberOfVertices();
  rest.Points.resize(nodes, 3);
  for (int r = 0; r < nodes; ++r)
  {
    rest.Points.row(r) = this->Mesh.GetPositions()[this->Region.Vertices[r]].transpose();
  }
  rest.Turns.assign(nodes, Eigen::Matrix3d::Identity());
  return rest;
}

void RegionProxy::Prolong(const Positions& base, const NodeShape& from, const NodeShape& to,
  const std::vector<AffineMap>& handleMaps, Positions& roiPositions, const ParallelFor& loop) const
{
  // Each node's motion as a map of base points to their displacement, M b + u with
  // M = T T0^-1 - I and u = c - c0 - M c0, blended per row.
  const int nodes = this->Region.GetNumberOfVertices();
  std::vector<AffineMap>& motions = this->Motions;
  motions.resize(nodes + 1);
  motions[nodes].setZero(); // the still node's (Weigh)
  loop(0, nodes, [&](int first, int last) {
    for (int r = first; r < last; ++r)
    {
      const Eigen::Matrix3d turn = to.Turns[r] * from.Turns[r].inverse() - Eigen::Matrix3d::Identity();
      const Vector3 c0 = from.Points.row(r).transpose();
      motions[r].leftCols<3>() = turn;
      motions[r].col(3) = to.Points.row(r).transpose() - c0 - turn * c0;
    }
  });
  const int n = static_cast<int>(this->Rest.rows());
  roiPositions.resize(n, 3);
  static_assert(sizeof(AffineMap) == 12 * sizeof(double), "the motions are packed column-major 3 x 4 maps");
  loop(0, n, [&](int first, int last) {
    BlendRows(first, last, this->WeightOffsets.data(), this->WeightNodes.data(), this->Weights.data(),
      reinterpret_cast<const double*>(motions.data()), base.data(), roiPositions.data(), n);
  });
  // A handle's rows (without weights) go to its map of the rest.
  loop(0, static_cast<int>(this->HandleRows.size()), [&](int first, int last) {
    for (int h = first; h < last; ++h)
    {
      const int k = this->HandleRows[h];
      const int group = this->HandleGroups[k];
      const Vector3 p = this->Rest.row(k).transpose();
      const Vector3 target = group < static_cast<int>(handleMaps.size())
        ? Vector3(handleMaps[group].leftCols<3>() * p + handleMaps[group].col(3))
        : p;
      roiPositions.row(k) = target.transpose();
    }
  });
}

void RegionProxy::Interpolate(const Positions& nodeValues, Positions& fineValues, const ParallelFor& loop) const
{
  // The nodes' values with the still node's, 0, after them, summed as BlendRows sums: the first
  // node's value and the others' differences from it, weighted.
  Positions values(nodeValues.rows() + 1, nodeValues.cols());
  values.topRows(nodeValues.rows()) = nodeValues;
  values.bottomRows(1).setZero();
  const int n = static_cast<int>(this->Rest.rows());
  fineValues.setZero(n, nodeValues.cols());
  loop(0, n, [&](int first, int last) {
    for (int k = first; k < last; ++k)
    {
      const int begin = this->WeightOffsets[k];
      if (begin == this->WeightOffsets[k + 1])
      {
        continue; // a handle's row
      }
      const auto head = values.row(this->WeightNodes[begin]);
      for (int e = begin + 1; e < this->WeightOffsets[k + 1]; ++e)
      {
        fineValues.row(k) += this->Weights[e] * (values.row(this->WeightNodes[e]) - head);
      }
      fineValues.row(k) += head;
    }
  });
}
}
