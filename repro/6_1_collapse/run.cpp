// Paper A Sect. 6.1: one case's run with its measures and output files, and
// the renumbered reruns (collapse.hpp).
#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "dda/polygon.hpp"
#include "repro/6_1_collapse/collapse.hpp"
#include "repro/common/common.hpp"
#include "repro/common/rock_run.hpp"
#include "repro/common/vtk_output.hpp"

namespace collapse61 {
namespace {
using repro::format_short;

// The rock's start (centroids and total mass) and the geometric measures
// of a state against it: front, mean drop, travel, runout mass (a Sample
// without its energies).
struct Start {
  std::vector<dda::Vec2> c0;
  double mass = 0.0;
  explicit Start(const dda::Simulation& sim) {
    for (int i = 0; i < sim.scene_block_count(); ++i) {
      c0.push_back(sim.centroid(i));
      mass += sim.mass(i);
    }
  }
  Sample measure(const dda::Simulation& sim, double column_width) const {
    Sample s;
    s.t = sim.time();
    s.front_x = -1e300;
    s.front_cx = -1e300;
    double drop = 0.0, out = 0.0;
    for (int i = 0; i < sim.scene_block_count(); ++i) {
      const dda::Polygon& p = sim.polygon(i);
      for (int v = 0; v < p.count; ++v) s.front_x = std::max(s.front_x, p.vertex(v).x);
      const dda::Vec2 c = sim.centroid(i), start = c0[static_cast<std::size_t>(i)];
      s.front_cx = std::max(s.front_cx, c.x);
      drop += sim.mass(i) * (start.y - c.y);
      s.max_travel = std::max(s.max_travel, dda::length(c - start));
      if (c.x > column_width) out += sim.mass(i);
    }
    s.mean_drop = drop / mass;
    s.runout_mass = out / mass;
    return s;
  }
};

// The output files of one case (run_case with a directory): series.csv
// every kSeriesEvery, frames.csv and blocks.csv every kFrameEvery.
struct Files {
  repro::TableWriter<Sample> series;
  repro::FrameFiles frames;
  Files(const std::string& cdir, const std::string& note)
      : series(cdir + "/series.csv",
               {repro::field("time", &Sample::t), repro::field("front_x", &Sample::front_x),
                repro::field("front_cx", &Sample::front_cx), repro::field("mean_drop", &Sample::mean_drop),
                repro::field("max_travel", &Sample::max_travel), repro::field("runout_mass", &Sample::runout_mass),
                repro::field("E_kinetic", &Sample::kinetic), repro::field("E_gravity", &Sample::gravity),
                repro::field("E_total", &Sample::total), repro::field("dt_over_dt_crit", &Sample::dt_ratio)},
               {note}),
        frames(cdir, note) {}
};

}  // namespace

const Sample& CaseResult::at(double t) const {
  const Sample* best = &series.front();
  for (const Sample& s : series)
    if (std::fabs(s.t - t) < std::fabs(best->t - t)) best = &s;
  return *best;
}

CaseResult run_case(int k, const dda::paper::Collapse& col, int threads, const std::string& dir) {
  const double friction = col.scene.contact.friction_deg, duration = col.scene.duration;
  const repro::Progress progress("6.1 collapse case " + std::to_string(k));
  dda::Simulation sim(col.scene);
  sim.set_threads(threads);
  const int n = sim.scene_block_count();
  CaseResult r;
  r.index = k;
  r.friction = friction;
  r.blocks = n;
  r.dropped = col.dropped;
  r.dropped_area = col.dropped_area;
  r.region_area = col.width * col.height;
  r.h = sim.potential_length(0);
  r.dt = sim.dt();
  r.dt_ratio0 = sim.dt() / sim.predicted_critical_step();
  r.duration = duration;
  progress(std::to_string(n) + " blocks (" + std::to_string(col.dropped) + " slivers dropped, " +
           format_short(col.dropped_area, 3) + " m^2), H = " + format_short(r.h, 4) +
           " m, dt/dt_crit = " + format_short(r.dt_ratio0, 3) + " at start, " + std::to_string(threads) +
           " thread(s)");

  const Start start(sim);
  const std::string cdir = dir + "/case" + std::to_string(k);
  const std::string note = "Paper A Sect. 6.1, geometry reconstructed (Fig. 19 lost); joint friction " +
                           format_short(friction, 3) + " deg, boundary 35 deg";
  std::unique_ptr<Files> files;
  if (!dir.empty()) files = std::make_unique<Files>(cdir, note);

  repro::RunOutputs outputs;
  outputs.sample = [&] {
    Sample s = start.measure(sim, col.width);
    const dda::Energy e = sim.energy();
    s.kinetic = e.kinetic;
    s.gravity = e.gravity;
    s.total = e.total();
    s.dt_ratio = sim.dt() / sim.critical_time_step();
    r.dt_ratio_max = std::max(r.dt_ratio_max, s.dt_ratio);
    if (files) files->series.row(s);
    r.series.push_back(s);
  };
  outputs.frame = [&] {
    if (files) files->frames.write(sim);
  };
  outputs.snapshot = [&] {
    if (!files) return;
    repro::write_vtk_polydata(dir + "/vtk/case" + std::to_string(k) + "_t" + time_tag(sim.time()) + ".vtk", sim,
                              "Paper A 6.1 collapse case " + std::to_string(k) + " (joint friction " +
                                  format_short(friction, 3) + " deg) t = " + time_tag(sim.time()) + " s",
                              true);
  };
  outputs.report = [&](long long s, double elapsed) {
    const Sample& x = r.series.back();
    return "t = " + format_short(sim.time(), 3) + " of " + format_short(duration, 3) + " s, " +
           format_short(static_cast<double>(s) / elapsed, 4) + " steps/s, front " + format_short(x.front_x, 4) +
           " m, mean drop " + format_short(x.mean_drop, 3) + " m";
  };

  const auto steps = static_cast<long long>(std::llround(duration / sim.dt()));
  outputs.series_every = std::max(1LL, static_cast<long long>(std::llround(kSeriesEvery / sim.dt())));
  outputs.frame_every = std::max(1LL, static_cast<long long>(std::llround(kFrameEvery / sim.dt())));
  outputs.snapshot_steps = {0};
  for (double t : kPaperTimes)
    if (t <= duration + 0.5 * sim.dt()) outputs.snapshot_steps.push_back(std::llround(t / sim.dt()));
  outputs.sample();
  outputs.frame();
  outputs.snapshot();
  const repro::Progress clock("");
  try {
    repro::run_with_outputs(sim, steps, outputs, progress, clock);
  } catch (const dda::SimulationError& e) {
    r.stopped = e.what();  // the series ends at the last sample before the stop
    progress("stopped by a stability guard: " + r.stopped);
  }
  r.wall = clock.elapsed_seconds();
  r.steps = sim.step_count();
  if (files) {
    files->series.commit();
    files->frames.commit();
  }
  progress("done: " + std::to_string(r.steps) + " steps in " + format_short(r.wall, 4) + " s (" +
           format_short(static_cast<double>(r.steps) / r.wall, 4) + " steps/s), front " +
           format_short(r.series.back().front_x, 4) + " m");
  return r;
}

Sample rerun_renumbered(int k, dda::paper::Collapse col, int threads, int axis) {
  const double duration = col.scene.duration;
  std::vector<std::pair<double, dda::BlockSpec>> keyed;
  for (dda::BlockSpec& b : col.scene.blocks) {
    const dda::Vec2 c = dda::area_centroid(b.vertices.data(), static_cast<int>(b.vertices.size())).centroid;
    keyed.emplace_back(axis == 0 ? c.x : c.y, std::move(b));
  }
  std::stable_sort(keyed.begin(), keyed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (std::size_t i = 0; i < keyed.size(); ++i) col.scene.blocks[i] = std::move(keyed[i].second);
  dda::Simulation sim(col.scene);
  sim.set_threads(threads);
  const Start start(sim);
  const repro::Progress progress("6.1 collapse case " + std::to_string(k) + ", blocks numbered by " +
                                 kNumberings[axis + 1]);
  const auto steps = static_cast<long long>(std::llround(duration / sim.dt()));
  const long long chunk = static_cast<long long>(std::llround(1.0 / sim.dt()));  // progress every simulated second
  for (long long s = 0; s < steps; s += chunk) {
    sim.advance(std::min(chunk, steps - s));
    progress("t = " + format_short(sim.time(), 3) + " of " + format_short(duration, 3) + " s");
  }
  const Sample end = start.measure(sim, col.width);
  progress("done: front " + format_short(end.front_x, 4) + " m");
  return end;
}

}  // namespace collapse61
