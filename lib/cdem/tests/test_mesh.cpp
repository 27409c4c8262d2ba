#include <catch2/catch.hpp>
#include <map>

#include "dda/cdem/mesh.hpp"
#include "dda/polygon.hpp"

using dda::Vec2;
using dda::cdem::mesh_convex_polygon;

TEST_CASE("meshing keeps the area and orients every triangle CCW", "[cdem][mesh]") {
  const std::vector<std::vector<Vec2>> outlines = {
      {{0, 0}, {2, 0}, {0, 1}}, {{0, 0}, {1, 0}, {1, 1}, {0, 1}}, {{0, 0}, {2, 0}, {3, 1}, {1.5, 2.5}, {-0.5, 1}}};
  for (const auto& o : outlines)
    for (int k : {1, 2, 3, 4}) {
      const auto m = mesh_convex_polygon(o, k);
      const double area = dda::area(dda::make_polygon(o.data(), static_cast<int>(o.size())));
      double sum = 0.0;
      for (const auto& t : m.triangles) {
        const double a = 0.5 * dda::cross(m.nodes[t[1]] - m.nodes[t[0]], m.nodes[t[2]] - m.nodes[t[0]]);
        REQUIRE(a > 0.0);
        sum += a;
      }
      REQUIRE(sum == Approx(area).epsilon(1e-12));
      const std::size_t fan = o.size() == 3 ? 1 : o.size();
      REQUIRE(m.triangles.size() == fan * static_cast<std::size_t>(k * k));
    }
}

TEST_CASE("meshing is conforming: every interior edge is shared by two triangles", "[cdem][mesh]") {
  const auto m = mesh_convex_polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, 3);
  std::map<std::pair<int, int>, int> count;
  for (const auto& t : m.triangles)
    for (int q = 0; q < 3; ++q) count[{std::min(t[q], t[(q + 1) % 3]), std::max(t[q], t[(q + 1) % 3])}] += 1;
  int boundary = 0;
  for (const auto& kv : count) {
    REQUIRE(kv.second <= 2);
    if (kv.second == 1) ++boundary;
  }
  REQUIRE(boundary == 4 * 3);  // each square side split in 3
  // Euler: V - E + F = 1 for a disc
  REQUIRE(static_cast<int>(m.nodes.size()) - static_cast<int>(count.size()) + static_cast<int>(m.triangles.size()) ==
          1);
}

TEST_CASE("rectangle mesh: corners first, area kept, CCW, conforming", "[cdem][mesh]") {
  const auto m = dda::cdem::mesh_rectangle({-1.0, -0.1}, 1.0, 0.2, 5, 2);
  REQUIRE(m.nodes.size() == 6u * 3u);
  REQUIRE(m.triangles.size() == 2u * 5u * 2u);
  CHECK(m.nodes[0] == Vec2{-1.0, -0.1});
  CHECK(m.nodes[1] == Vec2{0.0, -0.1});
  CHECK(m.nodes[2].x == 0.0);
  CHECK(m.nodes[2].y == Approx(0.1).epsilon(1e-15));
  CHECK(m.nodes[3].x == -1.0);
  double sum = 0.0;
  std::map<std::pair<int, int>, int> count;
  for (const auto& t : m.triangles) {
    const double a = 0.5 * dda::cross(m.nodes[t[1]] - m.nodes[t[0]], m.nodes[t[2]] - m.nodes[t[0]]);
    REQUIRE(a > 0.0);
    sum += a;
    for (int q = 0; q < 3; ++q) count[{std::min(t[q], t[(q + 1) % 3]), std::max(t[q], t[(q + 1) % 3])}] += 1;
  }
  CHECK(sum == Approx(0.2).epsilon(1e-12));
  int boundary = 0;
  for (const auto& kv : count) {
    REQUIRE(kv.second <= 2);
    if (kv.second == 1) ++boundary;
  }
  CHECK(boundary == 2 * (5 + 2));
  CHECK_THROWS_AS(dda::cdem::mesh_rectangle({0, 0}, 1.0, 1.0, 0, 1), std::invalid_argument);
}
