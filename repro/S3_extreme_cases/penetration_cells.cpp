// S3 penetration map: the cells and one run (penetration_cells.hpp).
#include "repro/S3_extreme_cases/penetration_cells.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/S_common/stability.hpp"

namespace s3map {
using dda::Vec2;

const char* name(Cell c) {
  switch (c) {
    case Cell::kBounced: return "bounced";
    case Cell::kGuardStop: return "guard stop";
    case Cell::kOtherStop: return "other stop";
    case Cell::kPassed: return "passed";
    case Cell::kStuck: return "stuck";
    case Cell::kMissed: return "missed";
  }
  return "?";
}

namespace {
std::vector<Vec2> square(Vec2 c) {
  return {c + Vec2{-0.5, -0.5}, c + Vec2{0.5, -0.5}, c + Vec2{0.5, 0.5}, c + Vec2{-0.5, 0.5}};
}
}  // namespace

dda::Scene scene(const Setup& c, bool guarded) {
  dda::Scene s = dda::paper::two_squares();
  s.contact.kn = c.kn;
  s.dt = c.dt;
  s.blocks[0].vertices = square({-0.5 - kGap, 0.0});
  s.blocks[1].vertices = square({0.5, kOffset});
  s.blocks[0].velocity = c.oblique ? c.speed * Vec2{std::cos(kOblique), std::sin(kOblique)} : Vec2{c.speed, 0.0};
  if (!guarded) s.guards.max_penetration = s.guards.max_approach_energy = 0.0;
  // Long enough to cross the gap and both blocks (2 m) or to finish a
  // bounce: 4 x the half period pi sqrt(m_eff / k) of the pair's spring
  // k = 2 kn (face contact, H = 1 m), m_eff = 1000 kg/m.
  s.duration = (kGap + 2.5) / c.speed + 4.0 * 3.14159 * std::sqrt(1000.0 / (2.0 * c.kn));
  return s;
}

Result run(const dda::Scene& s) {
  Result r;
  dda::Simulation sim(s);
  r.ratio = sim.dt() / sim.predicted_critical_step();
  const auto steps = static_cast<long>(std::ceil(sim.scene().duration / sim.dt()));
  bool touched = false;
  try {
    for (long k = 0; k < steps; ++k) {
      sim.step();
      if (sim.contact_count() > 0) touched = true;
      else if (touched) break;  // the contact is over: bounced or through
    }
  } catch (const dda::SimulationError& e) {
    r.message = e.what();
    const bool penetration = r.message.find("max_penetration") != std::string::npos ||
                             r.message.find("max_approach_energy") != std::string::npos;
    r.cls = penetration ? Cell::kGuardStop : Cell::kOtherStop;
  }
  const bool crossed = sim.centroid(0).x > sim.centroid(1).x;
  if (r.message.empty())
    r.cls = crossed ? Cell::kPassed : !touched ? Cell::kMissed : sim.contact_count() > 0 ? Cell::kStuck : Cell::kBounced;
  else if (crossed) r.cls = Cell::kPassed;  // a stop after the blocks crossed is too late
  if (r.cls == Cell::kBounced) r.final_state = repro::stab::vertex_state(sim);
  return r;
}

namespace {
bool has(const std::string& text, const char* part) { return text.find(part) != std::string::npos; }
}  // namespace

bool actionable(const std::string& m) {
  for (const char* part : {"step ", "(t = ", "pair (", "dt/dt_crit", "contact.kn"})
    if (!has(m, part)) return false;
  return has(m, "(bound ") || has(m, "the pair can store");
}

}  // namespace s3map
