// S2 stability maps: the scenes and the classification of one cell (maps.hpp).
#include "repro/S2_stability_maps/maps.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "dda/paper_scenes.hpp"
#include "dda/robustness_scenes.hpp"
#include "dda/simulation.hpp"

namespace s2 {

using dda::Vec2;
using repro::stab::RunClass;

MapScene two_squares_map() {
  MapScene m;
  m.name = "two_squares";
  m.title = "4.1 two squares (1 m/s, unified H)";
  m.scene = dda::paper::two_squares();
  m.scene.blocks[0].vertices = rect(-1.001, -0.5, 1.0, 1.0);  // 1 mm gap
  m.a = 0;
  m.b = 1;
  m.axis = {1.0, 0.0};
  m.rel_mass = 1000.0;
  m.impact_energy = 0.5 * 2000.0 * 1.0;
  m.h_sum_inv = 2.0;  // H = 1 m
  return m;
}

MapScene bouncing_map(dda::HRule h) {
  MapScene m;
  const bool ins = h == dda::HRule::kInscribedRadius;
  m.name = ins ? "bouncing_inscribed" : "bouncing_unified";
  m.title = std::string("5.1 bouncing block, case 1 (3.13 m/s, ") + (ins ? "inscribed-radius H)" : "unified H)");
  dda::paper::BouncingBlock bb = dda::paper::bouncing_block(0.1, h, 1.0);
  m.scene = bb.scene;
  const double v = std::sqrt(2.0 * kG * bb.drop);
  for (Vec2& p : m.scene.blocks[1].vertices) p.y -= bb.drop - 0.001;  // 1 mm above B
  m.scene.blocks[1].velocity = {0.0, -v};
  m.a = 1;  // A above B: in order while B's centroid lies below A's, along the axis -y
  m.b = 0;
  m.axis = {0.0, -1.0};
  m.rel_mass = 2000.0;
  m.impact_energy = 0.5 * 2000.0 * v * v;
  m.h_sum_inv = ins ? 1.0 / 0.5 + 1.0 / 0.05 : 2.0 / 2.05;
  return m;
}

double window(const MapScene& m, double kn, double dt) {
  const double omega = std::sqrt(kn * m.contact_length * m.h_sum_inv / m.rel_mass);
  return std::max(std::min(0.4, 0.002 + 4.0 * 3.14159265358979 / omega), 10.0 * dt);
}

MapRun map_run(const MapScene& m, double kn, double dt, bool balance_guard) {
  MapRun r;
  dda::Scene s = m.scene;
  s.contact.kn = kn;
  s.dt = dt;
  if (!balance_guard) s.guards.max_balance_error = 0.0;  // off
  r.window = window(m, kn, dt);
  s.duration = r.window;
  dda::Simulation sim(s);
  r.ratio0 = dt / sim.predicted_critical_step();
  r.ratio_max = r.ratio0;
  const double e0 = sim.energy().total();
  try {
    while (sim.time() < r.window - 0.5 * dt) {
      sim.step();
      const double growth = (sim.energy().total() - e0) / m.impact_energy;
      r.max_growth = std::max(r.max_growth, growth);
      if (sim.contact_count() > 0) r.ratio_max = std::max(r.ratio_max, dt / sim.critical_time_step());
    }
  } catch (const dda::SimulationError& e) {
    r.message = e.what();
    // An energy-budget stop says the run is inaccurate, not that it
    // diverges: the same cell without that guard decides.
    if (e.reason == dda::StopReason::kEnergyBudget) {
      MapRun unguarded = map_run(m, kn, dt, false);
      unguarded.message = "the energy-budget guard stopped it (" + r.message + "); with that guard off: " +
                     (unguarded.message.empty() ? "finishes" : unguarded.message);
      return unguarded;
    }
    const bool motion = e.reason == dda::StopReason::kStepMotion;
    // The penetration guard (depth past half the block, or an approach
    // energy the pair cannot store) stops a pass-through at any dt: a soft
    // kn, not a time-step blow-up.
    const bool pass_through =
        e.reason == dda::StopReason::kPenetration || e.reason == dda::StopReason::kApproachEnergy;
    r.cls = pass_through || (motion && r.max_growth <= 0.01) ? RunClass::kFlipThrough : RunClass::kBlowUp;
    return r;
  }
  r.energy_change = (sim.energy().total() - e0) / m.impact_energy;
  const double order = dda::dot(sim.centroid(m.b) - sim.centroid(m.a), m.axis);
  if (order < 0.0) {
    r.cls = RunClass::kFlipThrough;
  } else if (r.energy_change > 0.01) {
    r.cls = RunClass::kEnergyGrowth;
  }
  return r;
}

}  // namespace s2
