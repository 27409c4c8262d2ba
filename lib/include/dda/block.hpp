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

// Moves every vertex p of poly by point_displacement(centroid, p, d), the
// same bits; returns the largest squared displacement, m^2.
double displace_vertices(PolygonSpan poly, Vec2 centroid, const Vec6& d);

// RotationUpdate::kExact: moves every vertex p of poly to
// c + u0 + R(r0) (I + E) (p - c), c = centroid, (u0, v0, r0) = d[0..2],
// E = [[ex, gxy/2], [gxy/2, ey]] = d[3..5]: the strain increment in the
// step's start configuration, then the rigid rotation by r0 exactly. With
// E = 0 the polygon moves rigidly (its area and moments stay to round-off);
// to first order in d it is displace_vertices. Returns the largest squared
// displacement, m^2.
double rotate_and_displace_vertices(PolygonSpan poly, Vec2 centroid, const Vec6& d);

// The stress (sx, sy, txy) of a material turned by angle rad: R sigma R^T.
inline Vec3 rotated_stress(const Vec3& s, double angle) {
  const double c = std::cos(angle), sn = std::sin(angle);
  const double cc = c * c, ss = sn * sn, cs = c * sn;
  return {cc * s[0] + ss * s[1] - 2.0 * cs * s[2], ss * s[0] + cc * s[1] + 2.0 * cs * s[2],
          cs * (s[0] - s[1]) + (cc - ss) * s[2]};
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
// M4 a = f with M4 the lower-right 4x4 block of mass_matrix (Eq. 5a), in
// closed form. With p = gxy/2 - r and q = gxy/2 + r the displacement of
// Eq. 1 about the centroid reads u = x ex + y p, v = x q + y ey, so in the
// DOFs (ex, p) and (q, ey) the kinetic energy splits into two copies of the
// same 2x2 form rho [[Sxx, Sxy], [Sxy, Syy]]: one 2x2 inverse serves both.
// Forces map by the transpose (f_p = f_gxy - f_r / 2, f_q = f_gxy + f_r / 2)
// and accelerations back by r = (q - p) / 2, gxy = p + q. Called per block
// and step: one division instead of a 4x4 factorisation.
inline Eigen::Vector4d rotation_strain_acceleration(const AreaMoments& m, double density, const Eigen::Vector4d& f) {
  const double fr = f[0], fex = f[1], fey = f[2], fg = f[3];
  const double fp = fg - 0.5 * fr, fq = fg + 0.5 * fr;
  const double inv_det = 1.0 / (density * (m.sxx * m.syy - m.sxy * m.sxy));
  // inverse of rho S2 = inv_det [[Syy, -Sxy], [-Sxy, Sxx]]
  const double a_ex = inv_det * (m.syy * fex - m.sxy * fp), a_p = inv_det * (m.sxx * fp - m.sxy * fex);
  const double a_q = inv_det * (m.syy * fq - m.sxy * fey), a_ey = inv_det * (m.sxx * fey - m.sxy * fq);
  return {0.5 * (a_q - a_p), a_ex, a_ey, a_p + a_q};
}

// Plane-stress elastic matrix D (stress = D strain, engineering shear), Pa.
Mat3 elastic_matrix(double young, double poisson);

}  // namespace dda
