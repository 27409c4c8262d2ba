// Velocity Verlet (Paper A Sect. 2.3, Eqs. 6-8) per block: the half kick
// and drift with the moved geometry and body forces (move_blocks), and the
// contact forces summed in pair order through T(pg)^T (Eqs. 22-23, 28-29),
// a^{n+1} from M (Eq. 5a) and the second half kick (gather_and_kick).
#include <algorithm>

#include "block_lanes.hpp"
#include "geometry_kernels.hpp"
#include "simulation/internal.hpp"

namespace dda {

using detail::thread_index;
using detail::kPrefetchBlocks;
using detail::PhaseClock;
using detail::seconds_since;
using detail::smoothed;
using detail::prefetch_polygon;

namespace {

bool inside(const Aabb& b, const Aabb& grown) {
  return !(b.lo.x < grown.lo.x || b.lo.y < grown.lo.y || b.hi.x > grown.hi.x || b.hi.y > grown.hi.y);
}

}  // namespace

template <class Prefetch, class Each>
[[gnu::always_inline]] inline double Engine::over_block_share(const ThreadFlags& mine, Prefetch prefetch, Each each) {
  // Each block of this thread's share (block_share) in order, prefetching
  // kPrefetchBlocks ahead in a team; with a team, the share's seconds per
  // block since the phase began (the last barrier's exit, team_barrier),
  // else -1.
  const BlockShare share = block_share();
  const PhaseClock::time_point t0 = mine.phase_start;
  for (int i = share.begin; i < share.end; ++i) {
    if (i < share.prefetch_end) prefetch(i + kPrefetchBlocks);
    each(i);
  }
  return share.team && share.end > share.begin ? seconds_since(t0) / (share.end - share.begin) : -1.0;
}

// Flattened (as gather_and_kick): the per-block steps of this file
// (update_block_geometry; body_force in gather_and_kick) inline in the block loop, no call
// frames per block; the kernels of other files stay calls.
[[gnu::flatten]] void Engine::move_blocks() {
  // One pass per block: the half kick and drift of Eq. 8, the moved
  // block's geometry, and whether its box left its grown box (the broad
  // phase's list then needs a rebuild). Its body forces: with its contact
  // forces, in gather_contact_forces.
  const bool sweep = scene_.broad_phase == BroadPhase::kSweep;
  bool left_skin = false;
  ThreadFlags& mine = flags_[static_cast<std::size_t>(thread_index())];
  const double per_block = over_block_share(mine, [&](int i) { prefetch_block(i); }, [&](int i) __attribute__((always_inline)) {
    if (fixed_[i]) return;
    const Vec6 v = vel_[i] + 0.5 * dt_ * acc_[i];  // a local: the stores below cannot alias it
    vel_[i] = v;
    const Vec6 dd = dt_ * v;  // Eq. 8
    step_disp_[i] = dd;
    disp_[i] += dd;
    const Vec2 c = moments_[i].centroid;
    start_centroid_[i] = c;
    const PolygonSpan poly = polygon_span(i);
    if (exact_rotation_) {
      // RotationUpdate::kExact (see there and rotate_and_displace_vertices):
      // the rigid part turned by r0 exactly, and the stress (this step's
      // increment on the start configuration) turned with the material.
      step_motion2_[i] = rotate_and_displace_vertices(poly, c, dd);
      if (strains_) stress_[i] = rotated_stress(stress_[i] + elastic(i) * dd.tail<3>(), dd[2]);
    } else {
      step_motion2_[i] = detail::displace_polygon(poly, c, dd);  // displace_vertices: the largest vertex motion, squared (guard)
      if (strains_) stress_[i] += elastic(i) * dd.tail<3>();
    }
    update_block_geometry(i, poly);
    density_[i] = mass_[i] / moments_[i].area;  // mass is conserved: the density follows the strained area
    if (sweep && !inside(boxes_[i], skin_boxes_[i])) left_skin = true;
  });
  mine.left_skin = left_skin;
  if (per_block >= 0.0) mine.move_seconds_per_block = per_block;
  team_barrier(Simulation::kPhaseMove);
}

void Engine::prefetch_block(int i) const {
  // What moving block i reads and writes, for writing where it is written
  // (the other core may hold a copy from the pair loop).
  prefetch_polygon<1>(polygon_view(i));
  __builtin_prefetch(&vel_[i], 1);
  __builtin_prefetch(&acc_[i]);
  __builtin_prefetch(&moments_[i], 1);
  __builtin_prefetch(&sides_[i], 1);
  __builtin_prefetch(&boxes_[i], 1);
  __builtin_prefetch(&disp_[i], 1);
  __builtin_prefetch(&step_disp_[i], 1);
}

void Engine::prefetch_gather(int i) const {
  // Block i's pair loads (the other core wrote those of its pairs), the
  // stress of its body force and the velocity its kick writes.
  for (int q = near_pair_offset_[i], end = near_pair_offset_[i + 1]; q < end; ++q) {
    __builtin_prefetch(&near_pairs_[block_pairs_[q]]);
    __builtin_prefetch(&pair_loads_[block_pairs_[q]]);
  }
  __builtin_prefetch(&vel_[i], 1);
  __builtin_prefetch(&stress_[i]);
}

void Engine::update_geometry() {
  // The blocks' geometry at t = 0, and their masses (set once: the moves
  // conserve them, the density follows the strained area).
  for (int i = 0; i < block_count(); ++i) {
    update_block_geometry(i);
    if (mass_[i] == 0.0) mass_[i] = density_[i] * moments_[i].area;
    density_[i] = mass_[i] / moments_[i].area;
  }
}

void Engine::update_block_geometry(int i) { update_block_geometry(i, polygon_span(i)); }

void Engine::update_block_geometry(int i, PolygonSpan poly) {
  // The polygon's normals, moments and box, and with the normals at hand
  // block_facts' sharp corners and support lines (the same bits).
  const std::size_t b = static_cast<std::size_t>(i);
  // Triangles to pentagons inline, their loops unrolled (no call per block
  // and step), the same kernel as update_polygon_geometry's.
  double min_edge2;
  switch (poly.count) {
    case 4:
      min_edge2 = detail::polygon_geometry<4, true>(poly, support_[b], &sharp_corners_[b], moments_[b], boxes_[b]);
      break;
    case 5:
      min_edge2 = detail::polygon_geometry<5, true>(poly, support_[b], &sharp_corners_[b], moments_[b], boxes_[b]);
      break;
    case 3:
      min_edge2 = detail::polygon_geometry<3, true>(poly, support_[b], &sharp_corners_[b], moments_[b], boxes_[b]);
      break;
    default: min_edge2 = update_polygon_geometry(poly, support_[b], sharp_corners_[b], moments_[b], boxes_[b]);
  }
  sides_[i].tol = geometric_tolerance(boxes_[b]);
  if (scene_.contact.integration == Integration::kPaperBisector) {
    PotentialSide& side = sides_[i].side;
    // Without a small edge the bisectors are the vertex rays, the shared
    // list of the vertex count (detail::vertex_rays): set only when a small
    // edge comes or goes. The side's list is the vertex rays exactly when it
    // has one ray per vertex (a virtual node adds a ray, or replaces two by
    // one), 0 before the first. With a small edge the block's own list,
    // made the first time (room for a vertex ray and a virtual node per
    // edge), rebuilt every step.
    const double small = side.small_edge;  // small_edge_fraction H (choose_potential_length)
    const bool plain = !(min_edge2 < small * small);  // bisectors()' small-edge test on every edge
    if (plain) {
      if (side.bisector_count != side.poly.count) {
        side.bisectors = detail::vertex_rays(side.poly.count);
        side.bisector_count = side.poly.count;
      }
    } else {
      std::unique_ptr<Bisector[]>& own = own_bisectors_[b];
      if (!own) own.reset(new Bisector[static_cast<std::size_t>(2 * side.poly.count)]);
      side.bisectors = own.get();
      side.bisector_count = bisectors(side.poly, small, scene_.contact.small_edge_rays, own.get());
    }
  }
}

void Engine::block_facts(int i) {
  // What the overlap test reads of block i's polygon in every pair, found
  // once per block and step: the clipper's bevels when block i is the
  // contact, and the edges' normals and support offsets n_j . v_j (Eq. 9).
  const PolygonView poly = polygon_view(i);
  sharp_corners_[i] = sharp_corners(poly);
  support_lines(poly, support_[i]);
}

Vec6 Engine::body_force(int i) const {
  // Gravity (int T^T rho g dS = rho S g on the translation DOFs) and the
  // step's initial stress on the strain DOFs (K d of Eq. 4 carried as
  // accumulated stress because d is reset every step).
  Vec6 f = Vec6::Zero();
  if (fixed_[i]) return f;
  const double m = density_[i] * moments_[i].area;
  f[0] = m * scene_.gravity.x;
  f[1] = m * scene_.gravity.y;
  if (strains_) f.tail<3>() = -moments_[i].area * stress_[i];
  return f;
}

Engine::GatherArrays Engine::gather_arrays() {
  return {near_pair_offset_.data(), block_pairs_.data(), pair_active_.data(), near_pairs_.data(), pair_loads_.data()};
}

Vec6 Engine::gather_contact_forces(int i) { return gather_contact_forces(i, gather_arrays()); }

Vec6 Engine::gather_contact_forces(int i, const GatherArrays& a) {
  // Block i's force F^{n+1}: its body force, then its contact forces, Eqs.
  // 22-23 and 28-29 through T(pg)^T, added in increasing pair order (the
  // same bits for any thread count). The sum is kept in lanes
  // (point_load_lanes) and the arrays in locals (a): the force's stores
  // could alias them.
  const int* pairs = a.pairs;
  const NearPair* near = a.near;
  const PairLoad* loads = a.loads;
  const detail::Lanes c = detail::lanes(moments_[i].centroid);
  // The value of p.active a pair summed here has: 1 (active) for a free
  // block, 2 (never: a bool) for a fixed one, whose sum stays its body
  // force. One compare per near pair (a touching pair is a candidate).
  const int summed = fixed_[i] ? 2 : 1;
  const Vec6 body = body_force(i);
  detail::Lanes6 sum{{body[0], body[1]}, {body[2], body[3]}, {body[4], body[5]}};
  for (int q = a.offset[i], end = a.offset[i + 1]; q < end; ++q) {
    const int k = pairs[q];
    if (a.active[k] != summed) continue;
    const NearPair& p = near[k];
    const PairLoad& load = loads[k];
    detail::Lanes6 g = detail::point_load_lanes(c, load.point, load.force);
    // A pair whose pg was kept within its IP carries the rest of Eq. 20's
    // moment as a couple on the rotation DOF (+ on the first block, - on
    // the second, as the force): only then, so that every other sum keeps
    // its bits.
    if (load.couple != 0.0) g.g23[0] += load.couple;
    if (p.i == i) {  // block i is the pair's first (the force acts on it with +)
      sum.g01 += g.g01;
      sum.g23 += g.g23;
      sum.g45 += g.g45;
    } else {
      sum.g01 -= g.g01;
      sum.g23 -= g.g23;
      sum.g45 -= g.g45;
    }
  }
  Vec6 force;
  force << sum.g01[0], sum.g01[1], sum.g23[0], sum.g23[1], sum.g45[0], sum.g45[1];
  return force;
}

[[gnu::flatten]] void Engine::gather_and_kick() {
  // Per free block: its contact forces, a^{n+1}, the second half kick, and
  // the per-block guards (flagged here, reported by check_state). A fixed
  // block is skipped: no kick and no guard reads its sum, and a boundary
  // block has many near pairs.
  bool failed = false;
  // Thread 0 first gives the pairs that began to touch their contact
  // slots (contact_forces.cpp): this phase reads only the pairs' loads.
  if (thread_index() == 0) merge_contacts();
  ThreadFlags& mine = flags_[static_cast<std::size_t>(thread_index())];
  const GatherArrays arrays = gather_arrays();
  const double per_block = over_block_share(mine, [&](int i) { prefetch_gather(i); }, [&](int i) __attribute__((always_inline)) {
    if (fixed_[i]) return;
    const Vec6 force = gather_contact_forces(i, arrays);
    kick_block(i, force);
    if (guard_fault(i) != GuardFault::kNone) failed = true;
  });
  mine.guard_failed = failed;
  if (per_block >= 0.0) mine.seconds_per_block = smoothed(mine.seconds_per_block, mine.move_seconds_per_block + per_block);
  team_barrier(Simulation::kPhaseKick);
}

// Defined here (guards.cpp reports what it finds): gather_and_kick's
// flattened block loop inlines it after the kick.
Engine::GuardFault Engine::guard_fault(int i) const {
  // Block i (free) after its kick: a non-finite state, a collapsed area, or
  // a vertex that moved more in this step than max_step_motion of the
  // thinnest block within its reach (itself and its candidates: a block in
  // free flight is not stopped because a thin plate exists somewhere else).
  // Finite, all nine values at once: x * 0 is +-0 for a finite x and NaN
  // for an infinite or NaN one, and a sum of +-0 is +-0 (== 0) unless a NaN
  // enters it. No branch per value (the guard runs per block and step).
  using detail::Lanes;
  const Vec6& v = vel_[i];
  const AreaMoments& m = moments_[i];
  const Lanes zero{0.0, 0.0};
  const Lanes sum = Lanes{v[0], v[1]} * zero + Lanes{v[2], v[3]} * zero + Lanes{v[4], v[5]} * zero +
                    Lanes{m.centroid.x, m.centroid.y} * zero + Lanes{m.area, 0.0} * zero;
  const bool finite = sum[0] + sum[1] == 0.0;
  if (!finite) return GuardFault::kNonFinite;
  if (!(moments_[i].area > 0.0)) return GuardFault::kAreaCollapsed;
  // First against the limit of near_radius_ (<= the reach: a limit no
  // larger, |max_step_motion| r squared growing with r), which a block
  // mostly passes; only above it the reach itself (the same verdict).
  const double bound_limit = scene_.guards.max_step_motion * near_radius_[i];
  if (!(step_motion2_[i] > bound_limit * bound_limit)) return GuardFault::kNone;
  const double motion_limit = scene_.guards.max_step_motion * reach_radius(i);
  if (step_motion2_[i] > motion_limit * motion_limit) return GuardFault::kStepMotion;
  return GuardFault::kNone;
}

double Engine::reach_radius(int i) const {
  // The smallest inscribed radius within block i's reach: its own and its
  // candidates' (the pairs whose boxes overlapped at the last pair loop),
  // each pair's the smaller of its blocks' (pair_radius_).
  double reach = radius_[static_cast<std::size_t>(i)];
  for (int q = near_pair_offset_[static_cast<std::size_t>(i)]; q < near_pair_offset_[static_cast<std::size_t>(i) + 1]; ++q) {
    const int k = block_pairs_[static_cast<std::size_t>(q)];
    if (near_pairs_[static_cast<std::size_t>(k)].candidate) reach = std::min(pair_radius_[static_cast<std::size_t>(k)], reach);
  }
  return reach;
}

Vec6 Engine::force_acceleration(int i, const Vec6& f) const {
  // M^-1 f (Eq. 5a).
  const AreaMoments& m = moments_[i];
  const double mass = density_[i] * m.area;
  Vec6 a;
  a[0] = f[0] / mass;
  a[1] = f[1] / mass;
  if (strains_) {
    // Rotation and strains couple through the 4x4 lower block of M (Eq. 5a).
    a.tail<4>() = rotation_strain_acceleration(m, density_[i], f.tail<4>());
  } else {
    a.tail<4>().setZero();
    a[2] = f[2] / (density_[i] * (m.sxx + m.syy));
  }
  return a;
}

void Engine::kick_block(int i, const Vec6& force) {
  if (damped_) {
    damped_kick_block(i, force);  // Eq. 5c (damping.cpp)
    return;
  }
  const Vec6 a = force_acceleration(i, force);  // a local: the stores below cannot alias it
  acc_[i] = a;
  vel_[i] += 0.5 * dt_ * a;
}

void Engine::kick() {
  for (int i = 0; i < block_count(); ++i)
    if (!fixed_[i]) kick_block(i, gather_contact_forces(i));
}

}  // namespace dda
