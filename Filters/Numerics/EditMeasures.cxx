#include "EditMeasures.h"

#include <Eigen/SVD>

namespace LaplacianEditing
{
double AsRigidAsPossibleEnergy(const SurfaceMesh& mesh, LaplacianWeights weights,
  const std::vector<int>& region, const std::vector<Vector3>& deformed)
{
  const LaplacianOperator laplacian(mesh, weights);
  const auto& rest = mesh.GetPositions();
  double residual = 0.0, scale = 0.0;
  for (int v : region)
  {
    const std::vector<double> w = laplacian.EdgeWeights(v);
    const int* ring = mesh.NeighborsBegin(v);
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
    for (std::size_t k = 0; k < w.size(); ++k)
    {
      covariance += w[k] * (rest[ring[k]] - rest[v]) * (deformed[ring[k]] - deformed[v]).transpose();
    }
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d u = svd.matrixU();
    if ((svd.matrixV() * u.transpose()).determinant() < 0.0)
    {
      u.col(2) *= -1.0;
    }
    const Eigen::Matrix3d rotation = svd.matrixV() * u.transpose();
    for (std::size_t k = 0; k < w.size(); ++k)
    {
      const Vector3 edge = rest[ring[k]] - rest[v];
      residual += w[k] * (deformed[ring[k]] - deformed[v] - rotation * edge).squaredNorm();
      scale += w[k] * edge.squaredNorm();
    }
  }
  return scale > 0.0 ? residual / scale : 0.0;
}

EditMeasures MeasureEdit(const SurfaceMesh& mesh, const std::vector<int>& region,
  const std::vector<Vector3>& deformed, LaplacianWeights weights)
{
  EditMeasures measures;
  measures.Energy = AsRigidAsPossibleEnergy(mesh, weights, region, deformed);

  // The triangles touching the region, once each.
  std::vector<char> inRegion(mesh.GetNumberOfVertices(), 0), seen(mesh.GetNumberOfTriangles(), 0);
  std::vector<int> triangles;
  for (int v : region)
  {
    inRegion[v] = 1;
    for (const int* t = mesh.TrianglesBegin(v); t != mesh.TrianglesEnd(v); ++t)
    {
      if (!seen[*t])
      {
        seen[*t] = 1;
        triangles.push_back(*t);
      }
    }
  }
  const auto& rest = mesh.GetPositions();
  auto normal = [&](const std::vector<Vector3>& p, int t) {
    const auto& tri = mesh.GetTriangles()[t];
    return Vector3((p[tri[1]] - p[tri[0]]).cross(p[tri[2]] - p[tri[0]]));
  };
  double before = 0.0, after = 0.0;
  for (int t : triangles)
  {
    before += 0.5 * normal(rest, t).norm();
    after += 0.5 * normal(deformed, t).norm();
    // A face turned over points against the area-weighted normals around its corners.
    Vector3 around = Vector3::Zero();
    for (int corner : mesh.GetTriangles()[t])
    {
      for (const int* s = mesh.TrianglesBegin(corner); s != mesh.TrianglesEnd(corner); ++s)
      {
        around += *s == t ? Vector3::Zero() : normal(deformed, *s);
      }
    }
    measures.TurnedOverFaces += normal(deformed, t).dot(around) < 0.0 ? 1 : 0;
  }
  measures.AreaRatio = before > 0.0 ? after / before : 1.0;
  return measures;
}
}
