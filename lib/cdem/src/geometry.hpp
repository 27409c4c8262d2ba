// Geometry of constant-strain triangles shared by the CDEM model's steps
// (lib/cdem/src/model_*.cpp). Internal: not installed, pure functions.
#pragma once
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>

#include "dda/block.hpp"
#include "dda/vec2.hpp"

namespace dda::cdem::detail {

// A touch within this fraction of an edge's length from an end node is a
// touch of that node (a node-to-node clone).
inline constexpr double kNodeTieXi = 1e-6;

// Shape-function derivatives of a constant-strain triangle (CCW x0, x1, x2):
// dN_i/dx = b_i / (2A), dN_i/dy = c_i / (2A).
struct Cst {
  double area = 0.0;
  std::array<double, 3> b{}, c{};
};

inline Cst cst(const std::array<Vec2, 3>& x) {
  Cst g;
  g.b = {x[1].y - x[2].y, x[2].y - x[0].y, x[0].y - x[1].y};
  g.c = {x[2].x - x[1].x, x[0].x - x[2].x, x[1].x - x[0].x};
  g.area = 0.5 * cross(x[1] - x[0], x[2] - x[0]);
  return g;
}

// Element stiffness A B^T D B (6 x 6, DOFs x0 y0 x1 y1 x2 y2).
inline Eigen::Matrix<double, 6, 6> element_stiffness(const std::array<Vec2, 3>& x, const Mat3& d) {
  const Cst g = cst(x);
  Eigen::Matrix<double, 3, 6> b = Eigen::Matrix<double, 3, 6>::Zero();
  const double s = 1.0 / (2.0 * g.area);
  for (int i = 0; i < 3; ++i) {
    b(0, 2 * i) = g.b[i] * s;
    b(1, 2 * i + 1) = g.c[i] * s;
    b(2, 2 * i) = g.c[i] * s;
    b(2, 2 * i + 1) = g.b[i] * s;
  }
  return g.area * b.transpose() * d * b;
}

// Paper B Eqs. 2-3, one incremental step of a constant-strain triangle at
// its current corners x: the strain increment from the displacement since
// `last` with B of the mid configuration, the stress rotated by the
// element's incremental rotation and incremented with D d_eps (`last` and
// `stress` updated); f the nodal forces -A B^T sigma with B of x. Returns 1
// when the mid configuration is inverted, 2 when x is, 0 otherwise (the
// caller names the element in its error). Shared by the coarse and patch
// elements (model_elements.cpp) and the sub-model (model_submodel.cpp).
inline int cst_incremental_force(const std::array<Vec2, 3>& x, std::array<Vec2, 3>& last, Vec3& stress,
                                 const Mat3& d, std::array<Vec2, 3>& f) {
  std::array<Vec2, 3> du, mid;
  bool moved = false;
  for (int i = 0; i < 3; ++i) {
    du[i] = x[i] - last[i];
    mid[i] = 0.5 * (x[i] + last[i]);
    moved = moved || du[i] != Vec2{};
  }
  if (moved) {
    const Cst g = cst(mid);
    if (!(g.area > 0.0)) return 1;
    const double r = 1.0 / (2.0 * g.area);
    double exx = 0.0, eyy = 0.0, gxy = 0.0, rot = 0.0;
    for (int i = 0; i < 3; ++i) {
      exx += g.b[i] * du[i].x;
      eyy += g.c[i] * du[i].y;
      gxy += g.c[i] * du[i].x + g.b[i] * du[i].y;
      rot += g.b[i] * du[i].y - g.c[i] * du[i].x;
    }
    exx *= r;
    eyy *= r;
    gxy *= r;
    rot *= 0.5 * r;
    if (rot != 0.0) {
      const double cs = std::cos(rot), sn = std::sin(rot);
      const double sxx = stress[0], syy = stress[1], sxy = stress[2];
      stress[0] = cs * cs * sxx - 2.0 * cs * sn * sxy + sn * sn * syy;
      stress[1] = sn * sn * sxx + 2.0 * cs * sn * sxy + cs * cs * syy;
      stress[2] = cs * sn * (sxx - syy) + (cs * cs - sn * sn) * sxy;
    }
    stress += d * Vec3(exx, eyy, gxy);
    last = x;
  }
  const Cst g = cst(x);
  if (!(g.area > 0.0)) return 2;
  for (int i = 0; i < 3; ++i)
    f[i] = Vec2{-0.5 * (g.b[i] * stress[0] + g.c[i] * stress[2]), -0.5 * (g.b[i] * stress[2] + g.c[i] * stress[1])};
  return 0;
}

// Strain energy of a constant-strain triangle at corners x with stress
// sigma and compliance C: 1/2 A sigma^T C sigma, J per unit thickness.
inline double cst_strain_energy(const std::array<Vec2, 3>& x, const Vec3& stress, const Mat3& c) {
  return 0.5 * cst(x).area * stress.dot(c * stress);
}

inline double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 e = b - a;
  const double l2 = length_squared(e);
  const double t = l2 > 0.0 ? std::clamp(dot(p - a, e) / l2, 0.0, 1.0) : 0.0;
  return distance(p, a + t * e);
}

inline double point_triangle_distance(Vec2 p, const std::array<Vec2, 3>& x) {
  const bool inside =
      cross(x[1] - x[0], p - x[0]) >= 0.0 && cross(x[2] - x[1], p - x[1]) >= 0.0 && cross(x[0] - x[2], p - x[2]) >= 0.0;
  if (inside) return 0.0;
  return std::min({point_segment_distance(p, x[0], x[1]), point_segment_distance(p, x[1], x[2]),
                   point_segment_distance(p, x[2], x[0])});
}

}  // namespace dda::cdem::detail
