#include "GeodesicDistance.h"

#include <algorithm>
#include <cmath>

namespace LaplacianEditing
{
double FrontArrival(const Vector3& target, const Vector3& a, double da, const Vector3& b, double db)
{
  // d(x) = d_t + g . (x - target) with |g| = 1 in the triangle's plane: with E = [a - t, b - t]
  // and Q = (E^T E)^-1, (u - d_t 1)^T Q (u - d_t 1) = 1 for u = (da, db).
  const double infinity = std::numeric_limits<double>::infinity();
  const Vector3 ea = a - target, eb = b - target;
  const double aa = ea.squaredNorm(), ab = ea.dot(eb), bb = eb.squaredNorm();
  const double determinant = aa * bb - ab * ab;
  if (!(determinant > 1e-12 * (aa + bb) * (aa + bb)))
  {
    return infinity; // a degenerate triangle carries no front
  }
  // Q = [bb, -ab; -ab, aa] / determinant.
  const double q11 = bb / determinant, q12 = -ab / determinant, q22 = aa / determinant;
  const double qa = q11 + 2.0 * q12 + q22;
  const double qb = (q11 + q12) * da + (q12 + q22) * db;
  const double qc = q11 * da * da + 2.0 * q12 * da * db + q22 * db * db - 1.0;
  const double discriminant = qb * qb - qa * qc;
  if (discriminant < 0.0)
  {
    return infinity;
  }
  const double arrival = (qb + std::sqrt(discriminant)) / qa;
  // Upwind: the front must come to the target from inside the triangle, g = E (alpha, beta)
  // with alpha, beta <= 0, and not before the corners it comes from.
  const double ua = da - arrival, ub = db - arrival;
  if (q11 * ua + q12 * ub > 0.0 || q12 * ua + q22 * ub > 0.0 || arrival < std::max(da, db))
  {
    return infinity;
  }
  return arrival;
}

std::vector<double> ComputeGeodesicDistances(const SurfaceMesh& mesh,
  const std::vector<int>& sources, double maxDistance, DistanceMethod method)
{
  std::vector<double> distance(mesh.GetNumberOfVertices(), std::numeric_limits<double>::infinity());
  GeodesicSearch(mesh, method).Visit(sources, maxDistance, [&](int v, double d) { distance[v] = d; });
  return distance;
}
}
