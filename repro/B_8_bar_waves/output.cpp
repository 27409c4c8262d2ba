// Two elastic bars head on: the data files, runs.csv (one row per run) and
// traces.csv (contact stress against time after the touch), each declared as
// a column table.
#include "repro/B_8_bar_waves/output.hpp"

#include "repro/common/common.hpp"
#include "repro/common/table.hpp"

namespace bars {
namespace {

// A column of a run's measured value: empty for a stopped run (no data).
repro::Column<Run> measured(const char* name, double Run::*field) {
  return {name, [field](const Run& r) { return repro::cell_if(r.ok(), r.*field); }};
}

const std::vector<repro::Column<Run>> kRunColumns = {
    repro::field("model", &Run::model),
    repro::field("series", &Run::series),
    repro::field("ny", &Run::ny),
    repro::field("h", &Run::h),
    repro::field("dt", &Run::dt),
    repro::field("kn", &Run::kn),
    repro::field("wall_s", &Run::wall),
    repro::field("steps", &Run::steps),
    repro::field("critical_dt", &Run::critical_dt),
    {"status", [](const Run& r) { return r.ok() ? "ok" : "stopped: " + r.stopped; }},
    measured("t_touch", &Run::t_touch),
    measured("t_end", &Run::t_end),
    measured("duration", &Run::duration),
    measured("duration_err", &Run::duration_err),
    measured("mean_stress", &Run::mean_stress),
    measured("stress_err", &Run::stress_err),
    measured("plateau_stress", &Run::plateau_stress),
    measured("plateau_err", &Run::plateau_err),
    measured("v0", &Run::v0),
    measured("v1", &Run::v1),
    measured("exchange_err", &Run::exchange_err),
    measured("energy_end", &Run::energy_end),
    repro::field("energy_growth", &Run::energy_growth),
    repro::field("momentum_err", &Run::momentum_err),
    repro::field("touches", &Run::touches),
    repro::field("separations", &Run::separations)};

// One sample of a trace: its label, time after the touch and stress.
struct TraceSample {
  std::string label;
  double time, stress;
};
const std::vector<repro::Column<TraceSample>> kTraceColumns = {
    {"run", [](const TraceSample& t) { return t.label; }},
    {"time_after_touch", [](const TraceSample& t) { return t.time; }},
    {"stress", [](const TraceSample& t) { return t.stress; }}};

}  // namespace

void write_runs(const std::string& dir, const Setup& s, const Study& study) {
  const double E = s.material.young;
  const std::vector<Run>& runs = study.runs;
  repro::write_table(
      dir + "runs.csv", kRunColumns, runs,
      {"two bars L " + format_short(s.length) + " m x W " + format_short(s.width) + " m, v " + format_short(s.speed) +
           " m/s onto a bar at rest; rho " + format_short(s.material.density) + ", E " + format_short(E) +
           " Pa, nu 0 (plane stress); 2L/c " + repro::format_full(s.contact_time()) + " s, rho c v/2 " +
           repro::format_full(s.contact_stress()) + " Pa. B: clone + subdivision; B0: clone, no subdivision; A: "
           "Paper A DDA penalty. errors signed, relative to 1D theory; status 'stopped: ...' has no values. "
           "wall_s: mean of repeated runs when one is shorter than 0.05 s",
       // the mode cdem_scene() sets for B (the figure labels B's curves with it)
       "subdivision mode of B: in-place refinement (beyond the paper)"});
  std::vector<TraceSample> samples;
  for (const auto& [name, tr] : study.traces) {
    const Run* src = nullptr;
    for (const Run& r : runs)
      if (r.ok() && (name == "A kn=E" ? (r.series == "kn" && r.kn == E)
                                       : name == "A" ? (r.model == "A" && r.series == "dt" && r.dt == kDdaDt[2])
                                                     : (r.model == name && r.series == "mesh")))
        src = &r;
    if (!src) continue;
    const std::string label = name == "A" ? "A kn=E/100 dt=" + format_short(src->dt)
                              : name == "A kn=E" ? "A kn=E dt=" + format_short(src->dt)
                                                 : name + " ny=" + std::to_string(src->ny);
    for (std::size_t k = 0; k < tr.t.size(); ++k) samples.push_back({label, tr.t[k] - src->t_touch, tr.stress[k]});
  }
  repro::write_table(dir + "traces.csv", kTraceColumns, samples,
                     {"contact stress (the target's momentum change over each step / W, Pa) against the time after "
                      "the first touch; B, B0: finest completed mesh of the mesh series; A: kn = E/100 and kn = E"});
}

}  // namespace bars
