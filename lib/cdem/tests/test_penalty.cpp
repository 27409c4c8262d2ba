// The node-to-edge penalty baseline (CdemOptions::contact =
// ContactMode::kNodeToEdgePenalty, model_penalty.cpp): momentum exact in a
// head-on collision, energy nearly kept without damping at a small dt, and
// a penalty far too soft stops the run with a ContactError.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "dda/cdem/model.hpp"
#include "dda/cdem/scenes.hpp"

using dda::Vec2;
using namespace dda::cdem;

namespace {

CdemOptions penalty(double kn = 0.0) {
  CdemOptions o;
  o.contact = ContactMode::kNodeToEdgePenalty;
  o.subdivision = false;
  o.penalty_kn = kn;
  return o;
}

struct Run {
  double mom_err = 0.0;     // max |p - p0| / |p0| over the steps
  double energy_max = 0.0;  // max |E - E0| / E0 over the steps
  double energy_end = 0.0;  // E_end / E0 - 1
  double t_first = -1.0, t_last = -1.0;  // first / last step end with a spring
  double vi = 0.0, vj = 0.0;
  double max_depth = 0.0;
};

Run run(CdemScene s, double dt, double duration) {
  s.dt = dt;
  s.duration = duration;
  Model m(s);
  const double p0 = m.momentum().x, e0 = m.energy().total();
  Run r;
  while (m.time() < duration - 0.5 * dt) {
    m.step();
    r.mom_err = std::max(r.mom_err, std::fabs(m.momentum().x - p0) / std::fabs(p0) + std::fabs(m.momentum().y) / std::fabs(p0));
    r.energy_max = std::max(r.energy_max, std::fabs(m.energy().total() - e0) / e0);
    if (!m.penalty_contacts().empty()) {
      if (r.t_first < 0.0) r.t_first = m.time();
      r.t_last = m.time();
      for (const auto& c : m.penalty_contacts()) r.max_depth = std::max(r.max_depth, c.depth);
    }
  }
  r.energy_end = m.energy().total() / e0 - 1.0;
  r.vi = m.block_velocity(0).x;
  r.vj = m.block_velocity(1).x;
  return r;
}

}  // namespace

// Tolerances (named, with their reason):
// momentum: equal and opposite forces, round-off over 10^4 steps (measured
// 9e-16 to 5e-14 of p0 on the squares);
constexpr double kMomentumRoundOff = 1e-12;
// energy at dt = 2.5e-5 s (a quarter of Paper A's step): the explicit
// step's error of an undamped elastic penalty collision (measured max
// |E / E0 - 1| 3.1e-6 there, 7.2e-5 at 1e-4 s: second order);
constexpr double kEnergySmallDt = 1e-5;

TEST_CASE("penalty: head-on squares conserve momentum to round-off and exchange velocities", "[penalty]") {
  const Run r = run(two_squares(4, penalty()), 1e-4, 0.6);
  CHECK(r.mom_err < kMomentumRoundOff);
  CHECK(r.t_first > 0.5);             // the contact starts at the first step end with a node behind an edge
  CHECK(r.t_first <= 0.5 + 1.0001e-4);  // ... at most one step late
  CHECK(r.t_last > r.t_first);
  CHECK(std::fabs(r.vj - 1.0) < 1e-2);  // an elastic collision of equal blocks: near the exchange
  CHECK(std::fabs(r.vi) < 1e-2);
  // Negative control: block j fixed, the momentum of the free block is not kept.
  CdemScene fixed = two_squares(4, penalty());
  fixed.blocks[1].fixed = true;
  CHECK_FALSE(run(fixed, 1e-4, 0.6).mom_err < kMomentumRoundOff);
}

TEST_CASE("penalty: energy nearly conserved without damping at a small dt", "[penalty]") {
  const Run fine = run(two_squares(4, penalty()), 2.5e-5, 0.6);
  CHECK(fine.energy_max < kEnergySmallDt);
  CHECK(fine.max_depth > 0.0);
  // Negative control: mass damping 1/s takes energy away.
  CdemOptions damped = penalty();
  damped.mass_damping = 1.0;
  CHECK_FALSE(run(two_squares(4, damped), 2.5e-5, 0.6).energy_max < kEnergySmallDt);
}

TEST_CASE("penalty: a kn far too small stops the run with a ContactError", "[penalty]") {
  // kn = E / 10^8 = 10 Pa: the squares' face nodes sink past half an element.
  CdemScene s = two_squares(4, penalty(10.0));
  s.duration = 1.0;
  Model m(s);
  CHECK_THROWS_AS(m.advance_to(1.0), ContactError);
  // the default kn (E / 100 = 10 MPa) runs through
  Model ok(two_squares(4, penalty()));
  CHECK_NOTHROW(ok.advance_to(1.0));
  CHECK(ok.penalty_kn() == 1e7);
}

TEST_CASE("penalty: options are checked and the two-scale default is untouched", "[penalty]") {
  CdemOptions sub = penalty();
  sub.subdivision = true;
  sub.subdivision_mode = SubdivisionMode::kInPlace;  // the in-place refinement under test
  CHECK_THROWS_AS(Model(two_squares(4, sub)), dda::SceneError);
  CHECK_THROWS_AS(Model(two_squares(4, penalty(-1.0))), dda::SceneError);
  // dt above the critical step with the springs (kn 100 E: 1.2e-5 s)
  CHECK_THROWS_AS(Model(two_squares(4, penalty(1e11))), dda::SceneError);
  CdemScene stiff = two_squares(4, penalty(1e11));
  stiff.dt = 1e-5;
  Model p(stiff);
  CHECK(p.contact_critical_dt() < p.critical_dt());
  // the default (two-scale) model: no springs, no penalty energy
  Model d(two_squares(4));
  CHECK(d.penalty_kn() == 0.0);
  CHECK(d.contact_critical_dt() == d.critical_dt());
  d.advance_to(0.6);
  CHECK(!d.touches().empty());
  CHECK(d.penalty_contacts().empty());
  CHECK(d.energy().contact == 0.0);
}
