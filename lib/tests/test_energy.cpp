// The energy budget (kinetic + gravity + strain + contact + friction
// springs + dissipated work = initial energy) and the momentum balance of a
// pair whose loading point is kept within its intersection polygon.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dda/block.hpp"
#include "dda/paper_scenes.hpp"
#include "dda/rock_scenes.hpp"
#include "dda/simulation.hpp"
#include "test_helpers.hpp"

using namespace dda;
using namespace dda::test;

namespace {

// The largest |balance error| over `samples` equal intervals of [0, t_end],
// relative to the largest mechanical energy (kinetic + strain + contact +
// friction springs) seen at those times. without_dissipated: the budget
// with the dissipated work left out (the negative control).
double worst_balance(Simulation& sim, double t_end, int samples, bool without_dissipated = false) {
  double worst = 0.0, scale = 0.0;
  for (int k = 1; k <= samples; ++k) {
    sim.advance_to(t_end * k / samples);
    const Energy e = sim.energy();
    scale = std::max(scale, e.kinetic + e.strain + e.contact + e.friction_spring);
    worst = std::max(worst, std::fabs(without_dissipated ? e.total() - e.initial : e.balance_error()));
  }
  return worst / scale;
}

paper::Incline incline_run(double phi_deg, FrictionUpdate update) {
  paper::Incline inc = paper::incline(phi_deg, 30.0, 0.2);
  inc.scene.contact.friction_update = update;
  inc.scene.guards.max_balance_error = 0.0;  // measured here, not guarded
  return inc;
}

// Tolerances of the frictional budget (relative to the largest mechanical
// energy; measured at dt = 1e-5 s over 0.2-0.3 s: sliding 6.6e-7, sticking
// 1.1e-5 with the paper's rule and 1.0e-5 with the return mapping, falling
// as dt^0.6-0.9): a few times the measured error.
constexpr double kSlidingBalanceTol = 5e-6;
constexpr double kStickingBalanceTol = 5e-5;

}  // namespace

TEST_CASE("frictionless head-on impact: the energy balance error falls as dt^2", "[energy]") {
  // Paper A 4.1's two squares, rigid (strains off): translation only, the
  // contact force the exact gradient of the contact energy in the relative
  // position (test_contact), velocity Verlet's error O(dt^2). Measured:
  // 3.9e-4, 9.7e-5, 2.4e-5, 6.1e-6 of the kinetic energy at dt = 4e-4 ..
  // 5e-5 s, order 2.00. (A spinning block adds an O(dt) drift, 1e-6 of its
  // energy at dt = 4e-5 s: the linearised rotation of Eq. 1 grows it each
  // step; strains add a floor near 1e-5: neither is in this test.)
  std::vector<double> dts = {4e-4, 2e-4, 1e-4, 5e-5}, errors;
  for (double dt : dts) {
    Scene s = paper::two_squares();
    s.strains = false;
    s.dt = dt;
    Simulation sim(s);
    errors.push_back(worst_balance(sim, 1.0, 100));
    CHECK(sim.energy().dissipated == 0.0);
    CHECK(sim.energy().friction_spring == 0.0);
  }
  CAPTURE(errors);
  // Order 2 within 0.2 (the four points' fit; order 1 would fail it).
  CHECK(std::fabs(fitted_order(dts, errors) - 2.0) < 0.2);
  CHECK(errors.back() < 1e-5);
}

TEST_CASE("frictional incline: the energy budget closes with the dissipated work", "[energy]") {
  // Sect. 4.3's block on the 30 deg slope, dt = 1e-5 s. phi = 10 deg: it
  // slides, friction dissipates tan 10 / tan 30 = 31 % of the energy it
  // releases.
  for (FrictionUpdate update : {FrictionUpdate::kPaper, FrictionUpdate::kReturnMapping}) {
    CAPTURE(static_cast<int>(update));
    {
      paper::Incline inc = incline_run(10.0, update);
      Simulation sim(inc.scene);
      CHECK(worst_balance(sim, 0.2, 50) < kSlidingBalanceTol);
      const Energy e = sim.energy();
      CHECK(sim.contacts().at(0).sliding);
      CHECK(e.dissipated > 0.2 * e.kinetic);
      // Negative control: the same run without the dissipated work does
      // not balance (the check can fail).
      Simulation again(inc.scene);
      CHECK(worst_balance(again, 0.2, 50, true) > 100.0 * kSlidingBalanceTol);
    }
    {
      // phi = 40 deg: it sticks; its spring holds 9.1 J at 0.2 s.
      paper::Incline inc = incline_run(40.0, update);
      Simulation sim(inc.scene);
      CHECK(worst_balance(sim, 0.2, 50) < kStickingBalanceTol);
      CHECK(sim.energy().friction_spring > 0.0);
    }
  }
}

TEST_CASE("the energy budget guard stops a run whose balance error exceeds its bound", "[energy]") {
  paper::Incline inc = paper::incline(10.0, 30.0, 0.05);
  inc.scene.guards.energy_check_every = 100;
  SECTION("a bound below the measured error stops the run") {
    inc.scene.guards.max_balance_error = 1e-9;
    Simulation sim(inc.scene);
    try {
      sim.advance_to(0.05);
      FAIL("no stop");
    } catch (const SimulationError& e) {
      const std::string what = e.what();
      CHECK(what.find("energy budget off by") != std::string::npos);
      CHECK(what.find("guards.max_balance_error") != std::string::npos);
      CHECK(e.reason == StopReason::kEnergyBudget);  // callers classify by the reason, not the text
      CHECK(what.find("dt/dt_crit") != std::string::npos);
    }
  }
  SECTION("the default bound lets it run") {
    Simulation sim(inc.scene);
    CHECK_NOTHROW(sim.advance_to(0.05));
  }
  SECTION("0 switches the check off") {
    inc.scene.guards.max_balance_error = 0.0;
    Simulation sim(inc.scene);
    CHECK_NOTHROW(sim.advance_to(0.05));
  }
  SECTION("a negative bound is a scene error") {
    inc.scene.guards.max_balance_error = -1.0;
    CHECK_THROWS_AS(Simulation(inc.scene), SceneError);
  }
}

TEST_CASE("pg kept in the IP: each block takes Eq. 20's full moment, angular momentum is conserved", "[energy]") {
  // A 1.6 m x 0.1 m bar (block 0, CP) tilted 10 deg inside a free 2 m square
  // (block 1), 1 cm off its centre: the segment forces nearly cancel and
  // Eq. 20's crossing lies metres outside the bar (test_contact), so pg is
  // kept in the IP and the rest of the moment is a couple. After one step
  // from rest each block's angular momentum about the IP centroid c is h
  // times the moment it took: M about c for the bar (force at pg plus
  // couple), -M for the square.
  Scene s;
  s.contact.kn = 1e7;
  s.initial_overlap = 0.2;  // the whole bar overlaps: 0.1 m thick
  BlockSpec bar, square;
  const Vec2 b[4] = {{-0.8, -0.05}, {0.8, -0.05}, {0.8, 0.05}, {-0.8, 0.05}};
  for (Vec2 v : b) bar.vertices.push_back(rotate(v, 10.0 * M_PI / 180.0) + Vec2{0.01, 0.0});
  square.vertices = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  s.blocks = {bar, square};
  s.dt = 1e-7;
  Simulation sim(s);
  REQUIRE(sim.contacts().size() == 1);
  const ContactInfo ci = sim.contacts()[0];
  REQUIRE(ci.cp == 0);
  const Polygon ip = intersection_polygon(sim.polygon(0), sim.polygon(1));
  const Vec2 c = area_centroid(ip).centroid;
  REQUIRE(locate_point(ip, ci.point, pair_tolerance(sim.polygon(0), sim.polygon(1))) != PointLocation::kOutside);
  const double carried = cross(ci.point - c, ci.normal_force);
  const double moment = carried + ci.couple;
  // The couple carries most of it: a run without it would miss the check.
  REQUIRE(std::fabs(ci.couple) > 0.5 * std::fabs(moment));
  sim.step();
  auto angular_momentum = [&](int i) {
    const AreaMoments m = area_moments(sim.polygon(i));
    const Vec6 mv = mass_matrix(m, sim.mass(i) / m.area) * sim.velocity(i);
    return sim.mass(i) * cross(sim.centroid(i) - c, Vec2{sim.velocity(i)[0], sim.velocity(i)[1]}) + mv[2];
  };
  const double h = sim.dt();
  CHECK(angular_momentum(0) == Approx(h * moment).epsilon(1e-3));
  CHECK(angular_momentum(1) == Approx(-h * moment).epsilon(1e-3));
  CHECK(std::fabs(angular_momentum(0) + angular_momentum(1)) < 1e-9 * h * std::fabs(moment));
  CHECK(length(sim.momentum()) < 1e-9 * h * length(ci.normal_force));
}

TEST_CASE("a pair that slid and left keeps its dissipated work in the budget", "[energy]") {
  // A 1 m square slides at 3 m/s along a fixed 2 m slab (friction 10 deg),
  // off its end and away: its pair leaves the near list (rebuilt every
  // step without the sweep), and the work friction dissipated on it stays
  // in the budget.
  Scene s;
  s.gravity = {0.0, -9.81};
  s.contact.kn = 1e7;
  s.contact.kt = 1e7;
  s.contact.friction_deg = 10.0;
  s.contact.h_rule = HRule::kGiven;
  s.contact.h = 1.0;
  s.dt = 1e-5;
  BlockSpec slab, block;
  slab.vertices = {{-1, -1}, {1, -1}, {1, 0}, {-1, 0}};
  slab.fixed = true;
  block.vertices = {{-0.5, 0}, {0.5, 0}, {0.5, 1}, {-0.5, 1}};
  block.velocity = {3.0, 0.0};
  s.blocks = {slab, block};
  s.guards.max_balance_error = 0.0;
  Simulation sim(s);
  double worst = 0.0, scale = 0.0, dissipated_in_contact = 0.0;
  for (int k = 1; k <= 80; ++k) {
    sim.advance_to(0.01 * k);
    const Energy e = sim.energy();
    scale = std::max(scale, e.kinetic + e.strain + e.contact + e.friction_spring);
    worst = std::max(worst, std::fabs(e.balance_error()));
    if (!sim.contacts().empty()) dissipated_in_contact = e.dissipated;
  }
  CAPTURE(worst / scale, dissipated_in_contact);
  REQUIRE(sim.contacts().empty());
  REQUIRE(sim.centroid(1).y < 0.0);  // fell off: its centroid below the slab top
  CHECK(dissipated_in_contact > 0.05 * scale);
  CHECK(sim.energy().dissipated >= dissipated_in_contact);
  CHECK(worst / scale < kSlidingBalanceTol);
}

TEST_CASE("the friction work is summed in pair order: the same budget with 1 and 2 threads", "[energy]") {
  const Scene s = paper::collapse(15.0).scene;
  Simulation one(s), two(s);
  two.set_threads(2);
  one.advance(300);
  two.advance(300);
  const Energy a = one.energy(), b = two.energy();
  CHECK(a.dissipated > 0.0);
  CHECK(a.dissipated == b.dissipated);
  CHECK(a.friction_spring == b.friction_spring);
  CHECK(a.balance_error() == b.balance_error());
}
