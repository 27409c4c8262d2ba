// Paper A Sect. 4.2: the symmetric-stack run and its claim row, shared by the
// driver (symmetric_stack.cpp) and the negative control
// (controls.cpp beside this file).
#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/common/claims.hpp"
#include "repro/common/table.hpp"
#include "repro/common/sim_output.hpp"

namespace symmetric_stack {

// Tolerances: the scene is symmetric to the last bit only up to the order
// of floating-point operations (CP/TP roles and vertex orders are not
// mirrored), so round-off differences may grow through the impacts; 1e-6 m
// (and 1e-6 rad) is 1e-6 of the block size, far below anything visible in
// Fig. 10. The top block must move (> 1 cm) so that the row tests a response.
constexpr double kPositionTol = 1e-6;  // m
constexpr double kRotationTol = 1e-6;  // rad
constexpr double kMinTravel = 0.01;    // m
constexpr int kTopBlock = 3;           // dda::paper::symmetric_stack(): the top square

struct Result {
  double worst_position = 0.0;  // max |x_i + x_j|, |y_i - y_j| over mirror pairs (i, j), m
  double worst_rotation = 0.0;  // max |r_i + r_j| over mirror pairs, rad (mirror images turn opposite ways)
  double travel = 0.0;          // largest centroid travel of the top block, m
};

// One row of Fig. 10's traces: every block's centroid and the largest
// position asymmetry over the mirror pairs at that moment.
struct Trace {
  double time;
  std::vector<dda::Vec2> centroid;
  double asymmetry;
};
// Columns time, x0, y0, x1, y1, ..., asymmetry for `n` blocks.
inline std::vector<repro::Column<Trace>> trace_columns(int n) {
  std::vector<repro::Column<Trace>> columns = {{"time", [](const Trace& t) { return t.time; }}};
  for (int i = 0; i < n; ++i) {
    columns.push_back({"x" + std::to_string(i), [i](const Trace& t) { return t.centroid[i].x; }});
    columns.push_back({"y" + std::to_string(i), [i](const Trace& t) { return t.centroid[i].y; }});
  }
  columns.push_back({"asymmetry", [](const Trace& t) { return t.asymmetry; }});
  return columns;
}

// Runs the stack; centroid traces (with the position asymmetry) go to
// `traces` and the first and last block outlines to `snaps`, if given.
inline Result run(const dda::paper::SymmetricStack& st, repro::TableWriter<Trace>* traces,
                  repro::TableWriter<repro::VertexRow>* snaps) {
  dda::Simulation sim(st.scene);
  const int n = sim.scene_block_count();
  Result r;
  auto asymmetry = [&] {
    double a = 0.0;
    for (int i = 0; i < n; ++i) {
      const int j = st.mirror[static_cast<std::size_t>(i)];
      a = std::max({a, std::fabs(sim.centroid(i).x + sim.centroid(j).x),
                    std::fabs(sim.centroid(i).y - sim.centroid(j).y)});
      r.worst_rotation = std::max(r.worst_rotation, std::fabs(sim.displacement(i)[2] + sim.displacement(j)[2]));
    }
    return a;
  };
  auto record = [&](double a) {
    if (!traces) return;
    Trace t{sim.time(), {}, a};
    for (int i = 0; i < n; ++i) t.centroid.push_back(sim.centroid(i));
    traces->row(t);
  };
  if (snaps) repro::write_snapshot(*snaps, sim);
  r.worst_position = asymmetry();
  record(r.worst_position);
  const dda::Vec2 c0 = sim.centroid(kTopBlock);
  while (sim.time() < st.scene.duration - 0.5 * sim.dt()) {
    sim.step();
    const double a = asymmetry();
    r.worst_position = std::max(r.worst_position, a);
    r.travel = std::max(r.travel, dda::length(sim.centroid(kTopBlock) - c0));
    record(a);
  }
  if (snaps) repro::write_snapshot(*snaps, sim);
  return r;
}

inline repro::Claim row(const Result& r) {
  using repro::format_short;
  repro::Claim c{"4.2", "the stack moves symmetrically about the top block's axis, positions and rotations",
                 "'The symmetric response of the block system verifies the correctness of the proposed contact solution "
                 "approach' (Sect. 4.2, Fig. 10)",
                 "max over 1 s and all mirror pairs: centroid asymmetry " + format_short(r.worst_position, 3) +
                     " m, rotation asymmetry " + format_short(r.worst_rotation, 3) + " rad; top block moved up to " +
                     format_short(r.travel, 3) + " m",
                 "< " + format_short(kPositionTol) + " m and < " + format_short(kRotationTol) +
                     " rad, and the top block moved > " + format_short(kMinTravel) + " m",
                 r.worst_position < kPositionTol && r.worst_rotation < kRotationTol && r.travel > kMinTravel};
  c.key = "symmetric";
  c.control = "repro_controls: 4.2 symmetry: FAIL when the impactor drifts sideways";
  c.scope = repro::Scope::kPaper;
  return c;
}

}  // namespace symmetric_stack
