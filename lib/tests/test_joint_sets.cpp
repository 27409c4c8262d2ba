#include <catch2/catch.hpp>

#include <cmath>

#include "dda/joint_sets.hpp"
#include "dda/overlap.hpp"

using namespace dda;

TEST_CASE("joint sets cut a rectangle into convex blocks that tile it", "[joint_sets]") {
  const std::vector<Vec2> region = {{0, 0}, {20, 0}, {20, 50}, {0, 50}};
  const GeneratedBlocks g = generate_blocks(region, {{80.0, 1.5, {0, 0}}, {40.0, 2.5, {0, 0}}}, 0.0);
  double total = 0.0;
  for (const Polygon& p : g.blocks) {
    const PolygonCheck c = validate_polygon(p.v.data(), p.count);
    CHECK(c.ok());
    total += area(p);
  }
  CHECK(total == Approx(1000.0).epsilon(1e-12));
  CHECK(g.dropped == 0);
  // 1000 m^2 over cells of 1.5 * 2.5 / sin(40 deg) = 5.83 m^2: ~170 cells plus boundary pieces.
  CHECK(g.blocks.size() > 150);
  CHECK(g.blocks.size() < 300);
  // No two blocks overlap (they only share edges).
  int overlapping = 0;
  for (std::size_t i = 0; i < g.blocks.size(); ++i)
    for (std::size_t j = i + 1; j < g.blocks.size(); ++j)
      if (overlap_state(g.blocks[i], g.blocks[j]) == OverlapState::kOverlapping) ++overlapping;
  CHECK(overlapping == 0);
}

TEST_CASE("slivers below the area threshold are dropped and counted", "[joint_sets]") {
  const std::vector<Vec2> region = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const GeneratedBlocks all = generate_blocks(region, {{60.0, 1.0, {0.013, 0}}}, 0.0);
  const GeneratedBlocks kept = generate_blocks(region, {{60.0, 1.0, {0.013, 0}}}, 0.05);
  CHECK(kept.dropped > 0);
  CHECK(kept.blocks.size() + static_cast<std::size_t>(kept.dropped) == all.blocks.size());
  double a = kept.dropped_area;
  for (const Polygon& p : kept.blocks) a += area(p);
  CHECK(a == Approx(100.0).epsilon(1e-12));
}

TEST_CASE("a non-convex region is split into convex parts first", "[joint_sets]") {
  // An L-shaped outline.
  const std::vector<Vec2> region = {{0, 0}, {4, 0}, {4, 1}, {1, 1}, {1, 3}, {0, 3}};
  const auto parts = convex_parts(region);
  CHECK(parts.size() == 2);
  const GeneratedBlocks g = generate_blocks(region, {{75.0, 0.7, {0, 0}}}, 0.0);
  double total = 0.0;
  for (const Polygon& p : g.blocks) total += area(p);
  CHECK(total == Approx(6.0).epsilon(1e-12));
}

TEST_CASE("bad joint sets and regions are rejected with the field named", "[joint_sets]") {
  const std::vector<Vec2> cw = {{0, 0}, {0, 1}, {1, 0}};
  CHECK_THROWS_WITH(generate_blocks(cw, {}, 0.0), Catch::Contains("counter-clockwise"));
  const std::vector<Vec2> sq = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  CHECK_THROWS_WITH(generate_blocks(sq, {{45.0, 0.0, {}}}, 0.0), Catch::Contains("joint_sets[0].spacing"));
  CHECK_THROWS_WITH(generate_blocks(sq, {{180.0, 1.0, {}}}, 0.0), Catch::Contains("joint_sets[0].dip"));
}

TEST_CASE("a joint set whose origin lies beyond 2^52 spacings is refused, not looped on forever", "[joint_sets]") {
  // Found by the scene-file fuzzer (lib/io/fuzz): at 1e20 spacings k += 1
  // does not change k and the cutting loop never ends.
  const std::vector<Vec2> region = {{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  CHECK_THROWS_WITH(generate_blocks(region, {{60.0, 1.0, {0.0, 1e20}}}, 0.0), Catch::Contains("2^52 spacings"));
  // Far but within range: still cut.
  CHECK(generate_blocks(region, {{60.0, 1.0, {0.0, 1e6}}}, 0.0).blocks.size() > 10);
}
