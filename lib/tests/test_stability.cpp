// Fast stability checks (the full sweeps are repro/S1-S3): a too-large dt is
// stopped with a complete message, the critical step is a safe bound, and
// the incline converges at second order in dt. Speed is never asserted.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "dda/simulation.hpp"
#include "test_helpers.hpp"

using namespace dda;
using namespace dda::test;

namespace {


// Sect. 4.1's squares 1 mm apart with a stiff contact (kn 1e10 Pa).
Scene stiff_impact(double dt_fraction) {
  Scene s = paper::two_squares();
  s.blocks[0].vertices = rect_vertices(-1.001, -0.5, 1.0, 1.0);
  s.contact.kn = 1e10;
  s.dt_fraction = dt_fraction;
  s.duration = 0.05;
  s.guards.energy_check_every = 1;
  return s;
}

std::string stop_message(const Scene& s) {
  Simulation sim(s);
  try {
    sim.advance_to(s.duration);
  } catch (const SimulationError& e) {
    return e.what();
  }
  return "";
}

// A rigid 1 m square resting at its static penetration on a fixed 4 m x 1 m
// block. Its stiffest mode is the vertical one, omega^2 = k / m with
// k = kn L (1/H_A + 1/H_B) (the rocking mode is softer: k / (2 m)).
struct Resting {
  Scene scene;
  double exact_dt = 0.0;  // 2 / omega_max
};

Resting resting(double kn, HRule rule) {
  Resting r;
  Scene& s = r.scene;
  s.materials = {{2000.0, 1e9, 0.25}};
  s.contact.kn = kn;
  s.contact.h_rule = rule;
  s.gravity = {0.0, -9.81};
  s.strains = false;
  s.guards.energy_check_every = 0;
  const double h = rule == HRule::kInscribedRadius ? 0.5 : 2.5;  // both blocks: (4 + 1) / 2, or radius 0.5
  const double w = 2000.0 * 9.81, len = 1.0;
  const double d = len - std::sqrt(len * len - w * h / kn);  // static penetration of a flat contact
  BlockSpec b;
  b.vertices = rect_vertices(-2.0, -1.0, 4.0, 1.0);
  b.fixed = true;
  BlockSpec a;
  a.vertices = rect_vertices(-0.5, -d, 1.0, 1.0);
  s.blocks = {b, a};
  s.initial_overlap = 2.0 * d * (1.0 + 1e-9);
  const double k = kn * len * 2.0 / h;
  r.exact_dt = 2.0 / std::sqrt(k / 2000.0);
  return r;
}

// Mechanical energy after `steps` over its value early in the run.
double energy_growth(Scene s, double dt, int steps) {
  s.dt = dt;
  Simulation sim(s);
  double early = 0.0, late = 0.0;
  try {
    for (int k = 0; k < steps; ++k) {
      sim.step();
      if (k % 20 != 0) continue;
      const Energy e = sim.energy();
      const double m = e.kinetic + e.strain + e.contact;
      if (k < steps / 10) early = std::max(early, m);
      if (k >= steps - steps / 10) late = std::max(late, m);
    }
  } catch (const SimulationError&) {
    return 1e300;
  }
  return late / early;
}

// Trajectory of the incline's block (vertices every T/10) at one dt.
std::vector<double> incline_samples(double phi_deg, double duration, double dt) {
  paper::Incline in = paper::incline(phi_deg, 30.0, duration);
  in.scene.dt = dt;
  Simulation sim(in.scene);
  std::vector<double> out;
  for (int k = 1; k <= 10; ++k) {
    sim.advance_to(duration * k / 10.0);
    for (int v = 0; v < sim.polygon(1).count; ++v) {
      out.push_back(sim.polygon(1).vertex(v).x);
      out.push_back(sim.polygon(1).vertex(v).y);
    }
  }
  return out;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) d = std::max(d, std::fabs(a[i] - b[i]));
  return d;
}

}  // namespace

TEST_CASE("a dt far above dt_crit is stopped with step, time, block, pair, what and dt/dt_crit", "[stability]") {
  const std::string what = stop_message(stiff_impact(3.0));
  INFO(what);
  REQUIRE(!what.empty());
  CHECK(what.rfind("step ", 0) == 0);
  CHECK(what.find("(t = ") != std::string::npos);
  CHECK(what.find("block ") != std::string::npos);
  CHECK(what.find("pair (0, 1)") != std::string::npos);
  CHECK(what.find("more than") != std::string::npos);  // the limit that was exceeded
  CHECK(what.find("dt/dt_crit = ") != std::string::npos);
  CHECK(what.find("3 predicted at start") != std::string::npos);
}

TEST_CASE("the same stiff impact runs through at half the predicted dt_crit", "[stability]") {
  Scene s = stiff_impact(0.5);
  Simulation sim(s);
  CHECK(sim.dt() == Approx(0.5 * sim.predicted_critical_step()));
  CHECK_NOTHROW(sim.advance_to(s.duration));
  CHECK(sim.velocity(1)[0] == Approx(1.0).epsilon(0.05));  // B leaves with A's speed
}

TEST_CASE("the critical step is a safe bound on a resting contact (rigid block, exact omega^2 = k/m)",
          "[stability]") {
  for (HRule rule : {HRule::kMinMaxEdge, HRule::kInscribedRadius})
    for (double kn : {1e7, 1e8}) {
      const Resting r = resting(kn, rule);
      Simulation sim(r.scene);
      INFO("kn " << kn << ", inscribed H " << (rule == HRule::kInscribedRadius));
      REQUIRE(sim.contacts().size() == 1);
      // Safe: never above the exact limit; useful: not far below it.
      CHECK(sim.critical_time_step() <= r.exact_dt);
      CHECK(sim.predicted_critical_step() <= r.exact_dt);
      CHECK(sim.critical_time_step() >= 0.4 * r.exact_dt);
      CHECK(sim.predicted_critical_step() >= 0.4 * r.exact_dt);
      // And the exact limit is where velocity Verlet turns unstable (kn <= 1e8:
      // at stiffer kn the static penetration is so small that the growing
      // mode opens the contact and saturates).
      CHECK(energy_growth(r.scene, 0.98 * r.exact_dt, 4000) < 10.0);
      CHECK(energy_growth(r.scene, 1.05 * r.exact_dt, 4000) > 10.0);
    }
}

TEST_CASE("the incline converges at second order in dt (within 0.3 of 2)", "[stability]") {
  // Persistent contact, no impact: velocity Verlet's order shows. Error of
  // the block's vertices (sampled every 0.01 s over 0.1 s) against a run at
  // the finest dt / 16; order = slope of log(error) on log(dt).
  for (double phi : {0.0, 10.0}) {
    const double duration = 0.1;
    const std::vector<double> dts = {4e-5, 2e-5, 1e-5};
    const std::vector<double> ref = incline_samples(phi, duration, dts.back() / 16.0);
    std::vector<double> err;
    for (double dt : dts) err.push_back(max_difference(incline_samples(phi, duration, dt), ref));
    const double order = std::log(err.front() / err.back()) / std::log(dts.front() / dts.back());
    INFO("phi " << phi << " deg: errors " << err[0] << ", " << err[1] << ", " << err[2] << " m, order " << order);
    CHECK(err.back() > 1e-12);  // above round-off: the order is meaningful
    CHECK(std::fabs(order - 2.0) <= 0.3);
  }
}
