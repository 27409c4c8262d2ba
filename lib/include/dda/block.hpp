// 6-DOF DDA block kinematics (Paper A Eqs. 1-3, 5): the displacement
// matrix T, the mass matrix from the area moments, the plane elastic matrix.
#pragma once
#include <Eigen/Dense>

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

// Plane-stress elastic matrix D (stress = D strain, engineering shear), Pa.
Mat3 elastic_matrix(double young, double poisson);

}  // namespace dda
