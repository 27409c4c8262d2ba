// Paper B Sect. 4.2: the interaction force of each clone node (Eq. 11) and
// the separation criteria, tension (Eq. 6) and Mohr-Coulomb shear
// (Eqs. 7-10).
#include "model_ops.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace dda::cdem {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

// A sliding clone's tied point follows its main node along the target
// block's face: the nearest boundary edge and the foot of the node on it.
// Returns false when the node slid past the face (past a corner) or onto an
// edge integrated on the other level; the caller removes the clone then.
bool follow_sliding_target(Clone& c, NodeState& nd, const MeshState& mesh, const std::vector<BlockState>& blocks) {
  int a = -1, b = -1;
  double xi = 0.0;
  if (!locate_edge(mesh, nd.x, nd.block[c.ea], nd.x[c.main], a, b, xi)) return false;
  // The tie moves only along the face: to the touched edge itself or to a
  // neighbour sharing a node with it and turned by less than this angle (the
  // sub-edges of a refined face); a corner ends the slide.
  constexpr double kMaxFaceTurnCos = 0.8660254037844387;  // cos 30 deg
  if (!((a == c.ea && b == c.eb) ||
        ((a == c.ea || a == c.eb || b == c.ea || b == c.eb) &&
         dot(normalized(nd.x[b] - nd.x[a]), normalized(nd.x[c.eb] - nd.x[c.ea])) > kMaxFaceTurnCos)))
    return false;
  const Vec2 e = nd.x[b] - nd.x[a];
  const double xi_raw = dot(nd.x[c.main] - nd.x[a], e) / length_squared(e);
  constexpr double kFootSlack = 1e-9;  // relative to the edge length: round-off of the foot at a corner
  if (xi_raw < -kFootSlack || xi_raw > 1.0 + kFootSlack) return false;
  for (int q : {a, b}) {
    if (nd.kind[q] != NodeKind::kCoarse && nd.kind[q] != NodeKind::kFine) return false;
    if (!blocks[nd.block[q]].fixed && (nd.kind[q] == NodeKind::kFine) != c.fine) return false;
  }
  for (int q = 0; q < 2; ++q)
    if (c.t[q] >= 0) nd.clone_count[c.t[q]] -= 1;
  c.t = {a, b};
  c.w = {1.0 - xi, xi};
  c.ea = a;
  c.eb = b;
  nd.clone_count[a] += 1;
  nd.clone_count[b] += 1;
  return true;
}

void release_clone(NodeState& nd, const Clone& c, double t) {
  nd.clone_count[c.main] -= 1;
  nd.released_at[c.main] = t;
  for (int q = 0; q < 2; ++q)
    if (c.t[q] >= 0) {
      nd.clone_count[c.t[q]] -= 1;
      nd.released_at[c.t[q]] = t;
    }
}

// Interaction forces of the clone nodes (Eq. 11) at the current forces f:
// the force on each main node that gives it the acceleration of the point
// it is tied to, solved by Gauss-Seidel over coupled clones. Then the
// separation criteria: tension beyond sigma_t A_c (Eq. 6) removes the clone
// and its forces; shear beyond F_n tan(phi) + c A_c (Eqs. 7-9) limits the
// shear force to that value (Eq. 10) and the clone slides from then on: its
// normal velocity stays tied (the normal part of Eq. 11), its shear force is
// the one the tie demands (Eq. 11 with the slip of the step before stopped
// over the step) reduced to the limit with its own sign (Eq. 10: F_max
// F_s / |F_s|; below the limit the clone sticks again), and its tied point
// follows the node along the target's boundary; a sliding clone separates by Eq. 6 or
// when its node slides off the target. (Paper B's text removes the clone at
// Eq. 9 as well; the node, still pressed on the face, then touches again at
// once, and each re-touch's inelastic impact (Eq. 4) kills the tangential
// relative velocity: a frictionless face sticks or, with the re-touch
// delayed, is passed through.) The resulting forces are added to f.
void solve_clones(const ModelSetup& su, ModelState& st, bool fine, double t) {
  NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  std::vector<int> ids;
  for (int i = 0; i < static_cast<int>(st.clones.size()); ++i)
    if (st.clones[static_cast<std::size_t>(i)].fine == fine) ids.push_back(i);
  if (ids.empty()) return;
  std::vector<char> removed(st.clones.size(), 0);
  const double tan_phi = std::tan(su.opt.strength.friction_deg * kPi / 180.0);
  auto record = [&](const Clone& c, SeparationCriterion why, double limit) {
    const Vec2 n = clone_normal(c, mesh, nd.x);
    SeparationRecord rec;
    rec.time = t;
    rec.main_node = c.main;
    rec.main_block = nd.block[c.main];
    rec.target_block = nd.block[c.ea];
    rec.criterion = why;
    rec.normal_force = dot(c.lambda, n);
    rec.shear_force = dot(c.lambda, perp_left(n));
    rec.limit = limit;
    rec.contact_area = c.area;
    rec.fine = c.fine;
    return rec;
  };
  // Relative tangential velocity of each sliding clone (main node minus its
  // tied point) before the forces act; Eq. 10's demanded shear force stops it.
  std::vector<double> slip(st.clones.size(), 0.0);
  for (int i : ids) {
    Clone& c = st.clones[static_cast<std::size_t>(i)];
    if (!c.sliding) continue;
    if (!follow_sliding_target(c, nd, mesh, st.blocks)) {
      removed[i] = 1;
      c.lambda = Vec2{};
      st.log.separations.push_back(record(c, SeparationCriterion::kSlidOff, 0.0));
      continue;
    }
    Vec2 vrel = nd.v[c.main];
    for (int q = 0; q < 2; ++q)
      if (c.t[q] >= 0) vrel -= c.w[q] * nd.v[c.t[q]];
    slip[static_cast<std::size_t>(i)] = dot(vrel, perp_left(clone_normal(c, mesh, nd.x)));
  }
  // The time over which this force evaluation's impulse acts: the kick of
  // the force at t spans dt (coarse: the second half-kick of this step and
  // the first of the next) or at most one patch step dt/n; a shorter actual
  // span (a patch step split by a touch) only applies less of the
  // stopping impulse, so the slip is never reversed.
  const double span = fine ? su.dt / st.patches.substeps : su.dt;
  for (std::size_t pass = 0; pass <= ids.size(); ++pass) {
    for (int i : ids) {
      const Clone& c = st.clones[static_cast<std::size_t>(i)];
      nd.scratch[c.main] = nd.inv_m[c.main] * nd.f[c.main];
      for (int q = 0; q < 2; ++q)
        if (c.t[q] >= 0) nd.scratch[c.t[q]] = nd.inv_m[c.t[q]] * nd.f[c.t[q]];
    }
    for (int i : ids) st.clones[static_cast<std::size_t>(i)].lambda = Vec2{};
    for (int it = 0; it < 500; ++it) {
      double worst = 0.0, scale = 0.0;
      for (int i : ids) {
        if (removed[i]) continue;
        Clone& c = st.clones[static_cast<std::size_t>(i)];
        Vec2 r = nd.scratch[c.main];
        double w = nd.inv_m[c.main];
        for (int q = 0; q < 2; ++q)
          if (c.t[q] >= 0) {
            r -= c.w[q] * nd.scratch[c.t[q]];
            w += c.w[q] * c.w[q] * nd.inv_m[c.t[q]];
          }
        if (!(w > 0.0)) continue;
        Vec2 dl = -(1.0 / w) * r;
        if (c.sliding) {
          // Eq. 10: the shear force is the one the tie demands (Eq. 11 with
          // the slip of the step before stopped over `span`) reduced to the
          // limit F_n tan(phi) + c A_c with its own sign; never more, so
          // that friction cannot reverse the slip (a force at the limit
          // against a slip smaller than its impulse over the step pumps
          // energy in: up to 1.1e4 x KE0 in the B-9 impact study).
          const Vec2 n = clone_normal(c, mesh, nd.x), u = perp_left(n);
          const Vec2 want = c.lambda + dl - (slip[static_cast<std::size_t>(i)] / (span * w)) * u;
          const double fn = dot(want, n);
          const double lim = std::max(fn, 0.0) * tan_phi + su.opt.strength.cohesion * c.area;
          const double fs = std::clamp(dot(want, u), -lim, lim);
          dl = fn * n + fs * u - c.lambda;
        }
        c.lambda += dl;
        nd.scratch[c.main] += nd.inv_m[c.main] * dl;
        for (int q = 0; q < 2; ++q)
          if (c.t[q] >= 0) nd.scratch[c.t[q]] -= (c.w[q] * nd.inv_m[c.t[q]]) * dl;
        worst = std::max(worst, length(dl));
        scale = std::max(scale, length(c.lambda));
      }
      if (worst <= 1e-13 * scale || worst == 0.0) break;
    }
    bool changed = false;
    for (int i : ids) {
      if (removed[i]) continue;
      Clone& c = st.clones[static_cast<std::size_t>(i)];
      const Vec2 n = clone_normal(c, mesh, nd.x);
      const Vec2 u = perp_left(n);
      const double fn = dot(c.lambda, n), fs = dot(c.lambda, u);
      // Round-off guard: forces below 1e-12 E A_c are zero (a fresh clone
      // carries only round-off).
      const double noise =
          1e-12 * su.scene.materials[static_cast<std::size_t>(st.blocks[nd.block[c.main]].material)].young * c.area;
      if (fn < 0.0 && -fn > su.opt.strength.tensile * c.area + noise) {
        st.log.separations.push_back(record(c, SeparationCriterion::kTension, su.opt.strength.tensile * c.area));
        removed[i] = 1;
        c.lambda = Vec2{};
        changed = true;
        continue;
      }
      if (c.sliding) continue;
      const double fs_max = std::max(fn, 0.0) * tan_phi + su.opt.strength.cohesion * c.area;
      if (std::fabs(fs) > fs_max + noise) {
        st.log.slips.push_back(record(c, SeparationCriterion::kShear, fs_max));
        c.sliding = true;
        // the tie becomes edge-to-node (the edge's normal) for a node-to-node clone
        if (c.t[1] < 0 && !follow_sliding_target(c, nd, mesh, st.blocks)) {
          removed[i] = 1;
          c.lambda = Vec2{};
          st.log.separations.push_back(record(c, SeparationCriterion::kSlidOff, 0.0));
        }
        changed = true;
      }
    }
    if (!changed) break;
  }
  for (int i : ids) {
    if (removed[i]) continue;
    const Clone& c = st.clones[static_cast<std::size_t>(i)];
    nd.f[c.main] += c.lambda;
    for (int q = 0; q < 2; ++q)
      if (c.t[q] >= 0) nd.f[c.t[q]] -= c.w[q] * c.lambda;
  }
  std::vector<Clone> keep;
  for (std::size_t i = 0; i < st.clones.size(); ++i) {
    if (removed[i]) {
      release_clone(nd, st.clones[i], t);
      continue;
    }
    keep.push_back(st.clones[i]);
  }
  st.clones.swap(keep);
}

}  // namespace dda::cdem
