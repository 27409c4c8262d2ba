// Paper A Sect. 5.1: one bouncing-block run and the H-rule comparison row,
// shared by the driver (bouncing_block.cpp) and the negative controls
// (controls.cpp beside this file).
#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dda/robustness_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/common/claims.hpp"
#include "repro/common/cli.hpp"
#include "repro/common/csv.hpp"

namespace bouncing_block {
using repro::format_short;

struct Run {
  std::string label;
  double b_height = 0.0;
  dda::HRule rule{};
  std::vector<double> time, dy;  // A's accumulated vertical displacement
  dda::paper::RunStats stats;
  double h_a = 0.0, h_b = 0.0;
  double max_mirror = 0.0;     // mirror asymmetry of A about x = 0, m
  double lowest_base = 1e300;  // lowest y of A's vertices (B's top is y = 0)
  double first_rebound = 0.0;  // highest dy after the first contact, m
  double strain_after = 0.0;   // largest strain energy of A in the flight after the first impact, J
  double seconds = 0.0;
};

// `tweak`, if given, changes the scene before the run (the negative controls).
inline Run run(double b_height, dda::HRule rule, const std::string& label, void (*tweak)(dda::Scene&) = nullptr) {
  const repro::Progress clock(label);
  dda::paper::BouncingBlock bb = dda::paper::bouncing_block(b_height, rule);
  if (tweak) tweak(bb.scene);
  dda::Simulation sim(bb.scene);
  dda::paper::RunMonitor mon(sim, bb.fixed, bb.falling);
  Run r;
  r.label = label;
  r.b_height = b_height;
  r.rule = rule;
  r.h_a = sim.potential_length(bb.falling);
  r.h_b = sim.potential_length(bb.fixed);
  const double y0 = sim.centroid(bb.falling).y;
  r.time.push_back(0.0);
  r.dy.push_back(0.0);
  int phase = 0;
  r.first_rebound = -1e300;
  while (sim.time() < bb.scene.duration - 0.5 * sim.dt()) {
    sim.step();
    mon.sample();
    const dda::Polygon& a = sim.polygon(bb.falling);
    for (int k = 0; k < a.count; ++k) r.lowest_base = std::min(r.lowest_base, a.vertex(k).y);
    r.max_mirror = std::max(r.max_mirror, dda::paper::mirror_symmetry_error(sim, bb.falling, 0.0));
    const double dy = sim.centroid(bb.falling).y - y0;
    // Phase 0 falling, 1 first contact, 2 first flight after it, 3 later.
    const bool touching = sim.contact_count() > 0;
    if ((phase == 0 && touching) || (phase == 1 && !touching) || (phase == 2 && touching)) ++phase;
    if (phase == 2) {
      r.first_rebound = std::max(r.first_rebound, dy);
      if (sim.step_count() % 10 == 0) r.strain_after = std::max(r.strain_after, sim.energy().strain);
    }
    if (sim.step_count() % 10 == 0) {
      r.time.push_back(sim.time());
      r.dy.push_back(dy);
    }
  }
  r.stats = mon.stats();
  r.seconds = clock.elapsed_seconds();
  return r;
}

inline double max_difference(const Run& a, const Run& b) {
  double m = 0.0;
  for (std::size_t i = 0; i < std::min(a.dy.size(), b.dy.size()); ++i) m = std::max(m, std::fabs(a.dy[i] - b.dy[i]));
  return m;
}

// Criterion (set before the runs): "nearly equal" vs "significantly
// different" read as the unified-H difference being at most half of the
// inscribed-radius one.
constexpr double kRatioMax = 0.5;

// The comparison row from the largest case-1/case-2 differences under the
// unified and under the inscribed-radius H.
inline repro::Claim comparison_row(double diff_unified, double diff_inscribed) {
  repro::Claim c{"5.1", "the unified H makes cases 1 and 2 closer than the inscribed-radius H does",
                 "'the current approach using a unified H value lead to very similar block bouncing response. By "
                 "contrast, the previous approach ... lead to significantly different block bouncing response' "
                 "(Sect. 5.1, Fig. 14)",
                 "difference ratio unified / inscribed = " + format_short(diff_unified / diff_inscribed, 3),
                 "<= " + format_short(kRatioMax), diff_unified <= kRatioMax * diff_inscribed};
  c.control = "repro_controls: 5.1 H comparison: FAIL with the H rules swapped";
  c.scope = repro::Scope::kPaper;
  return c;
}

// A sane run: energy conserved to 1 % (frictionless, undamped) and the drop
// mirror symmetric to round-off (1e-9 m).
constexpr double kEnergyTol = 0.01;
constexpr double kMirrorTol = 1e-9;  // m
inline const char* const kControlSane = "5.1 sane run: FAIL with mass damping";

inline repro::Claim sane_row(const Run& r) {
  // Sane: A never passes B's top by more than the peak overlap allows
  // (no flip-through: its base stays above B's bottom), energy conserved
  // to 1 % (frictionless, undamped), and the drop stays symmetric.
  const bool no_flip = r.lowest_base > -r.b_height;
  const bool ok = no_flip && r.stats.energy_error < kEnergyTol && r.max_mirror < kMirrorTol;
  repro::Claim c{"5.1", r.label + ": run stays sane", "(not stated; robustness)",
                  "energy error " + format_short(r.stats.energy_error, 3) + "; peak overlap thickness " +
                      format_short(r.stats.peak_thickness, 3) + " m; lowest point of A " +
                      format_short(r.lowest_base, 3) + " m (B's top at 0, bottom at " +
                      format_short(-r.b_height) + "); first rebound to dy = " + format_short(r.first_rebound, 4) +
                      " m (A's vibration keeps " + format_short(r.strain_after, 3) +
                      " J of strain energy after the first impact, of m g 0.5 m = 9810 J); mirror asymmetry " +
                      format_short(r.max_mirror, 2) + " m",
                  "energy error < 1 %, A's base above B's bottom, asymmetry < 1e-9 m", ok};
  c.control = std::string("repro_controls: ") + kControlSane;
  c.scope = repro::Scope::kExtension;
  return c;
}

}  // namespace bouncing_block
