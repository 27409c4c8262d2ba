// Coulomb friction with stick/slide history (Paper A Sect. 3.2.5-3.2.6,
// Eqs. 24-26), per pair in contact. Included by the pair loop
// (contact_forces.cpp), its only caller, and inlined there: a call frame
// of its own, with its arguments passed through the stack, costs about 30
// instructions per contact, a fifth of the update itself.
#pragma once

#include "block_lanes.hpp"
#include "simulation/internal.hpp"

namespace dda {

inline double Engine::friction_tan(int a, int b) const {
  return friction_tan_table_[static_cast<std::size_t>(group_[a] * group_count_ + group_[b])];
}

[[gnu::always_inline]] inline void Engine::pair_friction(int cp, int tp, PairResult& r, PairHistory& hist,
                                                        double& friction_work, bool was_active, Vec2 last_point,
                                                        Vec2 last_ft, const NormalForce& nf) {
  // Coulomb friction with stick/slide history, Eqs. 24-26, on pair (cp,
  // tp); sets r's tangential force. A pair that was not in contact at the
  // last step starts afresh. last_point, last_ft: pg and the tangential
  // force on CP of the pair's last evaluation (read only when was_active).
  const ContactParams& c = scene_.contact;
  Vec2 step_d{};   // this step's Delta d (none for a fresh contact)
  Vec2 ft_last{};  // the last step's f_t (none for a fresh contact)
  if (was_active) {
    // Sect. 3.2.6: Delta d = Delta u_g(CP) - Delta u_g(TP) at the last pg;
    // a sticking pair accumulates it, a sliding pair restarts from it
    // (kPaper) or, with the return mapping, accumulates it onto the shear
    // it was returned to (below). The centroids are those of the step's
    // start configuration.
    using detail::Lanes;
    const Lanes pg = detail::lanes(last_point);
    const auto du = [&](int b) {
      return fixed_[b] ? Lanes{0.0, 0.0}
                       : detail::point_displacement_lanes(detail::lanes(start_centroid_[b]), pg, step_disp_[b]);
    };
    const Lanes dd = du(cp) - du(tp);
    step_d = detail::vec2(dd);
    const bool restart = c.friction_update == FrictionUpdate::kPaper;
    hist.d = detail::vec2(hist.sliding && restart ? dd : detail::lanes(hist.d) + dd);
    ft_last = last_ft;
  } else {
    hist = PairHistory{};
    hist.friction_tan = friction_tan(cp, tp);
  }
  const double fn = length(nf.force);
  const Vec2 ng = nf.force / fn;
  const Vec2 dtan = hist.d - dot(hist.d, ng) * ng;
  const double lt = length(dtan);
  const Vec2 s = lt > 0.0 ? dtan / lt : Vec2{};
  const double limit = fn * hist.friction_tan;
  Vec2 ft{};
  if (c.friction_update == FrictionUpdate::kReturnMapping) {
    // Elastic-plastic Coulomb (not the paper's Eq. 26, see FrictionUpdate):
    // Eq. 25 from either state; sliding returns d_tan onto the limit,
    // d_tan = -f_t / kt, so the spring keeps the shear it carries.
    if (c.kt * lt < limit) {
      ft = -c.kt * dtan;
      hist.sliding = false;
    } else {
      ft = -limit * s;
      hist.sliding = true;
      hist.d += (limit / c.kt) * s - dtan;
    }
  } else if (!hist.sliding) {
    if (c.kt * lt < limit) {
      ft = -c.kt * dtan;
    } else {
      ft = -limit * s;
      hist.sliding = true;
    }
  } else if (limit <= 0.0 || dot(hist.slide_dir, dtan) > 0.0) {
    // Eq. 26 keeps sliding while f_t(n-1) . d_tan < 0. With f_t(n-1) =
    // -limit s(n-1) that is s(n-1) . d_tan > 0, the form used here: it
    // stays defined when the limit is zero (phi = 0), where the literal
    // test would stick every other step: a zero limit keeps sliding with
    // zero force (it has no sliding direction yet when it started at rest).
    ft = -limit * s;
  } else {
    ft = -c.kt * dtan;
    hist.sliding = false;
  }
  if (hist.sliding && lt > 0.0) hist.slide_dir = s;
  // The friction work of the step (the energy budget, energy.cpp): ft on
  // CP and -ft on TP do ft . Delta d on the blocks, taken by the trapezoid
  // rule, as velocity Verlet's kinetic energy takes the work of every force
  // (it changes by 1/2 (F^n + F^{n+1}) . Delta x per step, up to O(h^3)).
  friction_work -= 0.5 * dot(ft_last + ft, step_d);
  r.tangential_force = ft;
}

}  // namespace dda
