// Paper A against Paper B on the same collisions: the scenes and the
// criteria of the rows (A, B, B0 and the penalty baseline P).
#include <algorithm>
#include <cmath>

#include "repro/B_7_contact_comparison/penalty_baseline.hpp"

namespace compare {

double worst_energy_remainder(const std::vector<dda::cdem::CdemEnergyAccount>& rows) {
  double worst = 0.0;
  for (const dda::cdem::CdemEnergyAccount& a : rows)
    worst = std::max(worst, std::fabs(a.initial - (a.kinetic + a.strain + a.gravity + a.touch_loss + a.refine_loss +
                                                   a.deletion_loss)) /
                                a.initial);
  return worst;
}
std::vector<double> halving(double base, int count) {
  std::vector<double> v;
  for (int i = 0; i < count; ++i) v.push_back(std::ldexp(base, -i));
  return v;
}
std::vector<SceneDef> scene_defs(const Settings& set) {
  const dda::cdem::PrismGeometry pg;
  const int pd = set.prism_divisions, sd = set.square_divisions;
  return {
      {"prisms",
       pg.gap / pg.speed,
       pg.speed,
       0.8,
       [pg] { return dda::cdem::two_prisms_scene(pg); },
       [pg, pd](bool sub) {
         dda::cdem::CdemOptions o;
         o.subdivision = sub;
         o.subdivision_mode = dda::cdem::SubdivisionMode::kInPlace;  // B: the in-place refinement, explicitly
         return dda::cdem::two_prisms(pd, o, pg);
       },
       halving(set.prisms_dt, 5)},
      {"squares",
       0.5,
       1.0,
       1.0,
       [] { return dda::paper::two_squares(); },
       [sd](bool sub) {
         dda::cdem::CdemOptions o;
         o.subdivision = sub;
         o.subdivision_mode = dda::cdem::SubdivisionMode::kInPlace;  // B: the in-place refinement, explicitly
         return dda::cdem::two_squares(sd, o);
       },
       halving(set.squares_dt, 4)},
  };
}
double worst_of(const std::vector<Result>& v, double Result::*f) {
  double w = 0.0;
  for (const Result& r : v) w = std::max(w, std::fabs(r.*f));
  return w;
}
bool touch_ok(const std::vector<Result>& a, const std::vector<Result>& b, const std::vector<Result>& b0) {
  bool a_within_step = true;
  for (const Result& r : a) a_within_step = a_within_step && r.touch_err <= r.dt * (1.0 + 1e-6);
  return std::max(worst_of(b, &Result::touch_err), worst_of(b0, &Result::touch_err)) < 1e-12 && a_within_step;
}
bool momentum_ok(const std::vector<Result>& a, const std::vector<Result>& b, const std::vector<Result>& b0) {
  return std::max({worst_of(a, &Result::mom_err), worst_of(b, &Result::mom_err), worst_of(b0, &Result::mom_err)}) <
         1e-12;
}
bool exchange_ok(const Result& a0, const Result& b0) {
  return a0.vj_err_exchange < 1e-3 && b0.vj_err_exchange < 0.10;
}
bool energy_ok(const Result& a0, const Result& b0) {
  return std::fabs(a0.energy_err_end) < 1e-3 && std::fabs(a0.energy_err_end) < std::fabs(b0.energy_err_end);
}
bool prisms_duration_ok(const Result& a0, const Result& b0) {
  return std::fabs(b0.contact_end - b0.contact_start - 0.0072) < 0.002 &&
         a0.contact_end - a0.contact_start > 3.0 * (b0.contact_end - b0.contact_start);
}
double squares_wave_time() {
  const dda::Material mat = dda::paper::two_squares().materials.front();
  const double c = std::sqrt(mat.young / mat.density);
  return 2.0 * 1.0 / c;
}
bool squares_duration_ok(const Result& a0, const Result& b0, double t_ref) {
  const double da = a0.contact_end - a0.contact_start, db = b0.contact_end - b0.contact_start;
  return std::fabs(db - t_ref) < 0.25 * t_ref && std::fabs(da - t_ref) > std::fabs(db - t_ref);
}
bool kn_dependence_ok(const std::vector<KnRun>& runs, double v0) {
  bool ok = true;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const Result& r = runs[i].result;
    ok = ok && std::fabs(r.v_j - v0) < 1e-2 * v0 && r.mom_err < 1e-12;
    if (i > 0) {
      const Result& q = runs[i - 1].result;
      ok = ok && q.contact_end - q.contact_start > r.contact_end - r.contact_start;
    }
  }
  return ok;
}
dda::cdem::CdemScene penalty_scene(const SceneDef& def, double kn_factor) {
  dda::cdem::CdemScene s = def.cdem_scene(false);
  s.options.contact = dda::cdem::ContactMode::kNodeToEdgePenalty;
  s.options.subdivision = false;
  double young = 0.0;
  for (const dda::Material& m : s.materials) young = std::max(young, m.young);
  s.options.penalty_kn = kn_factor * young / 100.0;
  return s;
}
bool penalty_touch_ok(const std::vector<Result>& p, double t_exact) {
  bool ok = !p.empty();
  for (const Result& r : p) ok = ok && r.t_touch >= t_exact && r.t_touch - t_exact <= r.dt * (1.0 + 1e-6);
  return ok;
}
bool penalty_momentum_ok(const std::vector<Result>& p) {
  return !p.empty() && worst_of(p, &Result::mom_err) < 1e-12;
}
bool stability_prediction_ok(const StabilityProbe& p, double dt_predicted) {
  return p.dt_stable >= dt_predicted * (1.0 - 1e-12) && p.dt_unstable > 0.0 &&
         p.dt_unstable <= kStabilityMargin * dt_predicted;
}
}  // namespace compare
