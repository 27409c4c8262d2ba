// Two elastic bars head on: the study's series of runs (the CDEM mesh and
// dt series, Paper A's dt and kn series) and the traces of one run per model.
#include "repro/B_8_bar_waves/bar_waves.hpp"

namespace bars {
namespace {

// A run timed again when it is too short to time once: the mean wall time
// of repeats until 0.2 s have passed (at most 20 runs).
template <class F>
Run timed(F run) {
  Run r = run();
  if (r.wall >= 0.05) return r;
  double total = r.wall;
  int n = 1;
  while (n < 20 && total < 0.2) {
    total += run().wall;
    ++n;
  }
  r.wall = total / n;
  return r;
}

}  // namespace

Study run_study(const Setup& s, int max_ny, const std::function<void(const Run&)>& note) {
  const double E = s.material.young;
  Study study;
  // A run of the series, timed; `run` fills the trace `tr` (recorded anew at each repeat).
  auto add = [&](const char* series, Trace& tr, const std::function<Run(Trace*)>& run) {
    Run r = timed([&] {
      tr = Trace{};
      return run(&tr);
    });
    r.series = series;
    study.runs.push_back(r);
    note(r);
    return r;
  };
  // Mesh series, dt = kCourant h / c; the trace of each CDEM model on its
  // finest completed mesh (kept as the series goes).
  for (const bool sub : {false, true})
    for (int ny : kMeshNy) {
      if (ny > max_ny) continue;
      Trace tr;
      const Run r = add("mesh", tr, [&](Trace* t) { return run_cdem(s, ny, 0.0, sub, t); });
      if (r.ok()) study.traces[r.model] = tr;
    }
  // dt series on one mesh (its first point is the mesh series' run).
  for (const bool sub : {false, true})
    for (double courant : kDtSweepCourant) {
      if (kDtSweepNy > max_ny) continue;
      const double dt = courant * (s.width / kDtSweepNy) / s.wave_speed();
      Trace unused;
      add("dt", unused, [&](Trace*) { return run_cdem(s, kDtSweepNy, dt, sub); });
    }
  // Paper A: dt series at kn = E / 100, kn series at the smallest dt.
  for (double dt : kDdaDt) {
    Trace tr;
    add("dt", tr, [&](Trace* t) { return run_dda(s, dt, 0.01 * E, t); });
    if (dt == kDdaDt[2]) study.traces["A"] = tr;
  }
  for (double f : kKnFactors) {
    Trace tr;
    add("kn", tr, [&](Trace* t) { return run_dda(s, kDdaDt[3], f * E, t); });
    if (f == 1.0) study.traces["A kn=E"] = tr;
  }
  return study;
}

}  // namespace bars
