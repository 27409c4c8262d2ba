// Two elastic bars head on: the data files, runs.csv (one row per run) and
// traces.csv (contact stress against time after the touch).
#include "repro/B_8_bar_waves/output.hpp"

#include "repro/common/common.hpp"

namespace bars {
namespace {
std::string num(const Run& r, double v) { return r.ok() ? repro::format_full(v) : std::string(); }
}  // namespace

void write_runs(const std::string& dir, const Setup& s, const Study& study) {
  const double E = s.material.young;
  const std::vector<Run>& runs = study.runs;
  const std::map<std::string, Trace>& traces = study.traces;
  repro::CsvWriter csv(
      dir + "runs.csv",
      {"model", "series", "ny", "h", "dt", "kn", "wall_s", "steps", "critical_dt", "status", "t_touch", "t_end",
       "duration", "duration_err", "mean_stress", "stress_err", "plateau_stress", "plateau_err", "v0", "v1",
       "exchange_err", "energy_end", "energy_growth", "momentum_err", "touches", "separations"},
      {"two bars L " + format_short(s.length) + " m x W " + format_short(s.width) + " m, v " + format_short(s.speed) +
       " m/s onto a bar at rest; rho " + format_short(s.material.density) + ", E " + format_short(E) +
       " Pa, nu 0 (plane stress); 2L/c " + repro::format_full(s.contact_time()) + " s, rho c v/2 " +
       repro::format_full(s.contact_stress()) + " Pa. B: clone + subdivision; B0: clone, no subdivision; A: "
       "Paper A DDA penalty. errors signed, relative to 1D theory; status 'stopped: ...' has no values. "
       "wall_s: mean of repeated runs when one is shorter than 0.05 s",
       // the mode cdem_scene() sets for B (the figure labels B's curves with it)
       "subdivision mode of B: in-place refinement (beyond the paper)"});
  for (const Run& r : runs)
    csv.row(std::vector<std::string>{
        r.model, r.series, std::to_string(r.ny), repro::format_full(r.h), repro::format_full(r.dt),
        repro::format_full(r.kn), repro::format_full(r.wall), std::to_string(r.steps), repro::format_full(r.critical_dt),
        r.ok() ? "ok" : "stopped: " + r.stopped, num(r, r.t_touch), num(r, r.t_end), num(r, r.duration),
        num(r, r.duration_err), num(r, r.mean_stress), num(r, r.stress_err), num(r, r.plateau_stress),
        num(r, r.plateau_err), num(r, r.v0), num(r, r.v1), num(r, r.exchange_err), num(r, r.energy_end),
        repro::format_full(r.energy_growth), repro::format_full(r.momentum_err), std::to_string(r.touches),
        std::to_string(r.separations)});
  csv.commit();
  repro::CsvWriter tcsv(dir + "traces.csv", {"run", "time_after_touch", "stress"},
                        {"contact stress (the target's momentum change over each step / W, Pa) against the time "
                         "after the first touch; B, B0: finest completed mesh of the mesh series; A: kn = E/100 and "
                         "kn = E"});
  for (const auto& [name, tr] : traces) {
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
    for (std::size_t k = 0; k < tr.t.size(); ++k)
      tcsv.row(std::vector<std::string>{label, repro::format_full(tr.t[k] - src->t_touch),
                                        repro::format_full(tr.stress[k])});
  }
  tcsv.commit();

}

}  // namespace bars
