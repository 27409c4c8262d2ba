// S1 work precision: every case at every dt, one monitored run for the
// errors and timed unmonitored runs for the cost (none with --timing-repeats
// 0: the monitored run's time then); the curves' observed
// orders (repro::stab::observed_order).
#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "dda/simulation.hpp"
#include "repro/S1_work_precision/work_precision.hpp"

namespace s1 {
namespace {
using repro::format_short;
// Timed runs per dt: 3, more for short runs where timer noise and the load
// of a shared machine weigh more (a median of 5 or 9).
int repeats_for(double seconds) { return seconds < 0.05 ? 9 : seconds < 0.2 ? 5 : 3; }

// What the wall_s/cpu_s columns are the median of.
std::string timing_words(const SweepOptions& o) {
  std::string w = o.max_repeats >= 9  ? "3 to 9 unmonitored runs (more for short runs)"
                  : o.max_repeats == 0 ? "the monitored run itself (no timed run: its observers' work included)"
                  : o.max_repeats == 1 ? "one unmonitored run"
                                       : "up to " + std::to_string(o.max_repeats) + " unmonitored runs";
  if (o.jobs > 1) w += ", " + std::to_string(o.jobs) + " cases at a time";
  return w;
}

// One case's runs: a monitored and a timed run per dt, and the reference.
struct CaseRuns {
  std::vector<RunOut> res;
  std::vector<repro::stab::Timing> times;
  RunOut ref;
  std::exception_ptr error;  // what the runs threw (rethrown in case order)
};

CaseRuns run_case(const Case& c, int max_repeats) {
  CaseRuns out;
  try {
    for (double dt : c.dts) {
      if (max_repeats == 0) {  // no timed run: the monitored run's own time, its observers included
        out.times.push_back(repro::stab::median_time(1, [&] { out.res.push_back(monitored_run(c, dt)); }));
        if (!out.res.back().ok) out.times.back() = repro::stab::Timing{};
        continue;
      }
      out.res.push_back(monitored_run(c, dt));
      out.times.push_back(out.res.back().ok ? timed_run(c.sc, dt, max_repeats) : repro::stab::Timing{});
    }
    // Reference run for the trajectory measures.
    if (!c.trajectory_windows.empty()) {
      out.ref = monitored_run(c, c.dts.front() / 16.0, false);
      if (!out.ref.ok)
        throw std::runtime_error(c.scene + ", " + c.option + ": reference run stopped: " + out.ref.message);
    }
  } catch (...) {
    out.error = std::current_exception();
  }
  return out;
}

// Every case's runs, `jobs` cases at a time (each case's runs on one thread
// in its own Simulations: nothing is shared), in case order.
std::vector<CaseRuns> run_cases(const std::vector<Case>& cases, const SweepOptions& options,
                                const repro::Progress& progress) {
  std::vector<CaseRuns> runs(cases.size());
  std::atomic<std::size_t> next{0};
  std::mutex progress_mutex;
  auto worker = [&] {
    for (std::size_t i = next++; i < cases.size(); i = next++) {
      runs[i] = run_case(cases[i], options.max_repeats);
      const std::lock_guard<std::mutex> lock(progress_mutex);
      progress(cases[i].scene + ", " + cases[i].option + ": done");
    }
  };
  const int jobs = std::max(1, std::min<int>(options.jobs, static_cast<int>(cases.size())));
  std::vector<std::thread> team;
  for (int j = 1; j < jobs; ++j) team.emplace_back(worker);
  worker();
  for (std::thread& t : team) t.join();
  return runs;
}
}  // namespace

// observe = false: the reference run (trajectory samples only).
RunOut monitored_run(const Case& c, double dt, bool observe) {
  RunOut r;
  dda::Scene s = c.sc;
  s.dt = dt;
  try {
    dda::Simulation sim(s);
    Observer obs = observe ? c.observer() : Observer{};
    obs.begin(sim);
    r.ratio0 = dt / sim.predicted_critical_step();
    r.ratio_max = dt / sim.critical_time_step();
    r.samples.push_back(repro::stab::vertex_state(sim));
    r.sample_times.push_back(0.0);
    const long per_sample = std::lround(c.sample_every / dt);
    const long total = std::lround(s.duration / dt);
    const long ratio_every = 1 + total / 20000;  // dt/dt_crit in contact: at most ~20000 evaluations
    for (long k = 1; k <= total; ++k) {
      sim.step();
      if (observe) obs.step(sim);
      if (k % ratio_every == 0 && sim.contact_count() > 0)
        r.ratio_max = std::max(r.ratio_max, dt / sim.critical_time_step());
      if (k % per_sample == 0) {
        r.samples.push_back(repro::stab::vertex_state(sim));
        r.sample_times.push_back(sim.time());
      }
    }
    if (observe) r.errors = obs.end(sim);
  } catch (const dda::SimulationError& e) {
    r.ok = false;
    r.message = e.what();
  }
  return r;
}

repro::stab::Timing timed_run(const dda::Scene& sc, double dt, int max_repeats) {
  dda::Scene s = sc;
  s.dt = dt;
  auto run = [&] {
    dda::Simulation sim(s);
    const long total = std::lround(s.duration / dt);
    for (long k = 0; k < total; ++k) sim.step();
  };
  const repro::stab::Timing first = repro::stab::median_time(1, run);
  const int repeats = std::min(repeats_for(first.wall), max_repeats);
  return repeats <= 1 ? first : repro::stab::median_time(repeats, run);
}

std::vector<CurveSummary> sweep(const std::vector<Case>& cases, const std::string& dir, References& references,
                                const repro::Progress& progress, const SweepOptions& options) {
  const std::vector<CaseRuns> case_runs = run_cases(cases, options, progress);
  repro::TableWriter<RunRow> runs(dir + "/runs.csv", kRunColumns,
                                  {"S1 work precision: error (relative, or m where the measure says so) against the "
                                   "median wall time (steady_clock) and CPU time of " + timing_words(options) +
                                   "; empty error: the run stopped (status says why)"});
  std::vector<CurveSummary> curves;
  for (std::size_t ci = 0; ci < cases.size(); ++ci) {
    const Case& c = cases[ci];
    if (case_runs[ci].error) std::rethrow_exception(case_runs[ci].error);
    const std::vector<RunOut>& res = case_runs[ci].res;
    const std::vector<repro::stab::Timing>& times = case_runs[ci].times;
    const RunOut& ref = case_runs[ci].ref;
    if (!c.trajectory_windows.empty()) references.push_back({c.scene + " | " + c.option, ref.samples});
    // Errors per measure.
    std::vector<std::string> names;
    std::vector<std::string> refs;
    std::vector<double> floors;
    for (const Measure& m : c.measures) {
      names.push_back(m.name);
      refs.push_back(m.reference);
      floors.push_back(m.floor);
    }
    for (const std::string& n : c.trajectory_names) {
      names.push_back(n + " (m)");
      refs.push_back("converged run at dt = " + format_short(c.dts.front() / 16.0) + " s");
      floors.push_back(1e-12);
    }
    const std::size_t nm = names.size();
    std::vector<std::vector<double>> err(nm, std::vector<double>(c.dts.size(), -1.0));
    for (std::size_t k = 0; k < c.dts.size(); ++k) {
      const RunOut& r = res[k];
      if (!r.ok) continue;
      for (std::size_t m = 0; m < c.measures.size(); ++m) err[m][k] = r.errors[m];
      for (std::size_t w = 0; w < c.trajectory_windows.size(); ++w) {
        double e = 0.0;
        // Samples of this run at the reference's times (both every sample_every).
        for (std::size_t s = 0; s < r.samples.size(); ++s) {
          if (r.sample_times[s] > c.trajectory_windows[w] + 1e-9) break;
          if (std::fabs(ref.sample_times[s] - r.sample_times[s]) > 1e-9)
            throw std::runtime_error("sample times differ: " + c.scene);
          e = std::max(e, repro::stab::max_abs_difference(r.samples[s], ref.samples[s]));
        }
        err[c.measures.size() + w][k] = e;
      }
    }
    for (std::size_t m = 0; m < nm; ++m) {
      CurveSummary cs;
      cs.scene = c.scene;
      cs.option = c.option;
      cs.measure = names[m];
      cs.reference = refs[m];
      cs.order = repro::stab::observed_order(c.dts, err[m], floors[m]);
      cs.order_all = repro::stab::observed_order(c.dts, err[m], floors[m], 100);
      for (std::size_t k = 0; k < c.dts.size(); ++k) {
        const RunOut& r = res[k];
        double local = std::numeric_limits<double>::quiet_NaN();
        if (k > 0 && err[m][k] > floors[m] && err[m][k - 1] > floors[m])
          local = std::log(err[m][k] / err[m][k - 1]) / std::log(c.dts[k] / c.dts[k - 1]);
        runs.row({c, names[m], c.dts[k], r, times[k], err[m][k], local});
        if (std::fabs(c.dts[k] - c.paper_dt) < 1e-12 * c.paper_dt) {
          cs.error_at_paper = r.ok ? err[m][k] : -1.0;
          cs.wall_at_paper = r.ok ? times[k].wall : -1.0;
          cs.cpu_at_paper = r.ok ? times[k].cpu : -1.0;
          cs.ratio_at_paper = r.ratio0;
        }
        if (r.ok) {
          cs.largest_stable_ratio = std::max(cs.largest_stable_ratio, r.ratio0);
          cs.max_error = std::max(cs.max_error, err[m][k]);
        }
        if (!r.ok && cs.first_failure.empty()) cs.first_failure = r.message;
      }
      curves.push_back(cs);
    }
  }
  runs.commit();

  repro::write_table(dir + "/orders.csv", kOrderColumns, curves);
  return curves;
}

}  // namespace s1
