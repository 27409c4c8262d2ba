// 6-DOF DDA block kinematics (Paper A Eqs. 1-3, 5): the displacement
// matrix T, the mass matrix from the area moments, the plane elastic matrix.
#pragma once
#include <Eigen/Dense>
#include <cmath>

#include "dda/polygon.hpp"

namespace dda {

// d = (u0, v0, r0, ex, ey, gxy): centroid translation, rotation, constant strains.
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;

// Displacement of point p for DOF vector d: u_p = T(p) d (Eqs. 1, 3), with
// (xt, yt) = p - centroid.
inline Vec2 point_displacement(Vec2 centroid, Vec2 p, const Vec6& d) {
  const double xt = p.x - centroid.x, yt = p.y - centroid.y;
  return {d[0] - yt * d[2] + xt * d[3] + 0.5 * yt * d[5], d[1] + xt * d[2] + yt * d[4] + 0.5 * xt * d[5]};
}

// T(p)^T f: the generalized force of a point force f at p (Eqs. 22-23).
inline Vec6 point_load(Vec2 centroid, Vec2 p, Vec2 f) {
  const double xt = p.x - centroid.x, yt = p.y - centroid.y;
  Vec6 g;
  g << f.x, f.y, -yt * f.x + xt * f.y, xt * f.x, yt * f.y, 0.5 * (yt * f.x + xt * f.y);
  return g;
}

// M = rho * int T^T T dS (Eq. 5a). Translation decouples from the rest
// because the first moments about the centroid vanish.
Mat6 mass_matrix(const AreaMoments& m, double density);

// Accelerations of the rotation and strain DOFs (r, ex, ey, gxy): solves
// M4 a = f with M4 the lower-right 4x4 block of mass_matrix (Eq. 5a), by a
// Cholesky factorisation written out for 4x4 (fixed loops the compiler
// unrolls: ~5x cheaper than Eigen's general LLT, called per block and step).
inline Eigen::Vector4d rotation_strain_acceleration(const AreaMoments& m, double density, const Eigen::Vector4d& f) {
  const double xx = density * m.sxx, yy = density * m.syy, xy = density * m.sxy;
  const double a[4][4] = {{xx + yy, -xy, xy, 0.5 * (xx - yy)},
                          {-xy, xx, 0.0, 0.5 * xy},
                          {xy, 0.0, yy, 0.5 * xy},
                          {0.5 * (xx - yy), 0.5 * xy, 0.5 * xy, 0.25 * (xx + yy)}};
  double l[4][4] = {}, inv_diag[4];  // L and 1 / L_jj (one division per column)
  for (int j = 0; j < 4; ++j) {
    double d = a[j][j];
    for (int k = 0; k < j; ++k) d -= l[j][k] * l[j][k];
    l[j][j] = std::sqrt(d);
    inv_diag[j] = 1.0 / l[j][j];
    for (int i = j + 1; i < 4; ++i) {
      double v = a[i][j];
      for (int k = 0; k < j; ++k) v -= l[i][k] * l[j][k];
      l[i][j] = v * inv_diag[j];
    }
  }
  double y[4];
  for (int i = 0; i < 4; ++i) {
    double v = f[i];
    for (int k = 0; k < i; ++k) v -= l[i][k] * y[k];
    y[i] = v * inv_diag[i];
  }
  Eigen::Vector4d x;
  for (int i = 3; i >= 0; --i) {
    double v = y[i];
    for (int k = i + 1; k < 4; ++k) v -= l[k][i] * x[k];
    x[i] = v * inv_diag[i];
  }
  return x;
}

// Plane-stress elastic matrix D (stress = D strain, engineering shear), Pa.
Mat3 elastic_matrix(double young, double poisson);

}  // namespace dda
