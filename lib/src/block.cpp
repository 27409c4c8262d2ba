#include "dda/block.hpp"

#include <algorithm>
#include <cmath>

#include "block_lanes.hpp"

namespace dda {

double displace_vertices(PolygonSpan poly, Vec2 centroid, const Vec6& d) {
  return detail::displace_polygon(poly, centroid, d);
}

double rotate_and_displace_vertices(PolygonSpan poly, Vec2 centroid, const Vec6& d) {
  // p' - p = u0 + E q + (R - I)(q + E q), q = p - c. cos r0 - 1 is taken as
  // -2 sin^2(r0 / 2): no cancellation for the small angles of a step.
  const double half = std::sin(0.5 * d[2]);
  const double c1 = -2.0 * half * half, s = std::sin(d[2]);
  const double ex = d[3], ey = d[4], g2 = 0.5 * d[5];
  double motion2 = 0.0;
  for (int k = 0; k < poly.count; ++k) {
    Vec2& p = poly.v[static_cast<std::size_t>(k)];
    const double qx = p.x - centroid.x, qy = p.y - centroid.y;
    const double sx = ex * qx + g2 * qy, sy = g2 * qx + ey * qy;  // E q
    const double wx = qx + sx, wy = qy + sy;                       // (I + E) q
    const Vec2 u{d[0] + sx + c1 * wx - s * wy, d[1] + sy + s * wx + c1 * wy};
    p = p + u;
    motion2 = std::max(motion2, u.x * u.x + u.y * u.y);
  }
  return motion2;
}

Mat6 mass_matrix(const AreaMoments& m, double density) {
  // Entries of int T^T T dS with int xt = int yt = 0 about the centroid.
  const double s = m.area, xx = m.sxx, yy = m.syy, xy = m.sxy;
  Mat6 t = Mat6::Zero();
  t(0, 0) = s;
  t(1, 1) = s;
  t(2, 2) = xx + yy;
  t(2, 3) = -xy;
  t(2, 4) = xy;
  t(2, 5) = 0.5 * (xx - yy);
  t(3, 3) = xx;
  t(3, 5) = 0.5 * xy;
  t(4, 4) = yy;
  t(4, 5) = 0.5 * xy;
  t(5, 5) = 0.25 * (xx + yy);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < i; ++j) t(i, j) = t(j, i);
  return density * t;
}

Mat3 elastic_matrix(double young, double poisson) {
  const double k = young / (1.0 - poisson * poisson);
  Mat3 d;
  d << k, k * poisson, 0.0, k * poisson, k, 0.0, 0.0, 0.0, k * 0.5 * (1.0 - poisson);
  return d;
}

}  // namespace dda
