// Paper A Sect. 4.3: one sliding run and the Eq. 30 criterion, shared by the
// driver (incline.cpp) and the negative controls (controls.cpp beside this file).
#pragma once
#include <cmath>
#include <string>

#include "dda/paper_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/common/claims.hpp"
#include "repro/common/table.hpp"

namespace incline {

constexpr double kG = 9.81;
constexpr double kPi = 3.14159265358979323846;
// Tolerance 1 % of the distance: "good agreement" read as within the line
// width of Fig. 12.
constexpr double kTol = 0.01;
constexpr int kRecordEvery = 500;  // steps between rows of sliding.csv

struct Run {
  double distance = 0.0;  // final sliding distance, m
  double analytic = 0.0;  // Eq. 30 at the same time, m
  double rel_error() const { return (distance - analytic) / analytic; }
};

// One row of sliding.csv (Fig. 12): the distance slid at a time and Eq. 30's.
struct Sample {
  double phi_deg, time, distance, analytic;  // deg, s, m, m (Eq. 30)
};
inline std::vector<repro::Column<Sample>> sliding_columns() {
  return {{"phi_deg", [](const Sample& s) { return s.phi_deg; }},
          {"time", [](const Sample& s) { return s.time; }},
          {"distance", [](const Sample& s) { return s.distance; }},
          {"analytic", [](const Sample& s) { return s.analytic; }}};
}

// Runs one case with the friction update `update`; Eq. 30 is evaluated with
// the friction angle `phi_deg` (the scene's own, except in a control);
// appends a Sample every kRecordEvery steps to `table` if given.
inline Run run(dda::paper::Incline in, repro::TableWriter<Sample>* table, double phi_deg,
               dda::FrictionUpdate update) {
  in.scene.contact.friction_update = update;
  dda::Simulation sim(in.scene);
  const dda::Vec2 c0 = sim.centroid(1);
  const double phi = phi_deg * kPi / 180.0;
  Run r;
  while (sim.time() < in.scene.duration - 0.5 * sim.dt()) {
    sim.step();
    if (table && sim.step_count() % kRecordEvery == 0) {
      const double l = dot(sim.centroid(1) - c0, in.downhill);
      table->row({phi_deg, sim.time(), l, dda::paper::incline_distance(kG, in.theta_rad, phi, sim.time())});
    }
  }
  r.distance = dot(sim.centroid(1) - c0, in.downhill);
  r.analytic = dda::paper::incline_distance(kG, in.theta_rad, phi, sim.time());
  return r;
}

// The Eq. 30 criterion of every sliding row: within kTol of Eq. 30.
inline bool eq30_met(const Run& r) { return std::fabs(r.rel_error()) < kTol; }
// The negative control of the rows with friction (controls.cpp).
inline const char* const kControlEq30Friction = "repro_controls: 4.3 Eq. 30 with friction: FAIL with friction off";
// ... and of the rows without (a test-case name).
inline const char* const kControlEq30Frictionless = "4.3 Eq. 30 without friction: FAIL with friction on";

// The friction start-up option (not the paper's start; Scene::damping):
// settled for kSettleTime with every contact sticking (mass damping
// kSettleDamping, about twice the contact's normal mode), so the springs
// carry the static shear at t = 0 instead of loading while the block gains
// a head start.
constexpr double kSettleDamping = 80.0;  // 1/s: ~2 x the contact's 39 rad/s normal mode, 20 decay times in 0.5 s
constexpr double kSettleTime = 0.5;      // s
inline dda::paper::Incline with_start_up(dda::paper::Incline in) {
  in.scene.damping.mass = kSettleDamping;
  in.scene.damping.settle_time = kSettleTime;
  in.scene.damping.settle_sticking = true;
  return in;
}

// The Eq. 30 row of one paper case (friction angle phi_deg).
inline repro::Claim eq30_row(double phi_deg, const Run& r) {
  using repro::format_short;
  repro::Claim c{"4.3", "sliding distance at t = 1 s follows Eq. 30, phi = " + format_short(phi_deg) + " deg",
                 "'Good agreements are obtained for numerical results and analytical results' (Sect. 4.3, Fig. 12, "
                 "Eq. 30)",
                 "l = " + format_short(r.distance, 5) + " m vs " + format_short(r.analytic, 5) + " m, rel. error " +
                     format_short(r.rel_error(), 3),
                 "|rel. error| < 1 %", eq30_met(r)};
  c.control = phi_deg > 0.0 ? kControlEq30Friction : repro::control_test(kControlEq30Frictionless);
  c.scope = repro::Scope::kPaper;
  return c;
}

// A block on a slope gentler than its friction angle stays put (Sect. 4.3's
// Coulomb law, Eq. 30 with tan(phi) > tan(theta)): it may only creep by the
// elastic shear of its contact springs (m g sin(theta) / kt ~ 1 mm for the
// paper's 1 m square and kt = 1e7 N/m); 1 cm in 1 s is ten times that.
constexpr double kRestPhi = 35.0;        // deg: 5 deg above the 30 deg slope
constexpr double kRestTolerance = 0.01;  // m
inline const char* const kControlRest = "4.3 rest: FAIL with friction off";

inline repro::Claim rest_row(const Run& r) {
  using repro::format_short;
  repro::Claim c{"4.3", "a block on a slope gentler than its friction angle stays put (phi = 35 deg on 30 deg)",
                 "the premise of Sect. 4.3, not a result the paper reports: 'Block B can slide along the inclined "
                 "plane of block A if the friction angle ... is smaller than the inclined angle'",
                 "moved " + format_short(r.distance, 3) + " m down the slope in 1 s",
                 "|l| < " + format_short(kRestTolerance) + " m", std::fabs(r.distance) < kRestTolerance};
  c.key = "rest";
  c.control = std::string("repro_controls: ") + kControlRest;
  c.scope = repro::Scope::kExtension;
  return c;
}

// Creep: B launched downhill at kCreepSpeed on a kCreepTheta slope with
// friction angle phi (the row: kCreepPhi) decelerates at g (cos t tan phi -
// sin t) = 1.97 m/s^2 and stops within 0.3 s; under Coulomb friction it then
// stays. H = 1 m (the paper's rule gives 6.5 m here, on which B keeps
// rocking and walks down with either update). The creep rate: the mean
// position over [2.5, 3] s minus that over [1, 1.5] s (averaging out the
// undamped contact vibration the launch leaves), over 1.5 s.
constexpr double kCreepPhi = 30.0, kCreepTheta = 20.0;  // deg
constexpr double kCreepSpeed = 0.5;                     // m/s downhill at t = 0
constexpr double kCreepEnd = 3.0;                       // s
constexpr double kCreepSample = 1e-3;                   // s between position samples
constexpr double kCreepTolerance = 1e-3;  // m/s: at rest; the paper's update was seen creeping tens of mm/s
struct Creep {
  double early = 0.0;  // mean position over [1, 1.5] s, m
  double rate = 0.0;   // m/s
};
inline Creep creep(dda::FrictionUpdate update, double phi_deg = kCreepPhi) {
  dda::paper::Incline in = dda::paper::incline(phi_deg, kCreepTheta, kCreepEnd, true, 1.0);
  in.scene.blocks[1].velocity = kCreepSpeed * in.downhill;
  in.scene.contact.friction_update = update;
  dda::Simulation sim(in.scene);
  const dda::Vec2 c0 = sim.centroid(1);
  auto mean_position = [&](double t0, double t1) {
    double sum = 0.0;
    int n = 0;
    for (double t = t0; t <= t1; t += kCreepSample, ++n) {
      sim.advance_to(t);
      sum += dot(sim.centroid(1) - c0, in.downhill);
    }
    return sum / n;
  };
  Creep c;
  c.early = mean_position(kCreepEnd - 2.0, kCreepEnd - 1.5);
  const double late = mean_position(kCreepEnd - 0.5, kCreepEnd);
  c.rate = (late - c.early) / 1.5;
  return c;
}
inline bool creep_stopped(const Creep& c) { return std::fabs(c.rate) < kCreepTolerance; }
inline const char* const kControlCreep = "4.3 creep: FAIL on a slope steeper than the friction angle";

}  // namespace incline
