#include "dda/block.hpp"

#include <algorithm>

#include "lanes.hpp"

namespace dda {

namespace {

using detail::Lanes;

// displace_vertices for kN vertices (0: poly.count), u and v of
// point_displacement in the two lanes: with t = (xt, yt) and s = (yt, xt),
//   (u, v) = (((d0, d1) + s (-d2, d2)) + t (d3, d4)) + (0.5 s) d5,
// lane by lane its operations (d0 + yt (-d2) is d0 - yt d2 exactly).
template <int kN>
double displace_n(Polygon& poly, Vec2 centroid, const Vec6& d) {
  const int count = kN ? kN : poly.count;
  const Lanes c = detail::lanes(centroid);
  const Lanes base{d[0], d[1]}, rotation{-d[2], d[2]}, strain{d[3], d[4]}, shear{d[5], d[5]};
  const Lanes half{0.5, 0.5};
  double motion2 = 0.0;
  for (int k = 0; k < count; ++k) {
    const Lanes p = detail::lanes(poly.v[static_cast<std::size_t>(k)]);
    const Lanes t = p - c;
    const Lanes s = detail::swapped(t);
    const Lanes u = base + s * rotation + t * strain + half * s * shear;
    poly.v[static_cast<std::size_t>(k)] = detail::vec2(p + u);
    const Lanes u2 = u * u;
    motion2 = std::max(motion2, u2[0] + u2[1]);
  }
  return motion2;
}

}  // namespace

double displace_vertices(Polygon& poly, Vec2 centroid, const Vec6& d) {
  if (poly.count == 4) return displace_n<4>(poly, centroid, d);
  return displace_n<0>(poly, centroid, d);
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
