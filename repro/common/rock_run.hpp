// What the drivers of long rock-mass runs (Paper A Sects. 6.1 and 6.2) share
// (header only, like sim_output.hpp: the repro_common library itself does not
// depend on dda): the frames they write (frames.csv, the block polygons, and
// blocks.csv, each block's state, at the same moments), the boundary
// segments of the scene (boundaries.csv), and the run loop that advances the
// simulation between outputs and reports progress.
#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "dda/scene.hpp"
#include "dda/simulation.hpp"
#include "repro/common/cli.hpp"
#include "repro/common/sim_output.hpp"
#include "repro/common/table.hpp"

namespace repro {

// One block's state at a moment: a row of blocks.csv.
struct BlockState {
  double time;
  int block;
  dda::Vec2 centroid;
  dda::Vec6 velocity, displacement;  // rates and the displacement since the start (u, v, r, ...)
};
inline std::vector<Column<BlockState>> block_state_columns() {
  return {{"time", [](const BlockState& b) { return b.time; }},
          {"block", [](const BlockState& b) { return b.block; }},
          {"cx", [](const BlockState& b) { return b.centroid.x; }},
          {"cy", [](const BlockState& b) { return b.centroid.y; }},
          {"vx", [](const BlockState& b) { return b.velocity[0]; }},
          {"vy", [](const BlockState& b) { return b.velocity[1]; }},
          {"speed", [](const BlockState& b) { return std::hypot(b.velocity[0], b.velocity[1]); }},
          {"dx", [](const BlockState& b) { return b.displacement[0]; }},
          {"dy", [](const BlockState& b) { return b.displacement[1]; }},
          {"rotation", [](const BlockState& b) { return b.displacement[2]; }}};
}

// frames.csv (every block's polygon, snapshot_columns) and blocks.csv (each
// scene block's state) under `dir`, written together at each frame.
class FrameFiles {
 public:
  FrameFiles(const std::string& dir, const std::string& note)
      : frames_(dir + "/frames.csv", snapshot_columns(), {note}),
        states_(dir + "/blocks.csv", block_state_columns(), {note}) {}
  void write(const dda::Simulation& sim) {
    write_snapshot(frames_, sim);
    for (int i = 0; i < sim.scene_block_count(); ++i)
      states_.row({sim.time(), i, sim.centroid(i), sim.velocity(i), sim.displacement(i)});
  }
  void commit() {
    frames_.commit();
    states_.commit();
  }

 private:
  TableWriter<VertexRow> frames_;
  TableWriter<BlockState> states_;
};

// boundaries.csv: the scene's boundary segments.
inline void write_boundaries(const std::string& path, const std::vector<dda::BoundarySegment>& boundaries) {
  using Segment = dda::BoundarySegment;
  write_table<Segment>(path,
                       {{"ax", [](const Segment& s) { return s.a.x; }},
                        {"ay", [](const Segment& s) { return s.a.y; }},
                        {"bx", [](const Segment& s) { return s.b.x; }},
                        {"by", [](const Segment& s) { return s.b.y; }},
                        {"depth", [](const Segment& s) { return s.depth; }}},
                       boundaries, {"boundary segments, solid on the right of a -> b"});
}

// A run's outputs: `sample` every series_every steps, `frame` every
// frame_every, `snapshot` at every multiple of snapshot_every (0: none) and
// at each of snapshot_steps; each also at the last step. `report(step,
// elapsed)` gives the progress line written at most every kReportEvery
// seconds of wall time (checked at the samples).
struct RunOutputs {
  long long series_every = 1, frame_every = 1, snapshot_every = 0;
  std::vector<long long> snapshot_steps;
  std::function<void()> sample, frame, snapshot;
  std::function<std::string(long long step, double elapsed)> report;
};

// Runs `sim` from step 0 to `steps`, the steps between two outputs as one
// Simulation::advance; wall time from `clock`. A dda::SimulationError
// propagates (the outputs written so far stay in their writers).
inline void run_with_outputs(dda::Simulation& sim, long long steps, const RunOutputs& o, const Progress& progress,
                             const Progress& clock) {
  constexpr double kReportEvery = 5.0;  // s of wall time between progress lines
  std::vector<long long> periods = {o.series_every, o.frame_every};
  if (o.snapshot_every > 0) periods.push_back(o.snapshot_every);
  const OutputSchedule outputs(steps, periods, o.snapshot_steps);
  double last_report = 0.0;
  for (long long s = 0; s < steps;) {
    const long long to = outputs.next(s);
    sim.advance(to - s);
    s = to;
    if (outputs.at(s, o.series_every)) o.sample();
    if (outputs.at(s, o.frame_every)) o.frame();
    if ((o.snapshot_every > 0 && outputs.at(s, o.snapshot_every)) || outputs.listed(s)) o.snapshot();
    if (s % o.series_every == 0 && clock.elapsed_seconds() - last_report > kReportEvery) {
      last_report = clock.elapsed_seconds();
      progress(o.report(s, last_report));
    }
  }
}

}  // namespace repro
