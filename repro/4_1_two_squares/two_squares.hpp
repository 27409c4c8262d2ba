// Paper A Sect. 4.1: the run and the claim rows of the two-squares collision,
// shared by the driver (two_squares.cpp) and the negative controls
// (controls.cpp beside this file, which run the same criteria on deliberately wrong
// scenes and assert FAIL).
#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dda/simulation.hpp"
#include "repro/common/claims.hpp"
#include "repro/common/table.hpp"

namespace two_squares {

// Acceptance criteria (named so that the driver and the controls share them).
constexpr double kVelocityTol = 0.01;   // m/s: 1 % of A's 1 m/s, the line width of Fig. 8
constexpr double kMomentumTol = 1e-9;   // relative: round-off of equal and opposite contact forces
constexpr double kEnergyTol = 1e-2;     // relative: penalty contact stores < 1 % at the peak
constexpr double kSpeedA = 1.0;         // m/s: A's initial speed (dda::paper::two_squares)
constexpr int kRecordEvery = 10;        // steps between rows of velocity.csv

struct Result {
  double va = 0.0, vb = 0.0;            // x velocities at the end, m/s
  double worst_momentum = 0.0;          // max |p - p0| / |p0|
  double worst_energy = 0.0;            // max |E - E0| / E0
  double t_first = -1.0, t_last = -1.0; // first and last step with a contact, s
};

// One row of Fig. 8's series (velocity.csv).
struct Sample {
  double time, vx_a, vx_b, momentum_x;
  dda::Energy energy;
};
inline std::vector<repro::Column<Sample>> velocity_columns() {
  return {{"time", [](const Sample& s) { return s.time; }},
          {"vx_A", [](const Sample& s) { return s.vx_a; }},
          {"vx_B", [](const Sample& s) { return s.vx_b; }},
          {"momentum_x", [](const Sample& s) { return s.momentum_x; }},
          {"kinetic", [](const Sample& s) { return s.energy.kinetic; }},
          {"strain", [](const Sample& s) { return s.energy.strain; }},
          {"contact", [](const Sample& s) { return s.energy.contact; }},
          {"total_energy", [](const Sample& s) { return s.energy.total(); }}};
}

// Runs `scene` (block 0 = A, block 1 = B) to its duration; rows of Fig. 8 go
// to `table` if given.
inline Result run(const dda::Scene& scene, repro::TableWriter<Sample>* table) {
  dda::Simulation sim(scene);
  Result r;
  const double p0 = sim.momentum().x;
  const double e0 = sim.energy().total();
  auto record = [&] {
    const dda::Energy e = sim.energy();
    if (table) table->row({sim.time(), sim.velocity(0)[0], sim.velocity(1)[0], sim.momentum().x, e});
    r.worst_energy = std::max(r.worst_energy, std::fabs(e.total() - e0) / e0);
  };
  record();
  while (sim.time() < scene.duration) {
    sim.step();
    r.worst_momentum = std::max(r.worst_momentum, std::fabs(sim.momentum().x - p0) / std::fabs(p0));
    if (sim.contact_count() > 0) {
      if (r.t_first < 0.0) r.t_first = sim.time();
      r.t_last = sim.time();
    }
    if (sim.step_count() % kRecordEvery == 0) record();
  }
  r.va = sim.velocity(0)[0];
  r.vb = sim.velocity(1)[0];
  return r;
}

// Row keys, used by the controls to pick a row.
inline const char* const kKeyAStops = "a-stops";
inline const char* const kKeyBLeaves = "b-leaves";
inline const char* const kKeyMomentum = "momentum";
inline const char* const kKeyEnergy = "energy";

inline std::vector<repro::Claim> claims(const Result& r) {
  using repro::format_short;
  std::vector<repro::Claim> c = {
      {"4.1", "block A stops after the impact", "'the two blocks exchange their kinetic energy during the collision process' (Sect. 4.1, Fig. 8): v_A -> 0", "v_A(1 s) = " + format_short(r.va) + " m/s",
       "|v_A| < " + format_short(kVelocityTol) + " m/s", std::fabs(r.va) < kVelocityTol},
      {"4.1", "block B leaves with A's speed", "'the two blocks exchange their kinetic energy' (Sect. 4.1, Fig. 8): v_B -> 1 m/s", "v_B(1 s) = " + format_short(r.vb) + " m/s",
       "|v_B - 1| < " + format_short(kVelocityTol) + " m/s", std::fabs(r.vb - kSpeedA) < kVelocityTol},
      {"4.1", "momentum is conserved", "'the results satisfy the conservation of momentum' (Sect. 4.1, Fig. 8)",
       "max |p - p0| / p0 = " + format_short(r.worst_momentum, 3), "< " + format_short(kMomentumTol),
       r.worst_momentum < kMomentumTol},
      {"4.1", "energy is conserved through the collision (no damping)", "'the two blocks exchange their kinetic energy' (Sect. 4.1): none lost",
       "max |E - E0| / E0 = " + format_short(r.worst_energy, 3) + "; contact from t = " + format_short(r.t_first) +
           " to " + format_short(r.t_last) + " s",
       "< " + format_short(kEnergyTol), r.worst_energy < kEnergyTol},
  };
  const char* const keys[] = {kKeyAStops, kKeyBLeaves, kKeyMomentum, kKeyEnergy};
  const char* const controls[] = {"4.1 velocity exchange: FAIL when B is twice as heavy",
                                  "4.1 velocity exchange: FAIL when B is twice as heavy",
                                  "4.1 momentum: FAIL when B is fixed",
                                  "4.1 energy: FAIL with mass damping"};
  for (std::size_t i = 0; i < c.size(); ++i) {
    c[i].key = keys[i];
    c[i].control = std::string("repro_controls: ") + controls[i];
    c[i].scope = repro::Scope::kPaper;
  }
  return c;
}

}  // namespace two_squares
