// Paper B Sect. 2, Eqs. 1-3: element forces of the constant-strain triangles
// (incremental stress, rotated), their assembly on the nodes, and the
// kinematics of the explicit step (positions at a time inside the step,
// half-kicks of the patch nodes).
#include "model_ops.hpp"

#include <cmath>
#include <sstream>

#include "geometry.hpp"

namespace dda::cdem {

using namespace detail;

// The coarse nodes at time t of the step (linear from their step-start
// positions), the hanging nodes on their edges.
void sync_positions(NodeState& nd, const MeshState& mesh, double t, double step_t0) {
  const double tau = t - step_t0;
  for (int n : mesh.coarse_dofs) nd.x[n] = nd.xs[n] + tau * nd.v[n];
  for (int h : mesh.hanging) {
    nd.x[h] = lerp(nd.x[nd.hang_a[h]], nd.x[nd.hang_b[h]], nd.hang_w[h]);
    nd.v[h] = lerp(nd.v[nd.hang_a[h]], nd.v[nd.hang_b[h]], nd.hang_w[h]);
  }
}

void add_node_force(NodeState& nd, int n, Vec2 f, bool patch_eval) {
  if (nd.kind[n] == NodeKind::kHanging) {
    add_node_force(nd, nd.hang_a[n], (1.0 - nd.hang_w[n]) * f, patch_eval);
    add_node_force(nd, nd.hang_b[n], nd.hang_w[n] * f, patch_eval);
    return;
  }
  if (patch_eval && nd.kind[n] == NodeKind::kCoarse)
    nd.iface[n] += f;
  else
    nd.f[n] += f;
}

// Incremental CST force (Paper B Eqs. 2-3): strain increment from the
// displacement since the last evaluation with B of the mid configuration,
// stress rotated by the element's incremental rotation and incremented with
// D d_eps; nodal forces -A B^T sigma with B of the current configuration.
void element_force(Element& e, NodeState& nd, const Mat3& d, bool patch_eval, double time, std::int64_t steps) {
  const std::array<Vec2, 3> x{nd.x[e.n[0]], nd.x[e.n[1]], nd.x[e.n[2]]};
  std::array<Vec2, 3> f;
  if (cst_incremental_force(x, e.last, e.stress, d, f) != 0) {
    std::ostringstream s;
    s << "cdem: element of block " << e.block << " inverted at t = " << time << " s (step " << steps << ")";
    throw SimulationError(s.str(), StopReason::kAreaCollapsed);
  }
  for (int i = 0; i < 3; ++i) add_node_force(nd, e.n[i], f[i], patch_eval);
}

// The coarse-step forces at st.time: gravity, mass damping, the elements
// evaluated at the coarse step (a sub-model's parents by their sub-model,
// Sect. 5 step 5), the clones (Eq. 11, separation Eqs. 6-10), the penalty
// baseline's springs.
void compute_coarse_forces(const ModelSetup& su, ModelState& st) {
  NodeState& nd = st.nodes;
  MeshState& mesh = st.mesh;
  const Vec2 g = su.scene.gravity;
  for (int n : mesh.coarse_dofs) nd.f[n] = nd.m[n] * g - su.opt.mass_damping * nd.m[n] * nd.v[n];
  for (int e : mesh.coarse_eval) {
    if (st.blocks[mesh.elem(e).block].fixed) continue;
    if (in_submodel(st.submodels, e)) continue;  // Sect. 5 step 5: its sub-model's force instead
    Element& el = mesh.elem(e);
    element_force(el, nd, su.d[st.blocks[el.block].material], false, st.time, st.steps);
  }
  add_submodel_forces(st.submodels, nd);
  solve_clones(su, st, false, st.time);
  if (su.opt.contact == ContactMode::kNodeToEdgePenalty) add_penalty_forces(su, st);
}

// The patch-step forces at t (kInPlace): the patch nodes' forces, the
// interface forces on the coarse nodes around the patch, the patch clones.
void compute_patch_forces(const ModelSetup& su, ModelState& st, double t) {
  NodeState& nd = st.nodes;
  MeshState& mesh = st.mesh;
  const Vec2 g = su.scene.gravity;
  for (int n : mesh.fine_dofs) nd.f[n] = nd.m[n] * g - su.opt.mass_damping * nd.m[n] * nd.v[n];
  for (int n : mesh.coarse_dofs) nd.iface[n] = Vec2{};
  for (int e : mesh.patch_eval) {
    Element& el = mesh.elem(e);
    if (!st.blocks[el.block].fixed) element_force(el, nd, su.d[st.blocks[el.block].material], true, st.time, st.steps);
  }
  solve_clones(su, st, true, t);
}

void kick_patch(NodeState& nd, const MeshState& mesh, double h) {
  for (int n : mesh.fine_dofs) nd.v[n] += (h * nd.inv_m[n]) * nd.f[n];
  for (int n : mesh.coarse_dofs) nd.iimp[n] += h * nd.iface[n];
}

// Coarse nodes next to a patch (corners of coarse elements evaluated at the
// patch steps) get those elements' force in their half-kicks like any other
// force (f = coarse-step forces + iface at t0 and t1), and at t1 the
// difference between the impulse the patch steps integrated for them (iimp)
// and what the two half-kicks gave (dt/2 at t0 and t1): so the impulses of
// every element on all its corners match (momentum exact) while the kicks
// stay centred (a return of the averaged impulse alone lags by dt/2 and
// pumps energy in at a rate ~ (omega dt)^2).
void kick_coarse_first_half(NodeState& nd, const MeshState& mesh, double dt) {
  for (int n : mesh.coarse_dofs) {
    nd.iface0[n] = nd.iface[n];
    nd.v[n] += (0.5 * dt * nd.inv_m[n]) * nd.f[n];
  }
  for (int n : mesh.coarse_dofs) nd.xs[n] = nd.x[n];
}

void forces_and_second_half_kick(const ModelSetup& su, ModelState& st) {
  NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  if (mesh.patch_eval.empty())
    for (int n : mesh.coarse_dofs) nd.iface[n] = Vec2{};
  compute_coarse_forces(su, st);
  for (int n : mesh.coarse_dofs) {
    nd.v[n] += nd.inv_m[n] * ((0.5 * su.dt) * nd.f[n] + nd.iimp[n] - (0.5 * su.dt) * nd.iface0[n]);
    nd.iimp[n] = Vec2{};
    nd.iface0[n] = Vec2{};
    nd.f[n] += nd.iface[n];
  }
}

// After the mesh changed at the step end: forces of the new mesh at t.
void refresh_forces_after_patch_change(const ModelSetup& su, ModelState& st, double t) {
  NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  for (int n : mesh.coarse_dofs) nd.iface[n] = Vec2{};
  if (!mesh.patch_eval.empty()) compute_patch_forces(su, st, t);
  compute_coarse_forces(su, st);
  for (int n : mesh.coarse_dofs) nd.f[n] += nd.iface[n];
}

}  // namespace dda::cdem
