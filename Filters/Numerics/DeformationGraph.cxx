#include "DeformationGraph.h"

#include "ClosestRotation.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <queue>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace LaplacianEditing
{
namespace
{
// A point follows this many nearest nodes; the next one's distance is where their weights end.
constexpr int Followed = 4;
constexpr int Labels = Followed + 1;
// A band point takes the misses of this many constrained points nearest to it.
constexpr int BandLabels = 3;
// The constrained points' pull against the graph's rigidity (Sumner et al. weigh it 10 to 100
// times the regularization).
constexpr double Pull = 10.0;
// A proximal term that keeps a node that nothing constrains where it was.
constexpr double Proximal = 1e-8;

struct Label
{
  int Node;
  double Distance;
};

// The points' neighbours along the tetrahedra's edges, with the edges' lengths.
struct EdgeGraph
{
  std::vector<int> Offsets, Neighbours;
  std::vector<double> Lengths;
};

// Per point, its first `wanted` labels from Offsets... kept flat: point p's are
// Labels[Labels * p, Labels * p + Counts[p]).
struct NearestLabels
{
  std::vector<Label> Found;
  std::vector<unsigned char> Counts;
  int Wanted = 0;
  const Label* Of(int p) const { return this->Found.data() + static_cast<std::size_t>(this->Wanted) * p; }
};

// Each point's nearest `wanted` sources along the edges, within `reach`: a Dijkstra search from
// every source at once, in which a point keeps the first `wanted` sources that reach it.
NearestLabels NearestSources(const EdgeGraph& graph, const std::vector<int>& sources, int wanted,
  double reach = std::numeric_limits<double>::infinity())
{
  const int n = static_cast<int>(graph.Offsets.size()) - 1;
  NearestLabels labels;
  labels.Wanted = wanted;
  labels.Found.resize(static_cast<std::size_t>(wanted) * n);
  labels.Counts.assign(n, 0);
  struct Entry
  {
    double Distance;
    int Point, Source;
    bool operator>(const Entry& other) const { return this->Distance > other.Distance; }
  };
  std::vector<Entry> heap;
  heap.reserve(4 * static_cast<std::size_t>(n));
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue(std::greater<Entry>(), std::move(heap));
  for (std::size_t k = 0; k < sources.size(); ++k)
  {
    queue.push({ 0.0, sources[k], static_cast<int>(k) });
  }
  auto has = [&](int p, int source) {
    const Label* found = labels.Of(p);
    for (int k = 0; k < labels.Counts[p]; ++k)
    {
      if (found[k].Node == source)
      {
        return true;
      }
    }
    return false;
  };
  while (!queue.empty())
  {
    const Entry entry = queue.top();
    queue.pop();
    const int p = entry.Point;
    if (labels.Counts[p] >= wanted || has(p, entry.Source))
    {
      continue;
    }
    labels.Found[static_cast<std::size_t>(wanted) * p + labels.Counts[p]++] = { entry.Source, entry.Distance };
    for (int k = graph.Offsets[p]; k < graph.Offsets[p + 1]; ++k)
    {
      const int q = graph.Neighbours[k];
      const double next = entry.Distance + graph.Lengths[k];
      if (next < reach && labels.Counts[q] < wanted && !has(q, entry.Source))
      {
        queue.push({ next, q, entry.Source });
      }
    }
  }
  return labels;
}

// Points no two closer than `spacing`, taken in order among those `eligible`.
std::vector<int> Sample(const Positions& rest, double spacing, const std::vector<char>& eligible,
  std::vector<int> nodes)
{
  auto key = [spacing](const Eigen::RowVector3d& p, int dx, int dy, int dz) {
    const std::int64_t i = static_cast<std::int64_t>(std::floor(p.x() / spacing)) + dx;
    const std::int64_t j = static_cast<std::int64_t>(std::floor(p.y() / spacing)) + dy;
    const std::int64_t k = static_cast<std::int64_t>(std::floor(p.z() / spacing)) + dz;
    return (i * 73856093) ^ (j * 19349663) ^ (k * 83492791);
  };
  std::unordered_map<std::int64_t, std::vector<int>> cells;
  for (int node : nodes)
  {
    cells[key(rest.row(node), 0, 0, 0)].push_back(node);
  }
  for (int p = 0; p < static_cast<int>(rest.rows()); ++p)
  {
    if (!eligible[p])
    {
      continue;
    }
    bool near = false;
    for (int dx = -1; dx <= 1 && !near; ++dx)
    {
      for (int dy = -1; dy <= 1 && !near; ++dy)
      {
        for (int dz = -1; dz <= 1 && !near; ++dz)
        {
          auto found = cells.find(key(rest.row(p), dx, dy, dz));
          if (found == cells.end())
          {
            continue;
          }
          for (int node : found->second)
          {
            near = near || (rest.row(node) - rest.row(p)).norm() < spacing;
          }
        }
      }
    }
    if (!near)
    {
      nodes.push_back(p);
      cells[key(rest.row(p), 0, 0, 0)].push_back(p);
    }
  }
  return nodes;
}
}

std::string DeformationGraph::Build(const Positions& rest, const Tetrahedra& tetrahedra,
  const std::vector<PointKind>& kinds, int nodes, const ParallelFor& loop)
{
  *this = DeformationGraph();
  const int n = static_cast<int>(rest.rows());
  if (n == 0 || tetrahedra.rows() == 0 || nodes < 1)
  {
    return "no points or tetrahedra to build a deformation graph on";
  }
  this->Rest = rest;
  this->Kinds = kinds;
  // The points' neighbours along the tetrahedra's edges: each point's, counted, then sorted.
  EdgeGraph graph;
  graph.Offsets.assign(n + 1, 0);
  double volume = 0.0;
  for (Eigen::Index t = 0; t < tetrahedra.rows(); ++t)
  {
    for (int i = 0; i < 4; ++i)
    {
      graph.Offsets[tetrahedra(t, i) + 1] += 3;
    }
    Eigen::Matrix3d d;
    for (int k = 0; k < 3; ++k)
    {
      d.col(k) = (rest.row(tetrahedra(t, k + 1)) - rest.row(tetrahedra(t, 0))).transpose();
    }
    volume += std::abs(d.determinant()) / 6.0;
  }
  std::partial_sum(graph.Offsets.begin(), graph.Offsets.end(), graph.Offsets.begin());
  std::vector<int> all(graph.Offsets.back()), next(graph.Offsets.begin(), graph.Offsets.end() - 1);
  for (Eigen::Index t = 0; t < tetrahedra.rows(); ++t)
  {
    for (int i = 0; i < 4; ++i)
    {
      for (int j = 0; j < 4; ++j)
      {
        if (i != j)
        {
          all[next[tetrahedra(t, i)]++] = tetrahedra(t, j);
        }
      }
    }
  }
  const std::vector<int> counted = graph.Offsets;
  for (int p = 0; p < n; ++p)
  {
    auto first = all.begin() + counted[p], last = all.begin() + counted[p + 1];
    std::sort(first, last);
    last = std::unique(first, last);
    graph.Neighbours.insert(graph.Neighbours.end(), first, last);
    graph.Offsets[p + 1] = static_cast<int>(graph.Neighbours.size());
  }
  all = {};
  graph.Lengths.resize(graph.Neighbours.size());
  for (int p = 0; p < n; ++p)
  {
    for (int k = graph.Offsets[p]; k < graph.Offsets[p + 1]; ++k)
    {
      graph.Lengths[k] = (rest.row(graph.Neighbours[k]) - rest.row(p)).norm();
    }
  }

  // Nodes spread over the zone; a piece the first sampling left without one gets its own.
  const double spacing = std::cbrt(volume / nodes);
  std::vector<int> sampled = Sample(rest, spacing, std::vector<char>(n, 1), {});
  NearestLabels labels = NearestSources(graph, sampled, Labels);
  std::vector<char> unreached(n, 0);
  bool anyUnreached = false;
  for (int p = 0; p < n; ++p)
  {
    unreached[p] = labels.Counts[p] == 0;
    anyUnreached = anyUnreached || unreached[p];
  }
  if (anyUnreached)
  {
    sampled = Sample(rest, spacing, unreached, sampled);
    labels = NearestSources(graph, sampled, Labels);
  }
  this->NodePoints = sampled;
  const int m = static_cast<int>(sampled.size());

  // The weights, and the nodes a point shares joined.
  this->WeightOffsets.assign(n + 1, 0);
  std::vector<std::pair<int, int>> joins;
  for (int p = 0; p < n; ++p)
  {
    const Label* l = labels.Of(p);
    const int count = labels.Counts[p];
    const int used = std::min(Followed, count);
    const double end = count > Followed ? l[Followed].Distance : l[count - 1].Distance + spacing;
    double sum = 0.0;
    const std::size_t first = this->Weights.size();
    for (int k = 0; k < used; ++k)
    {
      const double w = std::pow(1.0 - l[k].Distance / std::max(end, 1e-300), 2.0);
      this->WeightNodes.push_back(l[k].Node);
      this->Weights.push_back(w);
      sum += w;
      for (int j = 0; j < k; ++j)
      {
        joins.emplace_back(l[k].Node, l[j].Node);
        joins.emplace_back(l[j].Node, l[k].Node);
      }
    }
    for (std::size_t k = first; k < this->Weights.size(); ++k)
    {
      this->Weights[k] = sum > 0.0 ? this->Weights[k] / sum : 1.0 / used;
    }
    this->WeightOffsets[p + 1] = static_cast<int>(this->Weights.size());
  }
  std::sort(joins.begin(), joins.end());
  joins.erase(std::unique(joins.begin(), joins.end()), joins.end());
  this->NeighbourOffsets.assign(m + 1, 0);
  for (const auto& join : joins)
  {
    ++this->NeighbourOffsets[join.first + 1];
  }
  std::partial_sum(this->NeighbourOffsets.begin(), this->NeighbourOffsets.end(), this->NeighbourOffsets.begin());
  this->Neighbours.resize(joins.size());
  for (std::size_t k = 0; k < joins.size(); ++k)
  {
    this->Neighbours[k] = joins[k].second;
  }

  // The global step's matrix: the graph's Laplacian (each node's edges), the pull's W^T W.
  for (int p = 0; p < n; ++p)
  {
    if (kinds[p] != PointKind::Free)
    {
      this->Constrained.push_back(p);
    }
  }
  // The band: free points within a node spacing of constrained ones, which take the constrained
  // points' misses of the graph's field, fading with the distance.
  {
    const NearestLabels near = NearestSources(graph, this->Constrained, BandLabels, spacing);
    this->BandOffsets.assign(1, 0);
    for (int p = 0; p < n; ++p)
    {
      const Label* l = near.Of(p);
      if (kinds[p] != PointKind::Free || near.Counts[p] == 0)
      {
        continue;
      }
      const double fade = std::pow(1.0 - l[0].Distance / spacing, 2.0);
      double sum = 0.0;
      const std::size_t first = this->BandWeights.size();
      for (const Label& label : std::vector<Label>(l, l + near.Counts[p]))
      {
        const double w = std::pow(1.0 - label.Distance / spacing, 2.0);
        this->BandSources.push_back(label.Node); // a row of Constrained
        this->BandWeights.push_back(w);
        sum += w;
      }
      for (std::size_t k = first; k < this->BandWeights.size(); ++k)
      {
        this->BandWeights[k] *= fade / sum;
      }
      this->BandPoints.push_back(p);
      this->BandOffsets.push_back(static_cast<int>(this->BandWeights.size()));
    }
  }
  this->Alpha = Pull;
  std::vector<Eigen::Triplet<double>> entries;
  for (int a = 0; a < m; ++a)
  {
    for (int k = this->NeighbourOffsets[a]; k < this->NeighbourOffsets[a + 1]; ++k)
    {
      const int b = this->Neighbours[k];
      // |c_b - c_a - R_a (q_b - q_a)|^2
      entries.emplace_back(a, a, 1.0);
      entries.emplace_back(b, b, 1.0);
      entries.emplace_back(a, b, -1.0);
      entries.emplace_back(b, a, -1.0);
    }
    entries.emplace_back(a, a, Proximal);
  }
  for (int p : this->Constrained)
  {
    for (int i = this->WeightOffsets[p]; i < this->WeightOffsets[p + 1]; ++i)
    {
      for (int j = this->WeightOffsets[p]; j < this->WeightOffsets[p + 1]; ++j)
      {
        entries.emplace_back(this->WeightNodes[i], this->WeightNodes[j],
          this->Alpha * this->Weights[i] * this->Weights[j]);
      }
    }
  }
  Eigen::SparseMatrix<double> matrix(m, m);
  matrix.setFromTriplets(entries.begin(), entries.end());
  const std::string error = this->Factor.Factorize(matrix, SolverBackend::SimplicialLDLT);
  if (!error.empty())
  {
    *this = DeformationGraph();
    return error;
  }
  this->NodeRest.resize(m, 3);
  for (int a = 0; a < m; ++a)
  {
    this->NodeRest.row(a) = rest.row(sampled[a]);
  }
  // The pull's sums that do not change: per node, sum_t w_tn (p_t - q_n); per pair of nodes
  // that a constrained point shares, sum_t w_tn w_tk (p_t - q_k).
  this->PulledOffsets.setZero(m, 3);
  std::vector<std::tuple<int, int, Eigen::RowVector3d>> pairs;
  for (int p : this->Constrained)
  {
    for (int i = this->WeightOffsets[p]; i < this->WeightOffsets[p + 1]; ++i)
    {
      const int a = this->WeightNodes[i];
      this->PulledOffsets.row(a) += this->Weights[i] * (rest.row(p) - this->NodeRest.row(a));
      for (int j = this->WeightOffsets[p]; j < this->WeightOffsets[p + 1]; ++j)
      {
        const int b = this->WeightNodes[j];
        pairs.emplace_back(a, b, this->Weights[i] * this->Weights[j] * (rest.row(p) - this->NodeRest.row(b)));
      }
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const auto& x, const auto& y) {
    return std::tie(std::get<0>(x), std::get<1>(x)) < std::tie(std::get<0>(y), std::get<1>(y));
  });
  this->PairOffsets.assign(m + 1, 0);
  this->PairNodes.clear();
  std::vector<Eigen::RowVector3d> sums;
  for (std::size_t k = 0; k < pairs.size(); ++k)
  {
    const auto& [a, b, v] = pairs[k];
    if (k > 0 && std::get<0>(pairs[k - 1]) == a && std::get<1>(pairs[k - 1]) == b)
    {
      sums.back() += v;
      continue;
    }
    this->PairNodes.push_back(b);
    sums.push_back(v);
    ++this->PairOffsets[a + 1];
  }
  std::partial_sum(this->PairOffsets.begin(), this->PairOffsets.end(), this->PairOffsets.begin());
  this->PairOffsetSums.resize(static_cast<Eigen::Index>(sums.size()), 3);
  for (std::size_t k = 0; k < sums.size(); ++k)
  {
    this->PairOffsetSums.row(static_cast<Eigen::Index>(k)) = sums[k];
  }
  this->ResetToRest();
  (void)loop;
  return {};
}

void DeformationGraph::Spread(const Positions& misses, Positions& points, const ParallelFor& loop) const
{
  loop(0, static_cast<int>(this->BandPoints.size()), [&](int first, int last) {
    for (int b = first; b < last; ++b)
    {
      for (int k = this->BandOffsets[b]; k < this->BandOffsets[b + 1]; ++k)
      {
        points.row(this->BandPoints[b]) +=
          this->BandWeights[k] * misses.row(this->Constrained[this->BandSources[k]]);
      }
    }
  });
}

void DeformationGraph::ResetToRest()
{
  this->NodeCenters = this->NodeRest;
  this->Rotations.assign(this->NodePoints.size(), Eigen::Matrix3d::Identity());
  this->Turns.assign(this->NodePoints.size(), Eigen::Quaterniond::Identity());
}

Vector3 DeformationGraph::Follow(int p) const
{
  Vector3 x = Vector3::Zero();
  const Vector3 rest = this->Rest.row(p).transpose();
  for (int k = this->WeightOffsets[p]; k < this->WeightOffsets[p + 1]; ++k)
  {
    const int a = this->WeightNodes[k];
    x += this->Weights[k] *
      (this->NodeCenters.row(a).transpose() + this->Rotations[a] * (rest - this->NodeRest.row(a).transpose()));
  }
  return x;
}

void DeformationGraph::Solve(
  const Positions& targets, Positions& points, int iterations, const ParallelFor& loop)
{
  const int m = this->GetNumberOfNodes();
  if (m == 0)
  {
    return;
  }
  auto target = [&](int p) -> Vector3 {
    return this->Kinds[p] == PointKind::Targeted ? Vector3(targets.row(p).transpose())
                                                 : Vector3(this->Rest.row(p).transpose());
  };
  // The constrained points' share of the iterations, which depends on the targets only (so the
  // iterations cost the nodes', not the points'): per node, sum_t w_t y_t (p_t - q_n)^T and
  // sum_t w_t y_t.
  std::vector<Eigen::Matrix3d> pulled(m, Eigen::Matrix3d::Zero());
  Eigen::MatrixXd pulledTargets = Eigen::MatrixXd::Zero(m, 3);
  for (int p : this->Constrained)
  {
    const Vector3 y = target(p);
    for (int k = this->WeightOffsets[p]; k < this->WeightOffsets[p + 1]; ++k)
    {
      const int a = this->WeightNodes[k];
      pulled[a] += this->Weights[k] * y * (this->Rest.row(p) - this->NodeRest.row(a));
      pulledTargets.row(a) += this->Weights[k] * y.transpose();
    }
  }
  std::vector<Eigen::Matrix3d> covariances(m);
  Eigen::MatrixXd rhs(m, 3);
  for (int iteration = 0; iteration < iterations; ++iteration)
  {
    // Local: each node's rotation, from its edges and the constrained points it moves,
    // sum_t w_t (y_t - c_n) (p_t - q_n)^T.
    loop(0, m, [&](int first, int last) {
      for (int a = first; a < last; ++a)
      {
        Eigen::Matrix3d s = this->Alpha *
          (pulled[a] - this->NodeCenters.row(a).transpose() * this->PulledOffsets.row(a));
        for (int k = this->NeighbourOffsets[a]; k < this->NeighbourOffsets[a + 1]; ++k)
        {
          const int b = this->Neighbours[k];
          s += (this->NodeCenters.row(b) - this->NodeCenters.row(a)).transpose() *
            (this->NodeRest.row(b) - this->NodeRest.row(a));
        }
        // From the last iteration's rotation: a few Newton steps where it converges.
        Eigen::Quaterniond& q = this->Turns[a];
        if (!RefineClosestRotation(s, q))
        {
          q = ClosestRotation(s);
        }
        this->Rotations[a] = q.toRotationMatrix();
      }
    });
    // Global: the centres, with the rotations fixed. The pull's part,
    // alpha sum_t w_tn (y_t - sum_k w_tk R_k (p_t - q_k)), from the pairs' sums.
    rhs = Proximal * this->NodeCenters + this->Alpha * pulledTargets;
    for (int a = 0; a < m; ++a)
    {
      for (int k = this->NeighbourOffsets[a]; k < this->NeighbourOffsets[a + 1]; ++k)
      {
        const int b = this->Neighbours[k];
        const Eigen::RowVector3d turned =
          (this->Rotations[a] * (this->NodeRest.row(b) - this->NodeRest.row(a)).transpose()).transpose();
        rhs.row(b) += turned;
        rhs.row(a) -= turned;
      }
      for (int k = this->PairOffsets[a]; k < this->PairOffsets[a + 1]; ++k)
      {
        rhs.row(a) -= this->Alpha *
          (this->Rotations[this->PairNodes[k]] * this->PairOffsetSums.row(k).transpose()).transpose();
      }
    }
    this->NodeCenters = this->Factor.Solve(rhs);
  }
  const int n = static_cast<int>(this->Rest.rows());
  Positions misses(n, 3);
  loop(0, static_cast<int>(this->Constrained.size()), [&](int first, int last) {
    for (int k = first; k < last; ++k)
    {
      const int p = this->Constrained[k];
      misses.row(p) = (target(p) - this->Follow(p)).transpose();
    }
  });
  loop(0, n, [&](int first, int last) {
    for (int p = first; p < last; ++p)
    {
      if (this->Kinds[p] == PointKind::Free)
      {
        points.row(p) = this->Follow(p).transpose();
      }
      else if (this->Kinds[p] == PointKind::Targeted)
      {
        points.row(p) = targets.row(p);
      }
    }
  });
  this->Spread(misses, points, loop);
}
}

