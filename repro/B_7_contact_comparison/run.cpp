// Paper A against Paper B on the same collisions: the runs of the four
// models (A, B, B0, P) through one loop over dda::Stepper, the dt sweeps,
// A's kn sweep and P's stability probe.
#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "dda/cdem/stepper.hpp"
#include "dda/stepper.hpp"
#include "repro/B_7_contact_comparison/penalty_baseline.hpp"

namespace compare {
namespace {

// Runs `body` repeatedly until 0.2 s of wall time have passed (at most 20
// times) and returns the mean time of one run: single runs of the cheap
// configurations are too short to time.
template <class F>
double timed(F body) {
  double total = 0.0;
  int n = 0;
  while (n < 20 && (n == 0 || total < 0.2)) {
    const auto a = std::chrono::steady_clock::now();
    body(n == 0);
    total += std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
    ++n;
  }
  return total / n;
}

// What the loop watches beyond momentum, energy and the block velocities.
struct Watch {
  // A, P: the contact lasts from the first to the last step end with a
  // contact (penalty pairs or springs); B, B0 take it from their touches.
  bool contact_steps = false;
  // B, B0, P: the energy error at every step; A: at the history rows and in
  // contact only (its energy() integrates the contact energy).
  bool energy_every_step = true;
  // Called at each history row (B, B0: the energy account).
  std::function<void(History&)> record;
};

// One model run to def.duration at dt: momentum error at every step, the
// energy error, the contact steps, the history every 2e-4 s (recorded run
// only: `first`), the end state. The model-specific rest is the caller's.
Result watch(dda::Stepper& m, const SceneDef& def, double dt, History* hist, bool first, Result q, const Watch& w) {
  const double p0 = m.momentum().x, e0 = m.energy().total();
  long k = 0;
  const long every = std::max(1L, std::lround(2e-4 / dt));
  while (m.time() < def.duration - 0.5 * dt) {
    m.step();
    ++k;
    q.mom_err = std::max(q.mom_err, std::fabs(m.momentum().x - p0) / std::fabs(p0));
    const bool contact = w.contact_steps && m.contact_count() > 0;
    if (contact) {
      if (q.contact_start < 0.0) q.contact_start = m.time();
      q.contact_end = m.time();
    }
    if (first) {
      if (w.energy_every_step || k % every == 0 || contact)
        q.energy_err_max = std::max(q.energy_err_max, std::fabs(m.energy().total() - e0) / e0);
      if (hist && k % every == 0) {
        hist->t.push_back(m.time());
        hist->vi.push_back(m.block_motion(0).velocity.x);
        hist->vj.push_back(m.block_motion(1).velocity.x);
        if (w.record) w.record(*hist);
      }
    }
  }
  if (first) {
    q.energy_err_end = (m.energy().total() - e0) / e0;
    q.v_i = m.block_motion(0).velocity.x;
    q.v_j = m.block_motion(1).velocity.x;
    q.steps = k;
  }
  return q;
}

Result start(const SceneDef& def, const char* model, double dt) {
  Result r;
  r.scene = def.name;
  r.model = model;
  r.dt = dt;
  return r;
}

// The scene's errors against its reference (touch time, exchange) and, for
// the sweep, against its smallest dt.
std::vector<Result> sweep(const SceneDef& def, History* hist, bool base_only,
                          const std::function<Result(double, History*)>& run) {
  std::vector<Result> out;
  const std::size_t n = base_only ? 1 : def.dts.size();
  for (std::size_t i = 0; i < n; ++i) {
    Result r = run(def.dts[i], i == 0 ? hist : nullptr);
    r.touch_err = std::fabs(r.t_touch - def.t_touch_exact);
    r.vj_err_exchange = std::fabs(r.v_j - def.v0) / def.v0;
    out.push_back(r);
  }
  for (Result& r : out) r.vj_err_self = std::fabs(r.v_j - out.back().v_j) / def.v0;
  return out;
}

}  // namespace

Result run_dda(const SceneDef& def, double dt, History* hist) {
  Result r = start(def, "A", dt);
  r.wall = timed([&](bool first) {
    dda::Scene s = def.dda_scene();
    s.dt = dt;
    s.duration = def.duration;
    dda::SimulationStepper m{dda::Simulation(s)};
    Watch w;
    w.contact_steps = true;
    w.energy_every_step = false;
    const Result q = watch(m, def, dt, hist, first, r, w);
    // The penalty contact acts from the first step end with an overlap.
    if (first) {
      r = q;
      r.t_touch = q.contact_start;
    }
  });
  return r;
}

Result run_cdem(const SceneDef& def, bool subdivision, double dt, History* hist) {
  Result r = start(def, subdivision ? "B" : "B0", dt);
  r.wall = timed([&](bool first) {
    dda::cdem::CdemScene s = def.cdem_scene(subdivision);
    s.dt = dt;
    s.duration = def.duration;
    dda::cdem::ModelStepper st{dda::cdem::Model(s)};
    const dda::cdem::Model& m = st.model();
    Watch w;
    w.record = [&](History& h) { h.accounts.push_back(m.energy_account()); };
    const Result q = watch(st, def, dt, hist, first, r, w);
    if (first) {
      if (m.touches().empty()) throw std::runtime_error("B-7: CDEM run without a touch");
      r = q;
      r.t_touch = m.touches().front().time;
      r.contact_start = r.t_touch;
      r.contact_end = m.separations().empty() ? def.duration : m.separations().back().time;
    }
  });
  return r;
}

Result run_penalty(const SceneDef& def, double dt, History* hist) {
  Result r = start(def, "P", dt);
  r.wall = timed([&](bool first) {
    dda::cdem::CdemScene s = penalty_scene(def);
    s.dt = dt;
    s.duration = def.duration;
    dda::cdem::ModelStepper m{dda::cdem::Model(s)};
    Watch w;
    w.contact_steps = true;
    const Result q = watch(m, def, dt, hist, first, r, w);
    if (first) {
      if (q.contact_start < 0.0) throw std::runtime_error("B-7: penalty run without a contact");
      r = q;
      r.t_touch = q.contact_start;
    }
  });
  return r;
}

std::vector<Result> run_sweep(const SceneDef& def, const std::string& model, History* hist, bool base_only) {
  return sweep(def, hist, base_only, [&](double dt, History* h) {
    return model == "A" ? run_dda(def, dt, h) : run_cdem(def, model == "B", dt, h);
  });
}

std::vector<Result> penalty_sweep(const SceneDef& def, History* hist, bool base_only) {
  return sweep(def, hist, base_only, [&](double dt, History* h) { return run_penalty(def, dt, h); });
}

std::vector<KnRun> kn_sweep(const SceneDef& def, const std::vector<double>& factors) {
  std::vector<KnRun> runs;
  for (double factor : factors) {
    SceneDef d = def;
    d.dda_scene = [def, factor] {
      dda::Scene s = def.dda_scene();
      s.contact.kn *= factor;
      return s;
    };
    runs.push_back({factor, run_dda(d, def.dts.front(), nullptr)});
  }
  return runs;
}
StabilityProbe probe_stability(const SceneDef& def, double kn_factor, double after) {
  StabilityProbe p;
  p.kn_factor = kn_factor;
  const auto a = std::chrono::steady_clock::now();
  {
    dda::cdem::CdemScene s = penalty_scene(def, kn_factor);
    s.options.check_stability = false;  // the prediction only
    const dda::cdem::Model m(s);
    p.kn = m.penalty_kn();
    p.dt_mesh = m.critical_dt();
    p.dt_pred = m.contact_critical_dt();
  }
  const double t_end = def.t_touch_exact + after;
  for (double f : kStabilityLadder) {
    dda::cdem::CdemScene s = penalty_scene(def, kn_factor);
    s.options.check_stability = false;
    s.dt = f * p.dt_pred;
    s.duration = t_end;
    std::string why;
    try {
      dda::cdem::Model m(s);
      const double e0 = m.energy().total();
      while (why.empty() && m.time() < t_end - 0.5 * s.dt) {
        m.step();
        const double e = m.energy().total();
        if (!(std::fabs(e - e0) <= kBlowUpEnergy * e0))
          why = "energy " + format_short(e / e0, 3) + " x E0 at t = " + format_short(m.time(), 5) + " s";
      }
    } catch (const dda::SimulationError& e) {
      why = e.what();
    }
    if (!why.empty()) {
      p.dt_unstable = s.dt;
      p.failure = why;
      break;
    }
    p.dt_stable = s.dt;
  }
  p.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
  return p;
}
}  // namespace compare
