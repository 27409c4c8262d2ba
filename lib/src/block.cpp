#include "dda/block.hpp"

namespace dda {

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
