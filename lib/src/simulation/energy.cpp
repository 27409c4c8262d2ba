// Energy and momentum of the state: kinetic, gravity and strain energy of
// the free blocks, the penalty energy stored in the contacts' overlaps, the
// friction springs' energy and the work friction dissipated (the budget).
#include "simulation/internal.hpp"

namespace dda {

Vec2 Engine::momentum() const {
  Vec2 p{};
  for (int i = 0; i < block_count(); ++i)
    if (!fixed_[i]) p += mass_[i] * Vec2{vel_[i][0], vel_[i][1]};
  return p;
}

Energy Engine::energy() const {
  Energy e = block_energy();
  each_contact([&](std::size_t k, const ContactSlot&) {
    const int cp = near_pairs_[k].i, tp = near_pairs_[k].j;
    const PolygonView a = polygon_view(cp);
    const PolygonView b = polygon_view(tp);
    const double tol = pair_tolerance(a, b);
    const Polygon ip = intersection_polygon(a, b, tol);
    e.contact += contact_energy(sides_[cp].side, sides_[tp].side, ip, tol);
  });
  add_budget_terms(e);
  e.initial = energy0_;
  return e;
}

void Engine::add_budget_terms(Energy& e) const {
  add_friction_energy(e);
  // Eq. 5c damping (damping.cpp): the work its forces did, accumulated per
  // block, is dissipated; summed in block order (the same bits for any
  // thread count).
  for (double w : damping_work_) e.dissipated -= w;
}

void Engine::add_friction_energy(Energy& e) const {
  // The friction terms of the energy budget (Paper A Eqs. 24-26).
  // Stored: a sticking pair's force is the spring's, f_t = -kt d_tan
  // (Eq. 25), so it holds 1/2 kt |d_tan|^2 = |f_t|^2 / (2 kt). A sliding
  // pair under the return mapping keeps d_tan on the limit (d_tan = -f_t /
  // kt): the same |f_t|^2 / (2 kt). A pair sliding under the paper's rule
  // restarts d from the step's Delta d on the next step (Sect. 3.2.6): it
  // keeps no shear, its spring holds nothing (f_t = -|f_n| tan(phi) s is
  // no spring force).
  // Dissipated: the friction work W = -sum over steps of 1/2 (f_t^n +
  // f_t^{n+1}) . Delta d^n (friction.hpp, accumulated per pair) is what
  // friction took out of the blocks; what the springs do not hold of it is
  // gone: dissipated = W - stored. In a sticking step the trapezoid equals
  // the spring's energy change (f_t linear in d), so only sliding (the
  // work of the limit force on the slip), a restart that drops the shear
  // (kPaper: stick to slide, slide to stick) and a separation (the spring
  // vanishes with its pair) dissipate.
  if (!friction_) return;
  const bool restarts = scene_.contact.friction_update == FrictionUpdate::kPaper;
  const double half_compliance = 0.5 / scene_.contact.kt;
  double work = dropped_friction_work_;
  for (std::size_t k = 0; k < near_pairs_.size(); ++k) {
    work += pair_friction_work_[k];
    if (!near_pairs_[k].active) continue;
    const std::size_t slot = static_cast<std::size_t>(near_pairs_[k].slot);
    if (restarts && contact_slots_[slot].history.sliding) continue;
    e.friction_spring += half_compliance * length_squared(contact_slots_[slot].result.tangential_force);
  }
  e.dissipated = work - e.friction_spring;
}

void Engine::bank_friction_work(const std::vector<NearPair>& kept) {
  // Before a rebuild replaces the near list by `kept` (both sorted by
  // (i, j)): the friction work of the pairs that leave it, in pair order.
  auto before = [](const NearPair& x, const NearPair& y) { return x.i < y.i || (x.i == y.i && x.j < y.j); };
  std::size_t k = 0;
  for (std::size_t h = 0; h < near_pairs_.size(); ++h) {
    while (k < kept.size() && before(kept[k], near_pairs_[h])) ++k;
    const bool stays = k < kept.size() && !before(near_pairs_[h], kept[k]);
    if (!stays) dropped_friction_work_ += pair_friction_work_[h];
  }
}

Energy Engine::block_energy() const {
  // Kinetic, gravity and strain energy of the free blocks (no contacts).
  Energy e;
  for (int i = 0; i < block_count(); ++i) {
    if (fixed_[i]) continue;
    const Mat6 m = mass_matrix(moments_[i], density_[i]);
    e.kinetic += 0.5 * vel_[i].dot(m * vel_[i]);
    e.gravity -= mass_[i] * dot(scene_.gravity, moments_[i].centroid);
    if (strains_) e.strain += 0.5 * moments_[i].area * stress_[i].dot(elastic(i).ldlt().solve(stress_[i]));
  }
  return e;
}

}  // namespace dda
