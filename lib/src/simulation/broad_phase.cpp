// The broad phase: the near-pair list, sorted by (i, j), each pair owning
// its result slot while it stays near. A sort and sweep on boxes grown by
// a skin (a Verlet list), rebuilt only when a block left its grown box; or,
// without the sweep, all pairs whose boxes overlap, every step.
#include <algorithm>

#include "simulation/internal.hpp"

namespace dda {

using detail::team_size;
using detail::thread_index;

namespace {

// The near-pair list's spare room: at most 1 / kNearPairSlack of its pairs
// (dimensionless; the list changes by a few pairs per rebuild).
constexpr std::size_t kNearPairSlack = 8;

// The near-pair order: by first block, then second.
template <class P>
bool pair_before(const P& x, const P& y) {
  return x.i < y.i || (x.i == y.i && x.j < y.j);
}

}  // namespace

void Engine::update_near_pairs() {
  // Every thread reads every flag after move_blocks' barrier: the same
  // verdict in all of them. Without the sweep the list is rebuilt when the
  // pairs whose boxes overlap changed (a read-only test every thread makes
  // alike; an unchanged list keeps every slot as the merge would): a small
  // scene's usual step pays no rebuild and no allocation. The barrier after
  // the test keeps the list unchanged until every thread has read it (else
  // a thread still testing could read the rebuilt list, skip the rebuild's
  // barrier below and leave the team waiting for it). Thread 0 rebuilds;
  // the others wait for it at that barrier.
  bool rebuild = false;
  if (scene_.broad_phase == BroadPhase::kNone) {
    rebuild = !near_pairs_unchanged();
    team_barrier(Simulation::kPhaseBroad);
  }
  for (const ThreadFlags& f : flags_) rebuild = rebuild || f.left_skin;
  if (!rebuild) return;
  if (thread_index() == 0) {
    // The shares keep their proportions of the new list.
    const long before = static_cast<long>(near_pairs_.size());
    rebuild_near_pairs();
    const long after = static_cast<long>(near_pairs_.size());
    if (before > 0 && pair_split_.size() == static_cast<std::size_t>(team_size()) + 1) {
      for (long& b : pair_split_) b = b * after / before;
      pair_split_.back() = after;
    } else {
      split_evenly(team_size());
    }
  }
  team_barrier(Simulation::kPhaseBroad);  // every thread sees the new list and shares
}

bool Engine::near_pairs_unchanged() const {
  // BroadPhase::kNone: whether rebuild_near_pairs would list the same pairs
  // as near_pairs_ (every pair with a free block whose boxes overlap now,
  // in (i, j) order).
  const int n = block_count();
  std::size_t k = 0;
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j) {
      if ((fixed_[i] && fixed_[j]) || !aabb_overlap(boxes_[i], boxes_[j])) continue;
      if (k == near_pairs_.size() || near_pairs_[k].i != i || near_pairs_[k].j != j) return false;
      ++k;
    }
  return k == near_pairs_.size();
}

void Engine::rebuild_near_pairs() {
  // The pairs that may touch before the next rebuild, sorted by (i, j).
  // Sweep: sort and sweep along x on the boxes grown by the skin; the order
  // of the last rebuild is nearly sorted, so insertion sort is linear in
  // practice. Every pair whose current boxes overlap is in the list as
  // long as both boxes stay inside their grown boxes, so skipping the
  // others gives exactly the pairs a full sweep would give, in the same
  // order. Without the sweep (rebuilt every step): every pair with a free
  // block whose boxes overlap now, by testing all pairs.
  const int n = block_count();
  std::vector<NearPair> pairs;
  // Room for the last list and a little more: a rebuild lists about as
  // many pairs, without the doublings of a growing vector (whose spare
  // half would stay with the list, 12 bytes a pair).
  pairs.reserve(near_pairs_.size() + near_pairs_.size() / kNearPairSlack);
  if (scene_.broad_phase == BroadPhase::kNone) {
    for (int i = 0; i < n; ++i)
      for (int j = i + 1; j < n; ++j)
        if (!(fixed_[i] && fixed_[j]) && aabb_overlap(boxes_[i], boxes_[j])) pairs.push_back({i, j});
  } else {
    ++broad_phase_rebuilds_;
    skin_boxes_.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      skin_boxes_[i] = boxes_[i];
      if (fixed_[i]) continue;  // a fixed box never moves: no skin needed
      skin_boxes_[i].lo -= Vec2{skin_, skin_};
      skin_boxes_[i].hi += Vec2{skin_, skin_};
    }
    if (order_.size() != static_cast<std::size_t>(n)) {
      order_.resize(static_cast<std::size_t>(n));
      for (int i = 0; i < n; ++i) order_[i] = i;
    }
    const std::vector<Aabb>& g = skin_boxes_;
    for (std::size_t a = 1; a < order_.size(); ++a) {
      const int key = order_[a];
      std::size_t b = a;
      while (b > 0 && g[order_[b - 1]].lo.x > g[key].lo.x) {
        order_[b] = order_[b - 1];
        --b;
      }
      order_[b] = key;
    }
    for (std::size_t a = 0; a < order_.size(); ++a) {
      const int i = order_[a];
      for (std::size_t b = a + 1; b < order_.size(); ++b) {
        const int j = order_[b];
        if (g[j].lo.x > g[i].hi.x) break;
        if (fixed_[i] && fixed_[j]) continue;
        if (g[j].lo.y > g[i].hi.y || g[i].lo.y > g[j].hi.y) continue;
        pairs.push_back({std::min(i, j), std::max(i, j)});
      }
    }
    std::sort(pairs.begin(), pairs.end(), pair_before<NearPair>);
  }
  if (pairs.capacity() > pairs.size() + pairs.size() / kNearPairSlack) pairs.shrink_to_fit();
  // A pair on both lists keeps its state (witness, flags, load, friction
  // work and its contact slot): one merge pass over the two sorted lists. A pair in
  // contact now is on both with the sweep (its boxes overlap, so its grown
  // boxes do); a pair that leaves the list frees its slot.
  if (friction_) bank_friction_work(pairs);  // energy.cpp: the leaving pairs' friction work
  std::vector<double> friction_work(friction_ ? pairs.size() : 0);
  std::vector<PairLoad> loads(pairs.size());
  std::size_t h = 0;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    while (h < near_pairs_.size() && pair_before(near_pairs_[h], pairs[k])) ++h;
    if (h < near_pairs_.size() && !pair_before(pairs[k], near_pairs_[h])) {
      pairs[k].witness = near_pairs_[h].witness;
      pairs[k].candidate = near_pairs_[h].candidate;
      pairs[k].active = near_pairs_[h].active;
      pairs[k].slot = near_pairs_[h].slot;
      near_pairs_[h].slot = -1;  // handed on
      if (friction_) friction_work[k] = pair_friction_work_[h];
      loads[k] = pair_loads_[h];
    }
  }
  for (const NearPair& p : near_pairs_)
    if (p.slot >= 0) free_slots_.push_back(p.slot);
  near_pairs_.swap(pairs);
  pair_friction_work_.swap(friction_work);
  pair_loads_.swap(loads);
  // Each block's pairs in increasing order (CSR).
  near_pair_offset_.assign(static_cast<std::size_t>(n) + 1, 0);
  for (const NearPair& p : near_pairs_) {
    ++near_pair_offset_[static_cast<std::size_t>(p.i) + 1];
    ++near_pair_offset_[static_cast<std::size_t>(p.j) + 1];
  }
  for (int i = 0; i < n; ++i) near_pair_offset_[i + 1] += near_pair_offset_[i];
  block_pairs_.resize(static_cast<std::size_t>(near_pair_offset_[n]));
  std::vector<int> fill(near_pair_offset_.begin(), near_pair_offset_.end() - 1);
  for (std::size_t k = 0; k < near_pairs_.size(); ++k) {
    const int i = near_pairs_[k].i, j = near_pairs_[k].j;
    block_pairs_[static_cast<std::size_t>(fill[i]++)] = static_cast<int>(k);
    block_pairs_[static_cast<std::size_t>(fill[j]++)] = static_cast<int>(k);
  }
  set_pair_radii();
}

void Engine::set_pair_radii() {
  // Each near pair's smaller inscribed radius (radius_, fixed at t = 0):
  // what a candidate pair gives both its blocks' reach (reach_radius); and
  // each block's smallest over all its near pairs (near_radius_, a lower
  // bound of its reach).
  pair_radius_.resize(near_pairs_.size());
  near_radius_ = radius_;
  // And the pairs' active flags as the per-block sum reads them (pair_active_).
  pair_active_.resize(near_pairs_.size());
  for (std::size_t k = 0; k < near_pairs_.size(); ++k) pair_active_[k] = near_pairs_[k].active ? 1 : 0;
  for (std::size_t k = 0; k < near_pairs_.size(); ++k) {
    const std::size_t i = static_cast<std::size_t>(near_pairs_[k].i), j = static_cast<std::size_t>(near_pairs_[k].j);
    pair_radius_[k] = std::min(radius_[i], radius_[j]);
    near_radius_[i] = std::min(near_radius_[i], pair_radius_[k]);
    near_radius_[j] = std::min(near_radius_[j], pair_radius_[k]);
  }
}

std::size_t Engine::bytes_per_near_pair() const {
  // A near pair's own state; a touching pair's contact slot is apart
  // (sizeof(ContactSlot): the result and the friction history).
  // (pair_active_'s byte is the pair's active flag once more.)
  return sizeof(NearPair) + sizeof(PairLoad) + 2 * sizeof(int) + sizeof(double) + sizeof(unsigned char) +
         (friction_ ? sizeof(double) : 0);
}

}  // namespace dda
