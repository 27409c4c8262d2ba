// The pair loop: per near pair (independent of all others), the overlap
// test and intersection polygon (Paper A Sect. 3.1), the normal contact
// force and its loading point (Eqs. 10-20), the friction force
// (friction.hpp, Eqs. 24-26), and the penalty energy when a check is due.
#include <algorithm>
#include <array>

#include "lanes.hpp"
#include "simulation/friction.hpp"
#include "simulation/internal.hpp"

namespace dda {

using detail::thread_index;
using detail::team_size;
using detail::kPrefetchPairs;
using detail::PhaseClock;
using detail::seconds_since;
using detail::smoothed;
using detail::prefetch_polygon;

namespace {

// Relative cost of a near pair in the pair loop by what it turned out to
// be (dimensionless; instructions measured on the 6.1 collapse: ~2,500 for
// a touching pair, ~120 for a separate candidate, ~20 for a pair whose
// boxes do not overlap). Only the shares' balance depends on them.
constexpr long kWorkTouching = 125;
constexpr long kWorkCandidate = 6;
constexpr long kWorkOther = 1;

// aabb_overlap's verdict, both axes at once: a.lo <= b.hi and b.lo <=
// a.hi in both lanes (ordered compares: a NaN bound fails, as there).
inline bool boxes_overlap(const Aabb& a, const Aabb& b) {
  using detail::lanes;
  return (detail::lane_bits(lanes(a.lo) <= lanes(b.hi)) & detail::lane_bits(lanes(b.lo) <= lanes(a.hi))) == 3u;
}

constexpr double kTwoPi = 6.28318530717958647692;  // 2 pi, the penetration guard's first tier

// The contacts a thread's born or ended list keeps room for after a merge
// (a step's births and ends are a few per thousand blocks; more, as at the
// first force evaluation, is given back).
constexpr std::size_t kBornListRoom = 256;

}  // namespace

// Inlined into the pair loop (its only caller): a call frame of its own
// costs about as much as the bookkeeping it does. The pair's contact (null:
// no contact): in its slot when it touched at the last step, else a new
// entry of its thread's born list.
[[gnu::always_inline]] inline Engine::PairResult* Engine::pair_force(long k, bool was_active, const Polygon& ip,
                                                                     const IpEdge* source, double tol,
                                                                     bool& pair_fault, ThreadContacts& mine) {
  const int cp = near_pairs_[static_cast<std::size_t>(k)].i, tp = near_pairs_[static_cast<std::size_t>(k)].j;
  const ContactParams& c = scene_.contact;
  // Eqs. 11-20; pg kept within the IP where Eq. 20's crossing leaves it
  // (segment forces that nearly cancel), the rest of the moment a couple.
  const NormalForce nf =
      normal_contact_force(sides_[cp].side, sides_[tp].side, ip, c.integration, tol, source, LoadingPoint::kWithinIp);
  if (!nf.valid) return nullptr;
  const int slot = near_pairs_[static_cast<std::size_t>(k)].slot;
  PairResult* result;
  PairHistory* history;
  if (slot >= 0) {
    ContactSlot& s = contact_slots_[static_cast<std::size_t>(slot)];
    result = &s.result;
    history = friction_ ? &s.history : nullptr;
  } else {
    mine.born.emplace_back();
    BornContact& b = mine.born.back();
    b.pair = k;
    result = &b.result;
    history = &b.history;
  }
  PairResult& r = *result;
  PairLoad& load = pair_loads_[static_cast<std::size_t>(k)];
  r.normal_force = nf.force;
  r.ip_area = nf.ip_area;
  r.ip_length = 0.5 * nf.ip_perimeter;
  // friction.hpp, Eqs. 24-26, with the last evaluation's pg and tangential
  // force (the load's point and the result's force, still the last step's).
  if (friction_)
    pair_friction(cp, tp, r, *history, pair_friction_work_[static_cast<std::size_t>(k)], was_active, load.point,
                  r.tangential_force, nf);
  else
    r.tangential_force = Vec2{};
  const StabilityGuards& g = scene_.guards;
  if (g.max_penetration > 0.0 || g.max_approach_energy > 0.0) {
    // The penetration guard's measures (penetration_guard.cpp): the depth
    // and its bound, and at a first contact the relative approach energy.
    // The depth W (the IP's width) is bounded from above in three tiers,
    // each dearer and tighter than the last, and the bound from below by
    // the smaller inscribed radius: a pair below the bound at a tier stops
    // there (the verdict is the full test's, with r_min <= h_min).
    //  1. W <= 2 pi A / P from the IP's area A and perimeter P, which the
    //     normal force already has: a convex set of diameter D has
    //     W D <= 2 A (the quadrilateral spanned by a diameter and the two
    //     support points across it lies inside) and P <= pi D (Cauchy:
    //     P is pi times the mean width); no vertex loop.
    //  2. W <= the IP's extent along the normal force (a few dot products).
    //  3. W itself, against the blocks' half-thicknesses along the normal.
    double fn = 0.0;  // |normal force|, taken when a tier past the first or the approach energy needs it
    if (g.max_penetration > 0.0) {
      r.depth_bound = g.max_penetration * pair_radius_[static_cast<std::size_t>(k)];  // min(radius_[cp], radius_[tp])
      r.depth = kTwoPi * nf.ip_area / nf.ip_perimeter;
      if (!(r.depth <= r.depth_bound)) {
        fn = length(nf.force);
        r.depth = detail::extent_along(ip, nf.force) / fn;
        if (r.depth > r.depth_bound) {
          r.depth = detail::min_width(ip);
          r.depth_bound = 0.5 * g.max_penetration *
                          std::min(detail::extent_along(sides_[cp].side.poly, nf.force),
                                   detail::extent_along(sides_[tp].side.poly, nf.force)) /
                          fn;
        }
      }
    }
    if (was_active || !(g.max_approach_energy > 0.0)) {
      r.approach_energy = 0.0;
    } else {
      if (fn == 0.0) fn = length(nf.force);
      r.approach_energy = approach_energy(cp, tp, nf.point, nf.force / fn);
    }
    if (pair_guard_fault(cp, tp, r)) pair_fault = true;
  }
  near_pairs_[static_cast<std::size_t>(k)].active = true;
  load.force = r.normal_force + r.tangential_force;
  load.point = nf.point;
  load.couple = nf.couple;
  return result;
}

void Engine::pair_forces(bool with_energy) {
  // Pair forces, independent of each other. Each thread takes its
  // contiguous share of the list (pair_split_; all of it outside a
  // parallel region), not a dynamic schedule: its shared chunk counter
  // costs a cross-core round trip per chunk, which on a virtual machine
  // with slow core-to-core latency cost more than the uneven pair costs it
  // evens out (measured: 2 threads 0.9x of 1 thread with dynamic chunks of
  // 16). A pair whose boxes do not overlap is no candidate; a pair that
  // did not touch at the last step starts its friction history afresh
  // (pair_force). with_energy: each contact also stores its penalty energy
  // (for the energy guard, summed in pair order as energy() sums it).
  const int team = team_size(), t = thread_index();
  const long n = static_cast<long>(near_pairs_.size());
  const long begin = team > 1 ? pair_split_[static_cast<std::size_t>(t)] : 0;
  const long end = team > 1 ? pair_split_[static_cast<std::size_t>(t) + 1] : n;
  // The loop's arrays in locals: its stores could alias the vectors' members.
  NearPair* const near = near_pairs_.data();
  unsigned char* const active = pair_active_.data();
  const Aabb* const boxes = boxes_.data();
  const BlockSide* const sides = sides_.data();
  const std::uint32_t* const sharp = sharp_corners_.data();
  ThreadContacts& changed = thread_contacts_[static_cast<std::size_t>(t)];
  const SupportLines::Pair* const* const support = support_.data();
  // The intersection polygon and its edges' sources, rewritten by every
  // overlap test.
  Polygon ip;
  std::array<IpEdge, kMaxVertices> source;
  long work = 0;
  bool pair_fault = false;  // a pair failed the penetration guard
  // The phase began at the last barrier (team_barrier keeps the time).
  const PhaseClock::time_point t0 = team > 1 ? flags_[static_cast<std::size_t>(t)].phase_start : PhaseClock::time_point{};
  if (team > 1 && t == 0) balance_block_split();
  const long prefetch_end = team > 1 ? end - kPrefetchPairs : begin;
  for (long k = begin; k < end; ++k) {
    if (k < prefetch_end) {
      // The second block of a pair ahead (the first is mostly this pair's).
      const int j = near[k + kPrefetchPairs].j;
      prefetch_polygon<0>(polygon_view(j));
      __builtin_prefetch(&boxes[j]);
      __builtin_prefetch(&sides[j]);
    }
    NearPair& p = near[k];
    // p.active (did the pair touch at the last step?) is read and cleared
    // where it is needed, after the overlap test for a candidate: a value
    // kept across that call would be spilled around it.
    p.candidate = boxes_overlap(boxes[p.i], boxes[p.j]);
    if (!p.candidate) {
      work += kWorkOther;
      // Its slot is freed by merge_contacts. A copy of k (push_back takes a
      // reference, which would keep k in memory through the whole loop).
      // The flag is written only when set (most such pairs were apart).
      if (p.active) {
        p.active = false;
        active[k] = 0;
        changed.ended.push_back(long{k});
      }
      continue;
    }
    // Sect. 3.1.2 (overlap) and 3.1.3 (intersection polygon by cutting).
    const double tol = std::max(sides[p.i].tol, sides[p.j].tol);
    const OverlapFacts facts = {sharp[p.i], support[p.i], support[p.j]};
    PairResult* r = nullptr;
    int witness = p.witness;
    const OverlapState state =
        overlap_and_intersection(sides[p.i].side.poly, sides[p.j].side.poly, tol, ip, source.data(), &witness, facts);
    p.witness = static_cast<std::int16_t>(witness);  // an axis index: below 2 kMaxVertices
    const bool was_active = p.active;
    p.active = false;
    if (state != OverlapState::kOverlapping || ip.count < 3 ||
        !(r = pair_force(k, was_active, ip, source.data(), tol, pair_fault, changed))) {
      work += kWorkCandidate;
      if (was_active) {
        active[k] = 0;
        changed.ended.push_back(long{k});
      }
      continue;
    }
    active[k] = 1;  // p.active, set by pair_force
    work += kWorkTouching;
    // The penalty energy of the contact, as energy() computes it (the same
    // IP: the lines left out of the cut leave it unchanged).
    if (with_energy) r->energy = contact_energy(sides[p.i].side, sides[p.j].side, ip, tol);
  }
  // Read by every thread after the barrier below (run_steps' flags; none
  // before the first step).
  if (!flags_.empty()) flags_[static_cast<std::size_t>(t)].pair_failed = pair_fault;
  if (team > 1) {
    // The share's cost for the next split: its estimated work at this
    // core's measured speed.
    ThreadFlags& mine = flags_[static_cast<std::size_t>(t)];
    if (work > 0) mine.seconds_per_work = smoothed(mine.seconds_per_work, seconds_since(t0) / static_cast<double>(work));
    mine.pair_work = static_cast<double>(work) * (mine.seconds_per_work > 0.0 ? mine.seconds_per_work : 1.0);
  }
  team_barrier(Simulation::kPhasePairs);
}

}  // namespace dda

namespace dda {

void Engine::merge_contacts() {
  static_assert(sizeof(ContactSlot) == 128, "a contact slot is two cache lines");
  // Serial (thread 0, after the pair loop's barrier; the phase after it
  // reads only the pairs' loads): the slots of the pairs that stopped
  // touching are freed, then each pair that began to touch takes a free
  // slot (or a new one) for its contact. The table grows by an eighth at a
  // time (no doubling whose spare half would stay with it).
  for (ThreadContacts& tc : thread_contacts_) {
    for (const long k : tc.ended) {
      int& slot = near_pairs_[static_cast<std::size_t>(k)].slot;
      free_slots_.push_back(slot);
      slot = -1;
    }
    tc.ended.clear();
  }
  for (ThreadContacts& tc : thread_contacts_) {
    for (const BornContact& b : tc.born) {
      int slot;
      if (!free_slots_.empty()) {
        slot = free_slots_.back();
        free_slots_.pop_back();
      } else {
        slot = static_cast<int>(contact_slots_.size());
        if (contact_slots_.size() == contact_slots_.capacity())
          contact_slots_.reserve(contact_slots_.size() + contact_slots_.size() / 8 + 16);
        contact_slots_.emplace_back();
      }
      near_pairs_[static_cast<std::size_t>(b.pair)].slot = slot;
      ContactSlot& s = contact_slots_[static_cast<std::size_t>(slot)];
      s.result = b.result;
      s.history = friction_ ? b.history : PairHistory{};
    }
    // A list that held many (the first force evaluation: every contact)
    // gives its room back; a step's few births keep theirs.
    if (tc.born.capacity() > kBornListRoom) std::vector<BornContact>().swap(tc.born);
    tc.born.clear();
    if (tc.ended.capacity() > kBornListRoom) std::vector<long>().swap(tc.ended);
  }
}

}  // namespace dda
