// Paper B Sect. 5, the in-place refinement (SubdivisionMode::kInPlace,
// beyond the paper): the contact zone refined at a touch, the patches
// integrated with steps dt/n inside the coarse step (Eq. 12) with the
// touches found at the patch scale, and the patches deleted after their
// clone nodes separated.
#include <algorithm>
#include <cmath>
#include <functional>
#include <numeric>
#include <sstream>

#include "geometry.hpp"
#include "model_ops.hpp"

namespace dda::cdem {

using namespace detail;

// At a touch (Sect. 5): the coarse elements of both blocks within c dt2 of
// the contact point are refined k x k (k fixed by the first touch from the
// element size h_e: k = ceil(h_e / (c dt2)), clamped), plus the coarse
// elements at the clone's nodes, so that the clone ties patch nodes; the
// touched edge (ea, eb, xi) is then located again among the new sub-edges.
void refine_contact_zone(const ModelSetup& su, ModelState& st, int m, Vec2 point, int& ea, int& eb, double& xi,
                         TouchRecord& rec) {
  const NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  const int bm = nd.block[m], bt = nd.block[ea];
  const double rm = su.wave_speed[st.blocks[bm].material] * rec.dt2;
  const double rt = su.wave_speed[st.blocks[bt].material] * rec.dt2;
  const double eps = 1e-12 * (length(point) + 1.0);
  auto tri = [&](int e) { return std::array<Vec2, 3>{nd.x[mesh.elem(e).n[0]], nd.x[mesh.elem(e).n[1]], nd.x[mesh.elem(e).n[2]]}; };
  auto touches_node = [&](int e, std::initializer_list<int> nodes) {
    for (int a : mesh.elem(e).n)
      for (int b : nodes)
        if (a == b) return true;
    return false;
  };
  if (st.patches.k == 0) {
    double he = 0.0;
    for (int e : mesh.coarse_elems) {
      const int b = mesh.elem(e).block;
      if ((b == bm || b == bt) && point_triangle_distance(point, tri(e)) <= eps)
        he = std::max(he, std::sqrt(2.0 * cst(tri(e)).area));
    }
    const double r = std::min(rm, rt);
    int k = su.opt.max_subdivision;
    if (r > 0.0 && he > 0.0) k = static_cast<int>(std::ceil(he / r - 1e-9));
    st.patches.k = std::clamp(k, su.opt.min_subdivision, su.opt.max_subdivision);
    if (su.opt.contact_point_mass > 0.0) {
      // CdemOptions::contact_point_mass (Sect. 4.1): the touching node's
      // lumped mass M becomes M / k^2 once its elements are refined k x k.
      const int km = std::max(su.opt.min_subdivision,
                              static_cast<int>(std::ceil(std::sqrt(nd.m[m] / su.opt.contact_point_mass) - 1e-9)));
      if (km > su.opt.max_subdivision) {
        std::ostringstream msg;
        msg << "cdem: contact_point_mass " << su.opt.contact_point_mass << " kg/m needs k = " << km
            << " for the touching node's mass " << nd.m[m] << " kg/m, above max_subdivision " << su.opt.max_subdivision;
        throw SceneError(msg.str());
      }
      st.patches.k = km;
    }
  }
  std::vector<int> set;
  for (int e : mesh.coarse_elems) {
    const int b = mesh.elem(e).block;
    const double d = (b == bm || b == bt) ? point_triangle_distance(point, tri(e)) : 1e300;
    if ((b == bm && d <= rm + eps) || (b == bt && d <= rt + eps)) set.push_back(e);
  }
  rec.refined_elements = static_cast<int>(set.size());
  refine(su, st, set);
  for (int it = 0; it < 4; ++it) {
    if (!locate_edge(mesh, nd.x, bt, point, ea, eb, xi)) throw SimulationError("cdem: touched block lost its boundary");
    std::vector<int> more;
    for (int e : mesh.coarse_elems)
      for (int a : {m, ea, eb})
        if (nd.kind[a] == NodeKind::kCoarse && touches_node(e, {a})) more.push_back(e);
    if (more.empty()) break;
    rec.refined_elements += static_cast<int>(more.size());
    refine(su, st, more);
  }
  rec.subdivision = st.patches.k;
  rec.radius = std::max(rm, rt);
}

bool dissolve_free_patches(const ModelSetup& su, ModelState& st) {
  const NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  std::vector<int> parents;
  for (int i = 0; i < static_cast<int>(mesh.elems.size()); ++i)
    if (!mesh.elems[i].active && mesh.elems[i].lattice >= 0) parents.push_back(i);
  if (parents.empty()) return false;
  // components: parents joined by shared coarse edges
  std::vector<int> root(parents.size());
  std::iota(root.begin(), root.end(), 0);
  std::function<int(int)> find = [&](int i) { return root[i] == i ? i : root[i] = find(root[i]); };
  for (std::size_t i = 0; i < parents.size(); ++i) {
    const Element& e = mesh.elem(parents[i]);
    for (int q = 0; q < 3; ++q) {
      const MeshEdge& info = mesh.edges.at(edge_key(e.n[q], e.n[(q + 1) % 3]));
      for (int s : info.elems) {
        if (s < 0 || s == parents[i]) continue;
        const auto it = std::find(parents.begin(), parents.end(), s);
        if (it != parents.end()) root[find(static_cast<int>(i))] = find(static_cast<int>(it - parents.begin()));
      }
    }
  }
  std::vector<char> busy(nd.x.size(), 0);
  for (const Clone& c : st.clones) {
    busy[c.main] = 1;
    busy[c.ea] = 1;
    busy[c.eb] = 1;
    for (int a : c.t)
      if (a >= 0) busy[a] = 1;
  }
  std::vector<char> keep(parents.size(), 0);
  for (std::size_t i = 0; i < parents.size(); ++i) {
    const Lattice& lat = mesh.lattices[static_cast<std::size_t>(mesh.elem(parents[i]).lattice)];
    for (int n : lat.nodes)
      if (busy[n]) keep[static_cast<std::size_t>(find(static_cast<int>(i)))] = 1;
  }
  std::vector<int> go;
  for (std::size_t i = 0; i < parents.size(); ++i)
    if (!keep[static_cast<std::size_t>(find(static_cast<int>(i)))]) go.push_back(parents[i]);
  if (go.empty()) return false;
  unrefine(su, st, go);
  return true;
}

// With subdivision: the coarse nodes move linearly over [t0, t1] with
// their coarse velocity; the refined patches are integrated with steps
// dt/n in between (kick-drift-kick), their coarse nodes acting as velocity
// boundary conditions (Eq. 12); patch-element forces on coarse nodes are
// summed into an impulse returned at t1. A coarse touch at t0 + dt1 refines
// the contact zone there and the contact stage dt2 is integrated in the
// patch (the patch steps are cut at that time: a rare event, once per new
// patch).
//
// Touches inside a patch step (the two stages of Sect. 3 at the patch
// scale) split the step's DRIFT, not its kicks: every patch node drifts to
// the touch time, the touch is processed there (clone, Eq. 4 projection of
// the half-step velocities, refinement), and the drift goes on to the end of
// the step with the new velocities; the forces and kicks stay on the
// uniform grid t + j dt/n. (Our approximation; Paper B gives no algorithm.)
// For a node that does not touch, a split drift is the same drift; the
// touching nodes move dt1 with the free and dt2 with the clone velocity, as
// in Sect. 3. Cutting the whole step at each touch instead (steps s h and
// then h) makes the kick-drift-kick steps irregular, and leapfrog with
// varying steps does not keep its energy: its invariant ellipse of a mode
// depends on omega h, and switching between ellipses at random pumps energy
// at a rate that grows steeply with omega h (model of one mode, omega h = 1.8
// of the patch's top modes at substep_safety 0.9, a random cut per coarse
// step: the energy e-folds in about 4 coarse steps; uniform steps: bounded).
// On the B-8 bars (ny 8, k 6) the cut steps fed the clone chatter on the
// contact face (3374 touches) and raised the energy to 2.4 E0.
void patch_loop(const ModelSetup& su, ModelState& st, double t0, double t1, std::vector<Touch> touches) {
  NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  std::sort(touches.begin(), touches.end(), [](const Touch& a, const Touch& b) { return a.s < b.s; });
  if (mesh.patch_eval.empty() && touches.empty()) return;
  std::size_t next = 0;
  auto event_time = [&](std::size_t i) { return t0 + touches[i].s * su.dt; };
  const double eps_t = 1e-12 * su.dt;
  double t = t0;
  sync_positions(nd, mesh, t, st.step_t0);
  if (!mesh.patch_eval.empty()) compute_patch_forces(su, st, t);
  std::vector<Touch> pending;
  std::vector<Vec2> p0, p1;
  // Touch groups processed inside one patch step (each at its time of
  // impact, the drift split there): touches found at the same time are
  // processed together, so a few suffice; more means a touch that does not
  // let the step advance.
  constexpr long kMaxStalls = 1000;
  // Touches within this fraction of the remaining drift of the first one are
  // processed together (the grouping of simultaneous touches).
  constexpr double kGroupFraction = 1e-9;
  auto signed_gap = [&](const Touch& T) {
    const Vec2 e = nd.x[T.eb] - nd.x[T.ea];
    return cross(nd.x[T.node] - nd.x[T.ea], e) / length(e);
  };
  while (true) {
    bool changed = false;
    while (next < touches.size() && event_time(next) <= t + eps_t) {
      const Touch& T = touches[next++];
      if (nd.kind[T.node] != NodeKind::kCoarse || nd.kind[T.ea] != NodeKind::kCoarse || nd.kind[T.eb] != NodeKind::kCoarse)
        continue;  // now inside a patch: the patch detection finds it
      changed = process_touch(su, st, T, false, t, t0, t1) || changed;
    }
    for (const Touch& T : pending) changed = process_touch(su, st, T, true, t, t0, t1) || changed;
    pending.clear();
    if (changed && !mesh.patch_eval.empty()) compute_patch_forces(su, st, t);
    if (t >= t1 - eps_t) break;
    double h = std::min(su.dt / st.patches.substeps, t1 - t);
    if (next < touches.size()) h = std::min(h, event_time(next) - t);
    h = std::max(h, 0.0);
    if (mesh.patch_eval.empty()) {
      t += h;
      sync_positions(nd, mesh, t, st.step_t0);
      continue;
    }
    kick_patch(nd, mesh, 0.5 * h);
    // The drift over [t, t + h], split at the touches on its path.
    double tau = 0.0;  // fraction of h drifted
    long groups = 0;
    while (true) {
      p0 = nd.x;
      p1 = nd.x;
      for (int n : mesh.fine_dofs) p1[n] = nd.x[n] + ((1.0 - tau) * h) * nd.v[n];
      for (int n : mesh.coarse_dofs) p1[n] = nd.xs[n] + (t + h - st.step_t0) * nd.v[n];
      // released_at is compared with the step start: a node released at the
      // last force evaluation touches again from the next patch step.
      const std::vector<Touch> found = find_touches(su, st, false, t, t + tau * h, t + h, p0, p1);
      if (found.empty()) break;
      const double smin = found.front().s;
      std::vector<Touch> group;
      for (const Touch& T : found)
        if (T.s <= smin + kGroupFraction) group.push_back(T);
      if (smin >= 1.0) {  // at the end of the step: processed after the kick
        pending = group;
        break;
      }
      const double hs = smin * (1.0 - tau) * h;
      for (int n : mesh.fine_dofs) nd.x[n] += hs * nd.v[n];
      tau += smin * (1.0 - tau);
      const double te = t + tau * h;
      sync_positions(nd, mesh, te, st.step_t0);
      bool any = false;
      for (const Touch& T : group) any = process_touch(su, st, T, true, te, t0, t1) || any;
      // A group that nothing was done for is found again at once; so is a
      // contact that does not let the drift advance.
      if ((!any && smin <= 0.0) || ++groups > kMaxStalls) {
        const Touch& T = group.front();
        std::ostringstream msg;
        msg << "cdem: patch step stalled at t = " << te << " s (step " << st.steps + 1 << "): node " << T.node
            << " of block " << nd.block[T.node] << " touches block " << nd.block[T.ea] << " again at once "
            << "(depth " << std::max(0.0, -signed_gap(T)) << " m, " << groups << " touch groups in this patch step); "
            << "the contact cannot be resolved: try a smaller dt or friction > 0";
        throw ContactError(msg.str(), T.node, nd.block[T.node], nd.block[T.ea], st.steps + 1, te,
                           std::max(0.0, -signed_gap(T)));
      }
    }
    for (int n : mesh.fine_dofs) nd.x[n] += ((1.0 - tau) * h) * nd.v[n];
    t += h;
    sync_positions(nd, mesh, t, st.step_t0);
    compute_patch_forces(su, st, t);
    kick_patch(nd, mesh, 0.5 * h);
    ++st.patches.substeps_taken;
  }
}

}  // namespace dda::cdem
