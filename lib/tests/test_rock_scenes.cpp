// The Sect. 6 scene builders (dda/rock_scenes.hpp): their geometry, and short
// runs (a few hundred steps) that must stay stable, keep the energy bounded
// and move the blocks the expected way. The full-length runs are the repro
// drivers repro/6_1_collapse and repro/6_2_toppling_slumping.
#include <catch2/catch.hpp>

#include <cmath>

#include "dda/rock_scenes.hpp"
#include "dda/simulation.hpp"
#include "state_hash.hpp"

using namespace dda;

namespace {

double polygon_area(const std::vector<Vec2>& v) {
  double s = 0.0;
  for (std::size_t i = 0; i < v.size(); ++i) s += cross(v[i], v[(i + 1) % v.size()]);
  return 0.5 * s;
}

// Energy that a frictional, undamped explicit run may gain by round-off and
// O(dt^2) integration error before something is wrong: 1e-3 of the kinetic +
// potential energy exchanged so far, or 1 J/m, whichever is larger.
void check_energy_bounded(const Energy& e0, const Energy& e) {
  const double exchanged = std::fabs(e.gravity - e0.gravity) + e.kinetic;
  INFO("E0 " << e0.total() << " J/m, E " << e.total() << " J/m, exchanged " << exchanged);
  CHECK(e.total() <= e0.total() + std::max(1e-3 * exchanged, 1.0));
}

}  // namespace

TEST_CASE("6.1 collapse: the joint sets cut the 20 m x 50 m column into ~195 blocks below the stability limit",
          "[rock_scenes]") {
  const paper::Collapse c = paper::collapse(15.0);
  // Paper parameters.
  CHECK(c.scene.materials[0].density == 2700.0);
  CHECK(c.scene.materials[0].young == 2e9);
  CHECK(c.scene.materials[0].poisson == 0.3);
  CHECK(c.scene.contact.kn == 2e9);
  CHECK(c.scene.contact.kt == 1e9);
  CHECK(c.scene.contact.friction_deg == 15.0);
  REQUIRE(c.scene.contact.friction_rules.size() == 1);
  CHECK(c.scene.contact.friction_rules[0].friction_deg == 35.0);
  CHECK(c.scene.dt == 1e-4);
  CHECK(c.scene.duration == 7.5);
  CHECK(paper::collapse(30.0).scene.contact.friction_deg == 30.0);
  // The blocks tile the column up to the dropped slivers.
  double area = c.dropped_area;
  for (const BlockSpec& b : c.scene.blocks) {
    area += polygon_area(b.vertices);
    CHECK(polygon_area(b.vertices) >= c.min_area);
    for (const Vec2& p : b.vertices) {
      CHECK(p.x >= -1e-9);
      CHECK(p.x <= 20.0 + 1e-9);
      CHECK(p.y >= -1e-9);
      CHECK(p.y <= 50.0 + 1e-9);
    }
    CHECK(b.group == paper::kRockGroup);
    CHECK_FALSE(b.fixed);
  }
  CHECK(area == Approx(1000.0).epsilon(1e-9));
  CHECK(c.scene.blocks.size() > 150);
  CHECK(c.scene.blocks.size() < 250);
  CHECK(c.dropped_area < 10.0);  // < 1 % of the region
  for (const BoundarySegment& s : c.scene.boundaries) CHECK(s.group == paper::kBoundaryGroup);
  // predicted_critical_step is an a-priori bound (each block pressed along
  // its longest edge by the softest-H partner, strain modes added): dt at
  // ~0.5 of it leaves a factor ~2 for the live contacts.
  const Simulation sim(c.scene);
  CHECK(sim.dt() / sim.predicted_critical_step() < 0.6);
}

TEST_CASE("6.1 collapse, 400 steps: stable, energy bounded, the column settles and leans to the free side",
          "[rock_scenes]") {
  for (double phi : {15.0, 30.0}) {
    INFO("joint friction " << phi);
    const paper::Collapse c = paper::collapse(phi);
    Simulation sim(c.scene);
    const int n = sim.scene_block_count();
    std::vector<Vec2> c0;
    for (int i = 0; i < n; ++i) c0.push_back(sim.centroid(i));
    const Energy e0 = sim.energy();
    REQUIRE_NOTHROW([&] {
      for (int k = 0; k < 400; ++k) sim.step();
    }());
    const Energy e = sim.energy();
    check_energy_bounded(e0, e);
    double dx = 0.0, dy = 0.0, mass = 0.0, below = 0.0;
    for (int i = 0; i < n; ++i) {
      const Vec2 d = sim.centroid(i) - c0[static_cast<std::size_t>(i)];
      dx += sim.mass(i) * d.x;
      dy += sim.mass(i) * d.y;
      mass += sim.mass(i);
      for (int v = 0; v < sim.polygon(i).count; ++v) below = std::min(below, sim.polygon(i).vertex(v).y);
    }
    // After 0.04 s: the mass falls (mean centroid drop > 1 mm, far below a
    // free fall's 7.8 mm) and moves toward the free side (+x), and no
    // vertex sinks into the floor more than 1 cm (penalty overlap).
    CHECK(dy / mass < -1e-3);
    CHECK(dy / mass > -0.5 * 9.81 * 0.04 * 0.04);
    CHECK(dx / mass > 0.0);
    CHECK(below > -0.01);
    CHECK(sim.dt() / sim.critical_time_step() < 1.0);
  }
}

TEST_CASE("6.2 toppling/slumping: two wedges on 30 deg bases, one 75 deg joint set", "[rock_scenes]") {
  const paper::TopplingSlumping t = paper::toppling_slumping();
  CHECK(t.scene.contact.kn == 0.5e9);
  CHECK(t.scene.contact.kt == 1e8);
  CHECK(t.scene.contact.friction_deg == 22.0);
  REQUIRE(t.scene.contact.friction_rules.size() == 1);
  CHECK(t.scene.contact.friction_rules[0].friction_deg == 32.0);
  CHECK(t.scene.duration == 3.5);
  REQUIRE(t.side.size() == t.scene.blocks.size());
  int left = 0, right = 0;
  double area = t.dropped_area;
  for (std::size_t i = 0; i < t.scene.blocks.size(); ++i) {
    const BlockSpec& b = t.scene.blocks[i];
    area += polygon_area(b.vertices);
    // Each block stands on its sliding base: two vertices on the base line.
    const Vec2 toe{t.side[i] < 0 ? -t.valley_half_width : t.valley_half_width, 0.0};
    const Vec2 down = t.side[i] < 0 ? t.left_downdip : t.right_downdip;
    int on_base = 0;
    for (const Vec2& p : b.vertices) {
      CHECK(t.side[i] * p.x >= t.valley_half_width - 1e-9);  // on its own side of the valley
      if (std::fabs(cross(down, p - toe)) < 1e-9) ++on_base;
    }
    CHECK(on_base == 2);
    (t.side[i] < 0 ? left : right) += 1;
  }
  CHECK(left >= 8);
  CHECK(right >= 8);
  CHECK(area == Approx(polygon_area(t.left_region) + polygon_area(t.right_region)).epsilon(1e-9));
  const Simulation sim(t.scene);
  CHECK(sim.dt() / sim.predicted_critical_step() < 0.5);
}

TEST_CASE("6.2 toppling/slumping, 0.8 s: the right columns start to topple toward the valley, the left slabs do not",
          "[rock_scenes]") {
  const paper::TopplingSlumping t = paper::toppling_slumping();
  Simulation sim(t.scene);
  const Energy e0 = sim.energy();
  REQUIRE_NOTHROW(sim.advance_to(0.8));
  check_energy_bounded(e0, sim.energy());
  double rot[2] = {0.0, 0.0}, mass[2] = {0.0, 0.0};
  for (int i = 0; i < sim.scene_block_count(); ++i) {
    const int s = t.side[static_cast<std::size_t>(i)] < 0 ? 0 : 1;
    rot[s] += sim.mass(i) * sim.displacement(i)[2];
    mass[s] += sim.mass(i);
  }
  const double left = -rot[0] / mass[0], right = rot[1] / mass[1];  // outward: toward the valley
  INFO("mean outward rotation: left " << left << " rad, right " << right << " rad");
  // Toppling has begun on the right (> 0.5 deg outward at 0.8 s; the full
  // run reaches ~37 deg at 3.5 s); the left slabs lean back, not out.
  CHECK(right > 0.5 * 3.14159265358979 / 180.0);
  CHECK(left < 0.0);
  CHECK(right > 2.0 * std::fabs(left));
}

TEST_CASE("6.1 and 6.2 scenes, short runs: the same bits on 1 and 2 threads", "[rock_scenes]") {
  // The paper-scale scenes themselves (195 and 26 blocks, friction rules,
  // sweep broad phase): 1 thread stepping one step at a time against a
  // 2-thread team over the same steps (Simulation::advance).
  const Scene scenes[2] = {paper::collapse(15.0).scene, paper::toppling_slumping().scene};
  const int steps[2] = {300, 1500};
  for (int k = 0; k < 2; ++k) {
    Simulation one(scenes[k]), two(scenes[k]);
    two.set_threads(2);
    for (int i = 0; i < steps[k]; ++i) one.step();
    two.advance(steps[k]);
    INFO("scene " << k << ": " << one.contacts().size() << " contacts");
    CHECK(one.contacts().size() > 10);
    CHECK(test::state_hash(one) == test::state_hash(two));
  }
}
