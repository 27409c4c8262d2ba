// The penetration guard: two blocks must not pass through each other
// while the run goes on as if nothing happened.
//
// Where the force stops pushing apart. A block's potential (Paper A Eq.
// 12), phi = kn d_exit / H with d_exit the distance to the nearest edge
// (Eqs. 13-14), is largest at the block's inscribed-circle centre: phi_max
// = kn r / H, r its inscribed radius. The force on CP (Eq. 10) integrates
// grad phi_CP - grad phi_TP over the intersection polygon IP (Eq. 11: the
// same on its boundary): TP pushes each part of CP inside it toward TP's
// nearest exit. While CP's material has not passed TP's medial axis, the
// nearest exit is the face it entered through and the force pushes the
// blocks apart; past it the nearest exit is the far side and TP's
// potential pulls CP on, through it. Along the line of approach n the
// medial axis lies about half TP's extent along n behind the entry face:
// its half-thickness across the contact, h_TP = extent(TP, n) / 2 >= r_TP
// (= r for a face of a square; the inscribed-circle centre, 0.71 m deep,
// for a square's corner; the mid-plane for a plate hit on its face). The
// depth of no return is therefore about h_min = min(h_CP, h_TP): for two
// equal squares head on the net force peaks at depth r and falls to zero at
// full overlap (2 r); a corner driven into a thin plate is pulled through
// past h_plate. A thin block driven end-on into a large one is not at risk
// when its own thickness is penetrated: across the contact it is long.
//
// The largest energy a pair can store. The energy of a pair is the
// integral of phi_CP + phi_TP over IP (contact_energy; Eq. 10's force is
// its gradient). The part of a convex block P deeper than t, P_t, is convex
// with inradius r - t, and a convex body's area is at most its perimeter
// times its inradius (area = integral of the shrinking perimeters of its
// inner parallel bodies). So d area(P_t)/dt = -perimeter(P_t) <=
// -area(P_t) / (r - t), and area(P_t) <= A (1 - t / r). Hence int_P d_exit dA = int_0^r area(P_t) dt
// <= A r / 2 (a square or a triangle: A r / 3; a long strip: A r / 2). IP
// lies in both blocks, so whatever the overlap
//   E <= kn r_TP / H_TP min(A_TP / 2, A_CP) + kn r_CP / H_CP min(A_CP / 2, A_TP) = E_max.
// A pair that meets with a relative approach energy above E_max cannot be
// stopped by its own contact: it passes through.
//
// The checks (StabilityGuards; per touching pair, measured in the pair loop
// from the IP and the normal force it already has):
//  - depth d: the IP's width (its smallest extent over all directions).
//    For a flat contact of length L it is the penetration of the spring
//    k = kn L (1/H_CP + 1/H_TP) that stores E = k d^2 / 2; for a corner of
//    angle alpha driven in by delta it is delta min(1, 2 sin(alpha / 2));
//    a sliver along a joint has width ~0 however long it is (the normal
//    force of a vanishing overlap has no reliable direction: the IP's extent
//    along it is only the cheap upper bound of d with which the pair loop
//    skips the width of a shallow pair, and r_min = min(r_CP, r_TP) <= h_min
//    the cheap lower bound of h_min). Stop when d > max_penetration h_min
//    (default half the depth of no return). The depth grows per step by at
//    most the two blocks' vertex motions, which the step-motion guard keeps
//    below max_step_motion (0.25) r_min <= 0.25 h_min each: the check cannot
//    be stepped over between the bound and h_min.
//  - approach energy, at a pair's first contact: E_app = m_eff v_n^2 / 2,
//    v_n the normal closing speed at the loading point pg and 1 / m_eff =
//    sum over the two blocks of 1/m + ((pg - c) x n)^2 / I (rigid, a fixed
//    block adds 0). Stop when E_app > max_approach_energy E_max: the pair
//    will pass through, caught on its first step in contact.
// A pair with less energy than E_max that would still cross trips the depth
// check first.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "simulation/internal.hpp"

namespace dda {

double Engine::pair_energy_bound(int a, int b) const {
  // E_max above, J/m, with the areas of now and the inscribed radii of t = 0.
  const double area_a = moments_[a].area, area_b = moments_[b].area;
  return sides_[b].side.kn_over_h * radius_[b] * std::min(0.5 * area_b, area_a) +
         sides_[a].side.kn_over_h * radius_[a] * std::min(0.5 * area_a, area_b);
}

double Engine::approach_energy(int a, int b, Vec2 point, Vec2 normal, double* speed, double* mass) const {
  // E_app above, J/m; `normal` is the unit normal force on a (it pushes a
  // away from b). 0 when the blocks do not close at `point`.
  const auto velocity = [&](int i) {
    return fixed_[i] ? Vec2{} : point_displacement(moments_[i].centroid, point, vel_[i]);
  };
  const auto compliance = [&](int i) {
    if (fixed_[i]) return 0.0;
    const Vec2 arm = point - moments_[i].centroid;
    const double cross = arm.x * normal.y - arm.y * normal.x;
    const double inertia = density_[i] * (moments_[i].sxx + moments_[i].syy);
    return 1.0 / mass_[i] + cross * cross / inertia;
  };
  const double closing = -dot(velocity(a) - velocity(b), normal);
  const double m_eff = 1.0 / (compliance(a) + compliance(b));
  if (speed) *speed = closing;
  if (mass) *mass = m_eff;
  return closing > 0.0 ? 0.5 * m_eff * closing * closing : 0.0;
}

void Engine::check_pairs() const {
  // The first pair in pair order that fails the penetration guard, with
  // what a user can change.
  const StabilityGuards& g = scene_.guards;
  for (std::size_t k = 0; k < near_pairs_.size(); ++k) {
    if (!near_pairs_[k].active) continue;
    const PairResult& r = contact_slots_[static_cast<std::size_t>(near_pairs_[k].slot)].result;
    const int a = near_pairs_[k].i, b = near_pairs_[k].j;
    if (!pair_guard_fault(a, b, r)) continue;
    const double fn = length(r.normal_force);
    const Vec2 n = r.normal_force / fn;
    double speed = 0.0, m_eff = 0.0;
    const double e_now = approach_energy(a, b, pair_loads_[k].point, n, &speed, &m_eff);
    const double e_max = pair_energy_bound(a, b);
    // The half-thicknesses across the contact (as the pair loop took them).
    const double h_a = 0.5 * detail::extent_along(polygon_view(a), n);
    const double h_b = 0.5 * detail::extent_along(polygon_view(b), n);
    const double h_min = std::min(h_a, h_b);
    const int thin = h_a <= h_b ? a : b;
    const double kn = scene_.contact.kn;
    std::ostringstream s;
    const bool approach = r.approach_energy > 0.0 && r.approach_energy > g.max_approach_energy * e_max;
    if (approach) {
      s << "first contact with a relative approach energy of " << r.approach_energy << " J/m (closing speed "
        << speed << " m/s, effective mass " << m_eff << " kg/m), more than guards.max_approach_energy = "
        << g.max_approach_energy << " of the largest contact energy the pair can store, " << e_max
        << " J/m (kn = " << kn << " Pa, H = " << h_[a] << " and " << h_[b]
        << " m): the contact cannot stop the blocks, they would pass through each other. Raise contact.kn above "
        << kn * r.approach_energy / (g.max_approach_energy * e_max)
        << " Pa (the stored energy grows with kn; lower dt with it), or lower the impact speed; "
           "guards.max_approach_energy = 0 switches this check off";
    } else {
      // The depth a flat contact of this length would reach if the closing
      // energy went into its spring, and the kn that keeps it at the bound.
      const double bound = r.depth_bound;
      const double spring = kn * r.ip_length * (1.0 / h_[a] + 1.0 / h_[b]);
      const double reach = std::sqrt(r.depth * r.depth + 2.0 * e_now / spring);
      s << "penetration depth " << r.depth << " m (the intersection polygon's width; "
        << r.depth / h_[a] << " H) is " << r.depth / h_min << " of the half-thickness " << h_min
        << " m across the contact of " << block_label(thin) << ", more than guards.max_penetration = "
        << g.max_penetration << " (bound " << bound
        << " m): past that block's middle its potential (Eq. 12) stops pushing the blocks apart and they pass "
           "through each other (closing speed "
        << speed << " m/s, approach energy " << e_now << " J/m; the pair stores at most " << e_max
        << " J/m). Raise contact.kn to about " << kn * (reach / bound) * (reach / bound)
        << " Pa or more (the depth falls as 1/sqrt(kn); lower dt with it), or lower the impact speed; "
           "guards.max_penetration = 0 switches this check off";
    }
    stop_pair(a, b, approach ? StopReason::kApproachEnergy : StopReason::kPenetration, s.str());
  }
}

}  // namespace dda
