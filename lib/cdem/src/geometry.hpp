// Geometry of constant-strain triangles shared by the CDEM model's steps
// (lib/cdem/src/model_*.cpp). Internal: not installed, pure functions.
#pragma once
#include <Eigen/Core>
#include <algorithm>
#include <array>

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
