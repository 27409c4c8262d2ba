// The penetration guard (lib/src/simulation/penetration_guard.cpp): two 1 m
// squares meeting over a sweep of impact speed and kn, face on, corner
// first and obliquely. Pass-through is detected independently of the guard:
// the centroids' order along the impact normal (x) swapped.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "dda/simulation.hpp"
#include "state_hash.hpp"

using namespace dda;
using dda::test::state_hash;

namespace {

enum class Impact { kFace, kCorner, kOblique };

std::vector<Vec2> square(Vec2 centre, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  std::vector<Vec2> v;
  for (Vec2 p : {Vec2{-0.5, -0.5}, Vec2{0.5, -0.5}, Vec2{0.5, 0.5}, Vec2{-0.5, 0.5}})
    v.push_back(centre + Vec2{c * p.x - s * p.y, s * p.x + c * p.y});
  return v;
}

// Gap between the squares at t = 0 along x, m.
constexpr double kGap = 0.02;
// The angle of the corner and oblique impacts: 30 deg, rad.
constexpr double kAngle = 0.5235987755982988;

// A (block 0, named "A") moves at `speed` toward B (block 1, "B", at rest;
// its left face at x = 0): face on (B 0.2 m higher), corner first (A turned
// 30 deg) or obliquely (30 deg off the face normal). No gravity, rigid
// blocks, no friction; a step that moves a block at most 4 mm.
Scene impact(Impact kind, double speed, double kn) {
  Scene s;
  s.strains = false;
  s.contact.kn = kn;
  s.contact.h_rule = HRule::kGiven;
  s.contact.h = 1.0;
  s.dt = std::min(5e-4, 0.004 / speed);
  s.duration = 3.0 / speed + 0.5;
  BlockSpec a, b;
  a.name = "A";
  b.name = "B";
  b.vertices = square({0.5, 0.2}, 0.0);
  const double angle = kind == Impact::kCorner ? kAngle : 0.0;
  const double reach = kind == Impact::kCorner ? 0.5 * (std::cos(angle) + std::sin(angle)) : 0.5;
  a.vertices = square({-reach - kGap, 0.0}, angle);
  a.velocity = kind == Impact::kOblique ? speed * Vec2{std::cos(kAngle), std::sin(kAngle)} : Vec2{speed, 0.0};
  s.blocks = {a, b};
  return s;
}

// The overlap's extent along x (the impact normal), m.
double x_extent(const Polygon& ip) {
  double lo = ip.v[0].x, hi = ip.v[0].x;
  for (int q = 1; q < ip.count; ++q) {
    lo = std::min(lo, ip.v[q].x);
    hi = std::max(hi, ip.v[q].x);
  }
  return hi - lo;
}

struct Outcome {
  bool stopped = false;  // SimulationError
  StopReason reason = StopReason::kOther;
  std::int64_t stop_step = -1, steps = -1;  // the error's step and the simulation's count after it
  double stop_time = -1.0, time = -1.0;
  int pair_a = -1, pair_b = -1, block = -1;
  bool passed = false;   // centroids' order along x swapped at the end (or at the stop)
  double max_depth = 0.0;  // largest x-extent of the exact overlap seen (every 10 steps), m
  std::string message;
  std::uint64_t hash = 0;
};

Outcome run(const Scene& s) {
  Outcome o;
  Simulation sim(s);
  const auto total = static_cast<std::int64_t>(std::ceil(s.duration / s.dt));
  try {
    while (sim.step_count() < total) {
      sim.advance(std::min<std::int64_t>(10, total - sim.step_count()));
      const Polygon ip = intersection_polygon(sim.polygon(0), sim.polygon(1));
      if (ip.count >= 3) o.max_depth = std::max(o.max_depth, x_extent(ip));
    }
  } catch (const SimulationError& e) {
    o.stopped = true;
    o.message = e.what();
    o.reason = e.reason;
    o.stop_step = e.step, o.stop_time = e.time;
    o.pair_a = e.pair_a, o.pair_b = e.pair_b, o.block = e.block;
    o.steps = sim.step_count(), o.time = sim.time();
  }
  o.passed = sim.centroid(0).x > sim.centroid(1).x;
  o.hash = state_hash(sim);
  return o;
}

Scene unguarded(Scene s) {
  s.guards.max_penetration = 0.0;
  s.guards.max_approach_energy = 0.0;
  return s;
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST_CASE("penetration guard: no impact passes through unstopped; bounces are untouched", "[guards]") {
  // Two 1 m squares (2000 kg/m each, H = 1 m, bound 0.25 m): face on the
  // pair stores k d^2 / 2 = kn d^2 (k = 2 kn), at most E_max = 0.5 kn;
  // about kn / 3 at full overlap. Speeds from far below the bound to far
  // beyond E_max at two penalties.
  int passed_unguarded = 0, stopped_depth = 0, stopped_energy = 0, bounced = 0;
  for (Impact kind : {Impact::kFace, Impact::kCorner, Impact::kOblique})
    for (double kn : {1e5, 1e6})
      for (double speed : {1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0}) {
        INFO("impact " << static_cast<int>(kind) << ", kn " << kn << " Pa, speed " << speed << " m/s");
        const Scene s = impact(kind, speed, kn);
        const Outcome off = run(unguarded(s));
        const Outcome on = run(s);
        INFO("unguarded: passed " << off.passed << ", max depth " << off.max_depth << " m; guarded: " << on.message);
        CHECK_FALSE(off.stopped);
        passed_unguarded += off.passed ? 1 : 0;
        // With the guard: never through, and stopped before the centroids cross.
        CHECK_FALSE(on.passed);
        if (off.passed) CHECK(on.stopped);
        // A bounce well inside the bound runs on, bit for bit as without the guard.
        if (!off.passed && off.max_depth < 0.2) {
          CHECK_FALSE(on.stopped);
          CHECK(on.hash == off.hash);
          ++bounced;
        }
        if (on.stopped) {
          CHECK(has(on.message, "step "));
          CHECK(has(on.message, "(t = "));
          CHECK(has(on.message, "pair (0, 1) = block 0 'A' and block 1 'B'"));
          // The same facts as fields: the pair, the step and time the simulation stopped at.
          CHECK((on.pair_a == 0 && on.pair_b == 1 && on.block == -1));
          CHECK((on.stop_step == on.steps && on.stop_time == on.time && on.steps > 0));
          CHECK(has(on.message, "step " + std::to_string(on.stop_step) + " (t = "));
          CHECK(has(on.message, "dt/dt_crit"));
          CHECK(has(on.message, "contact.kn"));
          const bool depth =
              has(on.message, "penetration depth") && has(on.message, "max_penetration") && has(on.message, "(bound ");
          const bool energy = has(on.message, "approach energy") && has(on.message, "max_approach_energy");
          CHECK((depth || energy));
          // The typed reason agrees with the message (S2 and S3 classify by it).
          CHECK(on.reason == (depth ? StopReason::kPenetration : StopReason::kApproachEnergy));
          stopped_depth += depth ? 1 : 0;
          stopped_energy += energy ? 1 : 0;
        }
      }
  // The detector works (negative control: without the guard blocks pass
  // through), both checks fire somewhere, and slow impacts bounce.
  CHECK(passed_unguarded > 0);
  CHECK(stopped_depth > 0);
  CHECK(stopped_energy > 0);
  CHECK(bounced > 0);
}

TEST_CASE("penetration guard: the thresholds are checked and 0 switches a check off", "[guards]") {
  Scene s = impact(Impact::kFace, 1.0, 1e5);
  s.guards.max_penetration = -0.1;
  CHECK_THROWS_WITH(Simulation(s), Catch::Contains("guards.max_penetration"));
  s.guards.max_penetration = 0.5;
  s.guards.max_approach_energy = std::nan("");
  CHECK_THROWS_WITH(Simulation(s), Catch::Contains("guards.max_approach_energy"));
  // Far beyond E_max: the approach-energy check stops at first contact; with
  // it off the depth check stops later; with both off the blocks cross.
  s = impact(Impact::kFace, 64.0, 1e5);
  const Outcome both = run(s);
  s.guards.max_approach_energy = 0.0;
  const Outcome depth_only = run(s);
  s.guards.max_penetration = 0.0;
  const Outcome none = run(s);
  CHECK(both.stopped);
  CHECK(has(both.message, "first contact"));
  CHECK(depth_only.stopped);
  CHECK(has(depth_only.message, "penetration depth"));
  CHECK_FALSE(none.stopped);
  CHECK(none.passed);
}
