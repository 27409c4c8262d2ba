// S3 extreme cases (extreme_cases.cpp says what they are and expect): the
// cases, one run and the row criterion, here so that the negative controls
// (repro/common/test_controls.cpp) apply the same criterion to deliberately
// wrong configurations.
#pragma once
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "dda/overlap.hpp"
#include "dda/paper_scenes.hpp"
#include "dda/potential.hpp"
#include "dda/simulation.hpp"
#include "repro/S_common/stability.hpp"
#include "repro/common/common.hpp"
#include "repro/common/shapes.hpp"

namespace s3 {
using dda::Vec2;
using repro::format_short;
using repro::stab::RunClass;

inline std::string num(double x) { return repro::format_full(x); }

using repro::rect;

struct Extreme {
  std::string name, parameter;
  dda::Scene scene;
  double duration = 1.0;
  double va_expected = 0.0, vb_expected = 0.0;  // x-velocities after the impact (rigid 1D elastic)
  double v0 = 1.0;
};

// Out of line: GCC 12 warns (falsely, -Wmaybe-uninitialized) about Scene's
// default member initialisers when the constructor is inlined into cases().
[[gnu::noinline]] inline Extreme new_case() { return Extreme{}; }

inline dda::Scene base_scene() {
  dda::Scene s = dda::paper::two_squares();
  s.blocks.clear();
  return s;
}

inline dda::BlockSpec block(std::vector<Vec2> v, Vec2 vel, int material = 0) {
  dda::BlockSpec b;
  b.vertices = std::move(v);
  b.velocity = vel;
  b.material = material;
  return b;
}

inline void set_expected(Extreme& e, double ma, double mb) {
  e.va_expected = (ma - mb) / (ma + mb) * e.v0;
  e.vb_expected = 2.0 * ma / (ma + mb) * e.v0;
}

inline std::vector<Extreme> cases() {
  std::vector<Extreme> out;
  for (double ratio : {1e4, 1e-4}) {
    Extreme e = new_case();
    e.name = "mass ratio";
    e.parameter = "m_A / m_B = " + format_short(ratio);
    e.scene = base_scene();
    e.scene.materials = {{2000.0, 1e9, 0.25}, {2000.0 * ratio, 1e9, 0.25}};
    e.scene.blocks = {block(rect(-1.1, -0.5, 1.0, 1.0), {1.0, 0.0}, 1), block(rect(0.0, -0.5, 1.0, 1.0), {}, 0)};
    e.duration = 0.4;
    set_expected(e, ratio, 1.0);
    out.push_back(e);
  }
  for (double v : {1.0, 10.0, 100.0}) {
    Extreme e = new_case();
    e.name = "impact speed";
    e.parameter = format_short(v) + " m/s";
    e.scene = base_scene();
    e.v0 = v;
    e.scene.blocks = {block(rect(-1.001, -0.5, 1.0, 1.0), {v, 0.0}), block(rect(0.0, -0.5, 1.0, 1.0), {})};
    e.duration = 0.1;
    set_expected(e, 1.0, 1.0);
    out.push_back(e);
  }
  {
    Extreme e = new_case();
    e.name = "size ratio";
    e.parameter = "0.01 m square hits a 10 m square (1000 x)";
    e.scene = base_scene();
    e.scene.blocks = {block(rect(-0.0101, -0.005, 0.01, 0.01), {1.0, 0.0}), block(rect(0.0, -5.0, 10.0, 10.0), {})};
    e.duration = 0.02;
    set_expected(e, 1e-4, 100.0);  // masses in proportion to the areas, 1e-4 and 100 m^2
    out.push_back(e);
  }
  {
    Extreme e = new_case();
    e.name = "sliver 100:1";
    e.parameter = "1 m square hits the long side of a 0.01 m x 1 m sliver";
    e.scene = base_scene();
    e.scene.blocks = {block(rect(-1.001, -0.5, 1.0, 1.0), {1.0, 0.0}), block(rect(0.0, -0.5, 0.01, 1.0), {})};
    e.duration = 0.05;
    set_expected(e, 1.0, 0.01);
    out.push_back(e);
  }
  {
    Extreme e = new_case();
    e.name = "sliver 100:1";
    e.parameter = "1 m x 0.01 m sliver flies end-on into a 1 m square";
    e.scene = base_scene();
    e.scene.blocks = {block(rect(-1.001, -0.005, 1.0, 0.01), {1.0, 0.0}), block(rect(0.0, -0.5, 1.0, 1.0), {})};
    e.duration = 0.3;
    set_expected(e, 0.01, 1.0);
    out.push_back(e);
  }
  {
    Extreme e = new_case();
    e.name = "deep penetration";
    e.parameter = "two squares at 1 m/s, kn = 1e3 Pa (overlap to stop: 0.71 m)";
    e.scene = base_scene();
    e.scene.contact.kn = 1e3;
    e.scene.blocks = {block(rect(-1.001, -0.5, 1.0, 1.0), {1.0, 0.0}), block(rect(0.0, -0.5, 1.0, 1.0), {})};
    e.duration = 3.0;
    set_expected(e, 1.0, 1.0);
    out.push_back(e);
  }
  return out;
}

struct Outcome {
  RunClass cls = RunClass::kStable;
  double dt = 0.0, ratio0 = 0.0, ratio_max = 0.0;
  double momentum_error = 0.0, energy_error = 0.0;
  double va = 0.0, vb = 0.0, velocity_error = 0.0;
  double overlap = 0.0;  // deepest overlap thickness / smaller inscribed diameter
  double t_deep = -1.0, t_wrong = -1.0, t_swap = -1.0, t_soft = -1.0;
  bool penetration_stop = false;  // the penetration guard stopped the run
  std::string message;
  const char* class_name() const { return penetration_stop ? "penetration guard stop" : repro::stab::class_name(cls); }
};

inline double inscribed_diameter(const dda::Polygon& p) { return 2.0 * dda::inscribed_circle(p).radius; }

inline Outcome run(const Extreme& e, double dt_fraction) {
  Outcome o;
  dda::Scene s = e.scene;
  s.duration = e.duration;
  s.dt_fraction = dt_fraction;
  dda::Simulation sim(s);
  o.dt = sim.dt();
  o.ratio0 = sim.dt() / sim.predicted_critical_step();
  o.ratio_max = o.ratio0;
  const double small = std::min(inscribed_diameter(sim.polygon(0)), inscribed_diameter(sim.polygon(1)));
  const Vec2 p0 = sim.momentum();
  const dda::Energy en0 = sim.energy();
  const double e0 = en0.total(), ekin0 = en0.kinetic;
  double max_growth = 0.0, prev_force = 0.0, prev_thick = 0.0;
  const long steps = std::lround(e.duration / sim.dt());
  try {
    for (long k = 0; k < steps; ++k) {
      sim.step();
      const double t = sim.time();
      o.momentum_error = std::max(o.momentum_error, dda::length(sim.momentum() - p0) / dda::length(p0));
      max_growth = std::max(max_growth, (sim.energy().total() - e0) / ekin0);
      if (sim.contacts().empty()) continue;
      o.ratio_max = std::max(o.ratio_max, sim.dt() / sim.critical_time_step());
      const dda::Polygon& a = sim.polygon(0);
      const dda::Polygon& b = sim.polygon(1);
      const double tol = dda::pair_tolerance(a, b);
      const dda::Polygon ip = dda::intersection_polygon(a, b, tol);
      const double thick = ip.count >= 3 ? inscribed_diameter(ip) : 0.0;
      o.overlap = std::max(o.overlap, thick / small);
      // Softening: the overlap grows while the normal force drops (negative
      // contact stiffness: past the middle of a block the far side is nearer).
      double force = 0.0;
      for (const dda::ContactInfo& c : sim.contacts()) force += dda::length(c.normal_force);
      if (o.t_soft < 0.0 && thick > prev_thick && force < prev_force && thick > 0.01 * small) o.t_soft = t;
      prev_force = force;
      prev_thick = thick;
      if (o.t_deep < 0.0 && repro::stab::deep_penetration(a, b)) o.t_deep = t;
      for (const dda::ContactInfo& c : sim.contacts()) {
        const Vec2 towards = sim.centroid(c.tp) - sim.centroid(c.cp);
        if (o.t_wrong < 0.0 && dda::dot(c.normal_force, towards) > 0.0) o.t_wrong = t;
      }
      if (o.t_swap < 0.0 && sim.centroid(1).x < sim.centroid(0).x) o.t_swap = t;
    }
  } catch (const dda::SimulationError& err) {
    o.message = err.what();
    if (sim.centroid(1).x < sim.centroid(0).x) o.t_swap = sim.time();  // stopped too late
    o.penetration_stop =
        err.reason == dda::StopReason::kPenetration || err.reason == dda::StopReason::kApproachEnergy;
    const bool motion = err.reason == dda::StopReason::kStepMotion;
    o.cls = motion && max_growth <= 0.01 ? RunClass::kFlipThrough : RunClass::kBlowUp;
    return o;
  }
  if (o.t_swap < 0.0 && sim.centroid(1).x < sim.centroid(0).x) o.t_swap = sim.time();
  o.energy_error = (sim.energy().total() - e0) / ekin0;
  o.va = sim.velocity(0)[0];
  o.vb = sim.velocity(1)[0];
  o.velocity_error = (std::fabs(o.va - e.va_expected) + std::fabs(o.vb - e.vb_expected)) / e.v0;
  if (o.t_swap >= 0.0) {
    o.cls = RunClass::kFlipThrough;
  } else if (o.energy_error > 0.01) {
    o.cls = RunClass::kEnergyGrowth;
  }
  return o;
}

// The row criterion: a clean run (stable, velocities within 5 % of the
// rigid answer) at a dt below dt_crit, a guard stop naming dt/dt_crit above
// it; the deep cases (the contact cannot stop the blocks: their approach
// energy exceeds what the pair can store) must be stopped by the
// penetration guard before the blocks cross. A run in which the centroids
// swapped (the blocks passed through each other) never passes. Returns the
// verdict and the criterion in words.
inline std::pair<bool, std::string> row_verdict(const Extreme& e, const Outcome& o) {
  bool pass = false;
  std::string tolerance;
  const bool deep_case = e.name == "deep penetration" || e.parameter == "100 m/s";
  if (deep_case) {
    tolerance = "stopped by the penetration guard before the blocks cross";
    pass = o.penetration_stop;
  } else if (o.ratio0 > 1.0) {
    tolerance = "dt above dt_crit: the solver stops with a message";
    pass = !o.message.empty() && o.message.find("dt/dt_crit") != std::string::npos;
  } else {
    tolerance = "stable and |v - v_expected| < 5 % of the impact speed";
    pass = o.cls == RunClass::kStable && o.velocity_error < 0.05;
  }
  return {pass && o.t_swap < 0.0, tolerance + "; the blocks never cross"};
}
inline const char* const kRowControl =
    "repro_controls: S3 rows: FAIL with the penetration guard off and with the wrong expected velocities";

// ---- the guard row: a too-large dt is stopped with a full message ----------

// Two squares at 1 m/s, 1 mm apart, kn 1e10 Pa, dt = dt_fraction x the
// predicted critical step (the row: 3), the energy checked every step so
// that the stop comes during the impact.
inline dda::Scene guard_scene(double dt_fraction) {
  dda::Scene s = dda::paper::two_squares();
  s.blocks[0].vertices = rect(-1.001, -0.5, 1.0, 1.0);
  s.contact.kn = 1e10;
  s.dt_fraction = dt_fraction;
  s.duration = 0.2;
  s.guards.energy_check_every = 1;
  return s;
}

// The row's criterion: the solver stopped the run with a message naming the
// step, the time, the block, the pair, dt/dt_crit and what was exceeded (a
// guard limit, or a non-finite or collapsed state), and at least one row
// was written before the stop.
inline bool guard_stop_complete(const std::string& message, long rows_kept) {
  bool names_all = !message.empty();
  for (const char* word : {"step ", "(t = ", " s)", "block ", "pair (", "dt/dt_crit = "})
    names_all = names_all && message.find(word) != std::string::npos;
  names_all = names_all && (message.find("more than") != std::string::npos ||
                            message.find("non-finite") != std::string::npos ||
                            message.find("collapsed") != std::string::npos);
  return names_all && rows_kept >= 1;
}
inline constexpr const char* kControlGuardStop = "S3 guard stop: FAIL below the critical step and on a bare message";

}  // namespace s3
