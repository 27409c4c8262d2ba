#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "dda/block.hpp"
#include "test_helpers.hpp"

using namespace dda;
using namespace dda::test;

namespace {

// rho * int T^T T dS by a midpoint rule on an N x N grid over the rectangle:
// independent of the area-moment formulas.
Mat6 mass_by_quadrature(double x0, double y0, double w, double h, double rho, int n) {
  Mat6 m = Mat6::Zero();
  const Vec2 c{x0 + w / 2, y0 + h / 2};
  const double da = (w / n) * (h / n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec2 p{x0 + (i + 0.5) * w / n, y0 + (j + 0.5) * h / n};
      Eigen::Matrix<double, 2, 6> t;
      Vec6 e;
      for (int k = 0; k < 6; ++k) {
        e.setZero();
        e[k] = 1.0;
        const Vec2 u = point_displacement(c, p, e);
        t(0, k) = u.x;
        t(1, k) = u.y;
      }
      m += rho * da * t.transpose() * t;
    }
  return m;
}
}  // namespace

TEST_CASE("mass matrix of a rectangle equals the analytic integral", "[block]") {
  const double w = 2.0, h = 0.5, rho = 2000.0;
  const Mat6 m = mass_matrix(area_moments(rect(3.0, -1.0, w, h)), rho);
  const double mass = rho * w * h;
  CHECK(m(0, 0) == Approx(mass));
  CHECK(m(1, 1) == Approx(mass));
  CHECK(m(2, 2) == Approx(mass * (w * w + h * h) / 12.0));  // polar moment
  CHECK(m(3, 3) == Approx(mass * w * w / 12.0));
  CHECK(m(4, 4) == Approx(mass * h * h / 12.0));
  CHECK(m(5, 5) == Approx(mass * (w * w + h * h) / 48.0));
  CHECK(m(2, 5) == Approx(mass * (w * w - h * h) / 24.0));
  CHECK(std::fabs(m(2, 3)) < 1e-9 * mass);
  // Midpoint rule is exact for the constant and linear parts and converges
  // as 1/N^2 for the quadratic ones: N = 200 gives ~1e-5 relative.
  const Mat6 q = mass_by_quadrature(3.0, -1.0, w, h, rho, 200);
  CHECK((m - q).norm() < 1e-4 * m.norm());
}

TEST_CASE("mass matrix of a triangle equals the analytic integral", "[block]") {
  // Right triangle with legs a, b: Sxx = a^3 b / 36, Syy = a b^3 / 36, Sxy = -a^2 b^2 / 72.
  const double a = 3.0, b = 1.5, rho = 2700.0;
  const Vec2 p[3] = {{0, 0}, {a, 0}, {0, b}};
  const Mat6 m = mass_matrix(area_moments(make_polygon(p, 3)), rho);
  const double s = a * b / 2, sxx = a * a * a * b / 36, syy = a * b * b * b / 36, sxy = -a * a * b * b / 72;
  CHECK(m(0, 0) == Approx(rho * s));
  CHECK(m(2, 2) == Approx(rho * (sxx + syy)));
  CHECK(m(2, 3) == Approx(-rho * sxy));
  CHECK(m(2, 4) == Approx(rho * sxy));
  CHECK(m(3, 5) == Approx(rho * sxy / 2));
  CHECK(m(5, 5) == Approx(rho * (sxx + syy) / 4));
  CHECK(m.isApprox(m.transpose()));
  // Positive definite.
  CHECK(m.llt().info() == Eigen::Success);
}

TEST_CASE("displace_vertices moves each vertex by point_displacement", "[block]") {
  // The same bits as one vertex at a time, for the unrolled quadrilateral
  // and other counts; the largest squared motion of the vertices.
  Vec6 d;
  d << 1.3e-3, -2.1e-4, 3.7e-4, -1.1e-5, 2.3e-5, 4.1e-5;
  const Vec2 c{1e4 + 1.1, -3.2};
  const std::vector<std::vector<Vec2>> shapes = {
      {{1e4 + 0.1, -4.3}, {1e4 + 2.7, -4.9}, {1e4 + 3.1, -2.2}},
      {{1e4 + 0.1, -4.3}, {1e4 + 2.7, -4.9}, {1e4 + 3.1, -2.2}, {1e4 + 1.9, -1.45}},
      {{1e4 + 0.1, -4.3}, {1e4 + 2.7, -4.9}, {1e4 + 3.1, -2.2}, {1e4 + 1.9, -1.45}, {1e4 + 0.3, -2.1}},
  };
  for (const auto& pts : shapes) {
    Polygon p = make_polygon(pts.data(), static_cast<int>(pts.size()));
    const double motion2 = displace_vertices(p, c, d);
    double expect = 0.0;
    for (int k = 0; k < p.count; ++k) {
      const Vec2 u = point_displacement(c, pts[static_cast<std::size_t>(k)], d);
      CHECK(p.vertex(k) == pts[static_cast<std::size_t>(k)] + u);
      expect = std::max(expect, length_squared(u));
    }
    CHECK(motion2 == expect);
  }
}

TEST_CASE("point load is the transpose of point displacement", "[block]") {
  // Virtual work: f . (T d) == (T^T f) . d for any d, f.
  const Vec2 c{0.3, -0.2}, p{1.1, 0.7}, f{2.0, -5.0};
  Vec6 d;
  d << 0.1, -0.3, 0.05, 0.01, -0.02, 0.03;
  CHECK(dot(f, point_displacement(c, p, d)) == Approx(point_load(c, p, f).dot(d)));
}

TEST_CASE("rotation/strain acceleration solves the 4x4 block of M", "[block]") {
  // Against Eigen's LU on the lower-right block of mass_matrix, for a
  // rectangle, a sliver triangle, a pentagon and a rotated 100:1 sliver:
  // residual at round-off.
  const Vec2 tri[3] = {{0, 0}, {10, 0}, {0, 0.1}};
  const Vec2 pent[5] = {{0, 0}, {2, -0.5}, {3, 1}, {1.5, 2.5}, {-0.5, 1.5}};
  const Polygon polys[4] = {rect(3.0, -1.0, 2.0, 0.5), make_polygon(tri, 3), make_polygon(pent, 5),
                            rotated(rect(0.0, 0.0, 10.0, 0.1), 0.5, {0.0, 0.0})};  // rotated 100:1 sliver
  const double rho = 2700.0;
  for (const Polygon& p : polys) {
    const AreaMoments am = area_moments(p);
    const Eigen::Matrix4d m4 = mass_matrix(am, rho).bottomRightCorner<4, 4>();
    const Eigen::Vector4d f(1e3, -2e4, 5e2, 7e3);
    const Eigen::Vector4d a = rotation_strain_acceleration(am, rho, f);
    const Eigen::Vector4d ref = m4.lu().solve(f);
    CHECK((m4 * a - f).norm() <= 1e-12 * f.norm());
    CHECK((a - ref).norm() <= 1e-10 * ref.norm());
  }
}
