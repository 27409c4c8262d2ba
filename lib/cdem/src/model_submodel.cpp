// Paper B Sect. 5 (SubdivisionMode::kSubModel): the two space scales by a
// separate sub-model of the colliding elements.
//
// The paper's steps, and how each is done here:
//  (1) At a touch at P_i the circles of radius c dt2 (c = sqrt(E / rho) of
//      each block, dt2 the contact part of the step, Sect. 3) give the
//      colliding elements. Here: the unowned coarse elements of the two
//      blocks within c dt2 of the contact point, and at least those holding
//      the touching node and those holding the touched point (the touched
//      node, or both nodes of the touched edge). Elements of a fixed block
//      get none (they do not move). Each colliding element is split k x k,
//      k = ceil(h_e / (c dt2)) (h_e = sqrt(2 A_e), the largest of the
//      colliding elements; c dt2 the smaller of the two blocks' radii),
//      clamped to [min_subdivision, max_subdivision]; k per sub-model
//      (each sub-model is separate, so no k is shared between them).
//  (2) The initial (coarse) nodes are integrated with dt as without
//      subdivision: the contact is Sects. 3-4 at coarse nodes (two-stage
//      step, clone, Eqs. 4-5 with coarse masses, separation Eqs. 6-11), the
//      coarse masses unchanged.
//  (3) The initial nodes' motion is the velocity boundary condition of the
//      sub-model: the sub-nodes at the initial nodes, and the sub-nodes on
//      edges the colliding elements share with an element outside the
//      sub-model, are prescribed ((1 - w) X_a + w X_b of the edge's coarse
//      nodes a, b; the coarse nodes moving linearly over the step from their
//      position at t0 to the one at t1, i.e. with their mean velocity of the
//      step, which includes the touch's velocity jump). The other sub-nodes
//      (inside, on edges between two colliding elements, on the block's free
//      boundary) are free. Interpretation: the paper fixes the 'corresponding
//      inside nodes' of the initial nodes; the shared edges are fixed too so
//      that the sub-model stays conforming with its coarse neighbours.
//  (4) Eq. 12, m_j u_j'' = -sum_k K_jk u_k, over the sub-nodes, solved with
//      steps dt/n over the coarse step (kick-drift-kick, the sub-elements'
//      incremental CST forces of Eqs. 2-3 as the coarse elements', gravity
//      and mass damping on the free sub-nodes as Eq. 1). n = ceil(dt /
//      (substep_safety * dt_sub)), dt_sub = min over sub-elements of
//      2 / omega_max(e) (the element bound, Irons). A new sub-model is built
//      at the end of its touch's step (t1) from its parents' state then:
//      positions and velocities interpolated linearly from the parents'
//      corners (the velocities are the coarse half-step ones), stress the
//      parent's; lumped sub-element masses.
//  (5) The sub-elements' forces at the end of the integration (t1; chosen
//      over the average of the substeps because the coarse kick-drift-kick
//      needs the force AT t1, and a step average lags by dt/2, which pumps
//      energy into a leapfrog scheme) are distributed to the coarse nodes
//      with linear weights and REPLACE the colliding elements' own element
//      force. Which forces (CdemOptions::submodel_transfer): by default the
//      forces on every sub-node, each with its linear weights in its home
//      parent (the paper's 'force values for the whole element'); in the
//      literal reading only those on the prescribed sub-nodes, with their
//      drive weights. The parents' stress is frozen while they are owned.
// The sub-model lives from the touch until no clone ties a corner of its
// parents (the contact points separated); it is deleted at the end of that
// step: each parent takes its sub-elements' area-averaged stress, its
// reference positions reset to its current corners. The strain-energy
// change of that is deletion_loss; the free sub-nodes' kinetic energy is
// dropped (SubModelRecord::kinetic_dropped; it is not in the coarse balance).
//
// Energy and momentum: the coarse model's kinetic energy and momentum are
// those of the coarse nodes, which keep their masses (the free sub-nodes'
// mass is the coarse nodes' too, so their kinetic energy relative to the
// coarse field is shown beside the balance, CdemEnergyAccount::
// submodel_kinetic, not in it); its strain energy counts the sub-elements in
// place of their parents. By default the returned forces are every
// sub-element's nodal forces, which sum to zero element by element: the
// coarse momentum is conserved to round-off. In the literal reading the
// returned forces lack the free sub-nodes' share, i.e. they include those
// nodes' inertia, and do not sum to zero while a sub-model lives.
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <unordered_map>

#include "dda/cdem/mesh.hpp"
#include "model_ops.hpp"
#include "geometry.hpp"

namespace dda::cdem {

using namespace detail;

namespace {

// A point this close to an element counts as inside it (relative to the
// point's distance from the origin + 1 m): round-off of the positions, m.
constexpr double kInsideRelTol = 1e-12;
// ceil(dt / h) - this: a ratio that is an integer up to round-off is not
// pushed to the next integer.
constexpr double kCeilSlack = 1e-9;

}  // namespace

// Step (1) at the touch: the request; the sub-model is built at t1.
void request_submodel(SubModels& subs, int touch_index, int main_node, Vec2 point, int ea, int eb, double dt2) {
  SubModelRequest r;
  r.main_node = main_node;
  r.point = point;
  r.ea = ea;
  r.eb = eb;
  r.dt2 = dt2;
  subs.requests.push_back(r);
  subs.request_touch.push_back(touch_index);
}

void create_submodel(const ModelSetup& su, ModelState& st, const SubModelRequest& req, int touch_index, double t) {
  const NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  if (st.submodels.elem_owner.empty()) st.submodels.elem_owner.assign(mesh.elems.size(), -1);
  const int m = req.main_node;
  const int bm = nd.block[m], bt = nd.block[req.ea];
  const double rm = su.wave_speed[st.blocks[bm].material] * req.dt2;
  const double rt = su.wave_speed[st.blocks[bt].material] * req.dt2;
  const double eps = kInsideRelTol * (length(req.point) + 1.0);
  auto tri = [&](int e) { return std::array<Vec2, 3>{nd.x[mesh.elem(e).n[0]], nd.x[mesh.elem(e).n[1]], nd.x[mesh.elem(e).n[2]]}; };
  auto has = [&](int e, int a) { return std::find(mesh.elem(e).n.begin(), mesh.elem(e).n.end(), a) != mesh.elem(e).n.end(); };
  // the touched point: a node, or both nodes of the touched edge
  const Vec2 ed = nd.x[req.eb] - nd.x[req.ea];
  const double xi = std::clamp(dot(req.point - nd.x[req.ea], ed) / length_squared(ed), 0.0, 1.0);
  std::vector<int> touched;
  if (xi <= kNodeTieXi)
    touched = {req.ea};
  else if (xi >= 1.0 - kNodeTieXi)
    touched = {req.eb};
  else
    touched = {req.ea, req.eb};
  std::vector<int> parents;
  for (int e : mesh.coarse_elems) {
    const int b = mesh.elem(e).block;
    if ((b != bm && b != bt) || st.blocks[b].fixed || st.submodels.elem_owner[e] >= 0) continue;
    const double d = point_triangle_distance(req.point, tri(e));
    bool in = (b == bm && d <= rm + eps) || (b == bt && d <= rt + eps) || (b == bm && has(e, m));
    if (b == bt) {
      bool all = true;
      for (int a : touched) all = all && has(e, a);
      in = in || all;
    }
    if (in) parents.push_back(e);
  }
  TouchRecord* rec = touch_index < static_cast<int>(st.log.touches.size()) ? &st.log.touches[touch_index] : nullptr;
  if (rec) rec->radius = std::max(rm, rt);
  if (parents.empty()) return;  // every colliding element already has a sub-model

  double he = 0.0;
  for (int e : parents) he = std::max(he, std::sqrt(2.0 * cst(tri(e)).area));
  const double r = std::min(rm, rt);
  int k = su.opt.max_subdivision;
  if (r > 0.0 && he > 0.0) k = static_cast<int>(std::ceil(he / r - kCeilSlack));
  k = std::clamp(k, su.opt.min_subdivision, su.opt.max_subdivision);

  const double energy_before = energy_of(su, st).strain;
  SubModel s;
  s.k = k;
  s.parents = parents;
  std::unordered_map<int, int> coarse_index;  // coarse node -> index into s.coarse
  auto coarse_of = [&](int a) {
    const auto it = coarse_index.find(a);
    if (it != coarse_index.end()) return it->second;
    const int i = static_cast<int>(s.coarse.size());
    coarse_index.emplace(a, i);
    s.coarse.push_back(a);
    s.coarse_x0.push_back(nd.x[a]);
    return i;
  };
  auto add_node = [&](Vec2 x, Vec2 v, int block, bool prescribed, int a, int b, double w) {
    s.x.push_back(x);
    s.v.push_back(v);
    s.f.push_back(Vec2{});
    s.m.push_back(0.0);
    s.block.push_back(block);
    s.prescribed.push_back(prescribed ? 1 : 0);
    s.drive.push_back({prescribed ? coarse_of(a) : -1, prescribed ? coarse_of(b) : -1});
    s.drive_w.push_back(w);
    s.home.push_back(-1);
    s.home_ab.push_back({0.0, 0.0});
    return static_cast<int>(s.x.size()) - 1;
  };
  std::unordered_map<int, int> corner;                      // coarse node -> sub-node
  std::map<std::uint64_t, std::vector<int>> edge_subnodes;  // coarse edge -> k - 1 sub-nodes, lo to hi
  auto in_parents = [&](int e) { return std::find(parents.begin(), parents.end(), e) != parents.end(); };
  auto edge_nodes = [&](int a, int b, int block) {
    const std::uint64_t key = edge_key(a, b);
    auto it = edge_subnodes.find(key);
    if (it == edge_subnodes.end()) {
      const MeshEdge& info = mesh.edges.at(key);
      // prescribed where the edge is shared with an element outside the sub-model
      bool shared_out = false;
      for (int e2 : info.elems)
        if (e2 >= 0 && !in_parents(e2)) shared_out = true;
      std::vector<int> ids;
      for (int q = 1; q < k; ++q) {
        const double w = static_cast<double>(q) / k;
        ids.push_back(add_node(lerp(nd.x[info.lo], nd.x[info.hi], w), lerp(nd.v[info.lo], nd.v[info.hi], w), block, shared_out,
                               info.lo, info.hi, w));
      }
      it = edge_subnodes.emplace(key, std::move(ids)).first;
    }
    std::vector<int> ids = it->second;
    if (a > b) std::reverse(ids.begin(), ids.end());
    return ids;
  };
  const auto lattice = lattice_triangles(k);
  for (int e : parents) {
    const Element& pe = mesh.elem(e);
    std::array<int, 3> c{};
    for (int q = 0; q < 3; ++q) {
      const int a = pe.n[q];
      auto it = corner.find(a);
      if (it == corner.end()) it = corner.emplace(a, add_node(nd.x[a], nd.v[a], pe.block, true, a, a, 0.0)).first;
      c[q] = it->second;
    }
    const std::vector<int> e01 = edge_nodes(pe.n[0], pe.n[1], pe.block);
    const std::vector<int> e12 = edge_nodes(pe.n[1], pe.n[2], pe.block);
    const std::vector<int> e02 = edge_nodes(pe.n[0], pe.n[2], pe.block);
    std::vector<int> lat(static_cast<std::size_t>(lattice_count(k)), -1);
    std::vector<std::array<double, 2>> lat_ab(static_cast<std::size_t>(lattice_count(k)));
    const std::array<Vec2, 3> px = tri(e);
    const std::array<Vec2, 3> pv{nd.v[pe.n[0]], nd.v[pe.n[1]], nd.v[pe.n[2]]};
    for (int j = 0; j <= k; ++j)
      for (int i = 0; i + j <= k; ++i) {
        int id = lattice_boundary_node(i, j, k, c, e01, e12, e02);
        if (id < 0) {
          const double a = static_cast<double>(i) / k, b = static_cast<double>(j) / k;
          id = add_node(px[0] + a * (px[1] - px[0]) + b * (px[2] - px[0]), pv[0] + a * (pv[1] - pv[0]) + b * (pv[2] - pv[0]),
                        pe.block, false, -1, -1, 0.0);
        }
        lat[static_cast<std::size_t>(lattice_index(i, j, k))] = id;
        lat_ab[static_cast<std::size_t>(lattice_index(i, j, k))] = {static_cast<double>(i) / k, static_cast<double>(j) / k};
        if (s.home[id] < 0) {
          s.home[id] = e;
          s.home_ab[id] = {static_cast<double>(i) / k, static_cast<double>(j) / k};
        }
      }
    const double mass = pe.mass / (static_cast<double>(k) * k);
    for (const auto& lt : lattice) {
      SubElement se;
      se.n = {lat[static_cast<std::size_t>(lt[0])], lat[static_cast<std::size_t>(lt[1])], lat[static_cast<std::size_t>(lt[2])]};
      se.parent = e;
      // the parent's stress and reference configuration (its corners at its
      // last evaluation, interpolated): the first evaluation adds the
      // parent's strain increment since then, as the parent's would
      se.stress = pe.stress;
      for (int q = 0; q < 3; ++q) {
        const auto& ab = lat_ab[static_cast<std::size_t>(lt[q])];
        se.last[q] = pe.last[0] + ab[0] * (pe.last[1] - pe.last[0]) + ab[1] * (pe.last[2] - pe.last[0]);
      }
      se.mass = mass;
      for (int a : se.n) s.m[a] += mass / 3.0;
      s.elems.push_back(se);
    }
  }
  s.home_c.resize(s.x.size());
  for (std::size_t i = 0; i < s.x.size(); ++i)
    for (int q = 0; q < 3; ++q) s.home_c[i][q] = coarse_index.at(mesh.elem(s.home[i]).n[q]);
  s.inv_m.resize(s.m.size());
  int free_nodes = 0;
  for (std::size_t i = 0; i < s.m.size(); ++i) {
    s.inv_m[i] = s.prescribed[i] ? 0.0 : 1.0 / s.m[i];
    free_nodes += s.prescribed[i] ? 0 : 1;
  }
  s.coarse_force.assign(s.coarse.size(), Vec2{});
  // step (4)'s n from the sub-elements' critical step (element bound)
  double omega = 0.0;
  for (const SubElement& se : s.elems) {
    const auto kk = element_stiffness({s.x[se.n[0]], s.x[se.n[1]], s.x[se.n[2]]}, su.d[st.blocks[mesh.elem(se.parent).block].material]);
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> es(kk, Eigen::EigenvaluesOnly);
    omega = std::max(omega, std::sqrt(std::max(es.eigenvalues().maxCoeff(), 0.0) / (se.mass / 3.0)));
  }
  const double sub_critical = omega > 0.0 ? 2.0 / omega : su.dt;
  s.substeps = std::max(1, static_cast<int>(std::ceil(su.dt / (su.opt.substep_safety * sub_critical) - kCeilSlack)));

  SubModelRecord record;
  record.created = t;
  record.main_node = m;
  record.main_block = bm;
  record.target_block = bt;
  record.elements = static_cast<int>(parents.size());
  record.k = k;
  record.sub_nodes = static_cast<int>(s.x.size());
  record.free_nodes = free_nodes;
  record.substeps = s.substeps;
  record.sub_critical_dt = sub_critical;
  record.radius = std::max(rm, rt);
  s.record = static_cast<int>(st.submodels.records.size());
  st.submodels.records.push_back(record);
  if (rec) {
    rec->subdivision = k;
    rec->refined_elements = static_cast<int>(parents.size());
  }
  const int index = static_cast<int>(st.submodels.live.size());
  for (int e : parents) st.submodels.elem_owner[e] = index;
  st.submodels.live.push_back(std::move(s));
  submodel_forces(st.submodels.live.back(), su, st, t);
  // the sub-elements take their parents' stress on the same area: the strain
  // energy changes by round-off only; measured as refine_loss
  st.energy.refine_loss += energy_before - energy_of(su, st).strain;
}

// Eqs. 2-3 on the sub-elements at their current positions: the forces on
// the free sub-nodes (with gravity and mass damping, Eq. 1) and, step (5),
// the forces returned to the coarse nodes: the element forces on every
// sub-node by its weights in its home parent (kWholeElement), or those on
// the prescribed sub-nodes by their drive weights (kPrescribedNodes).
void submodel_forces(SubModel& s, const ModelSetup& su, const ModelState& st, double t) {
  const MeshState& mesh = st.mesh;
  const Vec2 g = su.scene.gravity;
  for (std::size_t i = 0; i < s.x.size(); ++i)
    s.f[i] = s.prescribed[i] ? Vec2{} : s.m[i] * g - su.opt.mass_damping * s.m[i] * s.v[i];
  std::fill(s.coarse_force.begin(), s.coarse_force.end(), Vec2{});
  const bool whole = su.opt.submodel_transfer == SubModelTransfer::kWholeElement;
  std::vector<Vec2>& bc = s.bc;  // element forces on the returned sub-nodes
  bc.assign(s.x.size(), Vec2{});
  for (std::size_t q = 0; q < s.elems.size(); ++q) {
    SubElement& se = s.elems[q];
    const std::array<Vec2, 3> x{s.x[se.n[0]], s.x[se.n[1]], s.x[se.n[2]]};
    std::array<Vec2, 3> f;
    const int block = mesh.elem(se.parent).block;
    if (cst_incremental_force(x, se.last, se.stress, su.d[st.blocks[block].material], f) != 0) {
      std::ostringstream msg;
      msg << "cdem: sub-element " << q << " of the sub-model of element " << se.parent << " of block " << block
          << " inverted at t = " << t << " s (step " << st.steps + 1 << ")";
      throw SimulationError(msg.str(), StopReason::kAreaCollapsed);
    }
    for (int i = 0; i < 3; ++i) (s.prescribed[se.n[i]] ? bc : s.f)[se.n[i]] += f[i];
    if (whole)
      for (int i = 0; i < 3; ++i)
        if (!s.prescribed[se.n[i]]) bc[se.n[i]] += f[i];
  }
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    if (!is_finite(s.x[i]) || !is_finite(s.v[i]) || !is_finite(s.f[i]) || !is_finite(bc[i])) {
      int parent = -1;
      for (const SubElement& se : s.elems)
        for (int a : se.n)
          if (a == static_cast<int>(i)) parent = se.parent;
      std::ostringstream msg;
      msg << "cdem: non-finite state at sub-node " << i << " of the sub-model of element " << parent << " of block "
          << s.block[i] << ", t = " << t << " s (step " << st.steps + 1 << ")";
      throw SimulationError(msg.str(), StopReason::kNonFinite);
    }
    if (!s.prescribed[i]) {
      if (!whole) continue;
      const double a = s.home_ab[i][0], b = s.home_ab[i][1];
      s.coarse_force[static_cast<std::size_t>(s.home_c[i][0])] += (1.0 - a - b) * bc[i];
      s.coarse_force[static_cast<std::size_t>(s.home_c[i][1])] += a * bc[i];
      s.coarse_force[static_cast<std::size_t>(s.home_c[i][2])] += b * bc[i];
      continue;
    }
    const double w = s.drive_w[i];
    s.coarse_force[static_cast<std::size_t>(s.drive[i][0])] += (1.0 - w) * bc[i];
    s.coarse_force[static_cast<std::size_t>(s.drive[i][1])] += w * bc[i];
  }
}

// Steps (2)-(4) for the live sub-models over the coarse step t0 -> t1 (the
// coarse nodes already at t1), then step (1)'s sub-models of this step's
// touches built at t1.
void advance_submodels(const ModelSetup& su, ModelState& st, double t0, double t1) {
  const NodeState& nd = st.nodes;
  const double span = t1 - t0;
  for (SubModel& s : st.submodels.live) {
    std::vector<Vec2> x1(s.coarse.size()), vc(s.coarse.size());
    for (std::size_t c = 0; c < s.coarse.size(); ++c) {
      x1[c] = nd.x[s.coarse[c]];
      vc[c] = (x1[c] - s.coarse_x0[c]) / span;
    }
    const int n = s.substeps;
    const double h = span / n;
    for (int j = 0; j < n; ++j) {
      const double tau = static_cast<double>(j + 1) / n;
      for (std::size_t i = 0; i < s.x.size(); ++i) {
        if (s.prescribed[i]) {
          const auto a = static_cast<std::size_t>(s.drive[i][0]), b = static_cast<std::size_t>(s.drive[i][1]);
          const double w = s.drive_w[i];
          s.x[i] = (1.0 - w) * lerp(s.coarse_x0[a], x1[a], tau) + w * lerp(s.coarse_x0[b], x1[b], tau);
          s.v[i] = (1.0 - w) * vc[a] + w * vc[b];
        } else {
          s.v[i] += (0.5 * h * s.inv_m[i]) * s.f[i];
          s.x[i] += h * s.v[i];
        }
      }
      submodel_forces(s, su, st, t0 + (j + 1) * h);
      for (std::size_t i = 0; i < s.x.size(); ++i)
        if (!s.prescribed[i]) s.v[i] += (0.5 * h * s.inv_m[i]) * s.f[i];
    }
    s.coarse_x0 = x1;
    st.submodels.records[static_cast<std::size_t>(s.record)].substeps_taken += n;
    st.submodels.substeps_taken += n;
  }
  for (std::size_t r = 0; r < st.submodels.requests.size(); ++r)
    create_submodel(su, st, st.submodels.requests[r], st.submodels.request_touch[r], t1);
  st.submodels.requests.clear();
  st.submodels.request_touch.clear();
}

void add_submodel_forces(const SubModels& subs, NodeState& nd) {
  for (const SubModel& s : subs.live)
    for (std::size_t c = 0; c < s.coarse.size(); ++c) nd.f[s.coarse[c]] += s.coarse_force[c];
}

// The end of a sub-model: no clone ties a corner of its parents any more.
bool delete_separated_submodels(const ModelSetup& su, ModelState& st) {
  const NodeState& nd = st.nodes;
  MeshState& mesh = st.mesh;
  std::vector<char> busy(nd.x.size(), 0);
  for (const Clone& c : st.clones) {
    busy[c.main] = 1;
    for (int a : c.t)
      if (a >= 0) busy[a] = 1;
  }
  bool any = false;
  for (std::size_t q = st.submodels.live.size(); q-- > 0;) {
    SubModel& s = st.submodels.live[q];
    bool live = false;
    for (int e : s.parents)
      for (int a : mesh.elem(e).n) live = live || busy[a];
    if (live) continue;
    SubModelRecord& record = st.submodels.records[static_cast<std::size_t>(s.record)];
    record.kinetic_dropped = submodel_kinetic(s, mesh, nd);
    double change = 0.0;
    for (int e : s.parents) {
      Element& pe = mesh.elem(e);
      const Mat3& c = su.c[st.blocks[pe.block].material];
      Vec3 sum = Vec3::Zero();
      double area = 0.0, before = 0.0;
      for (const SubElement& se : s.elems) {
        if (se.parent != e) continue;
        const std::array<Vec2, 3> x{s.x[se.n[0]], s.x[se.n[1]], s.x[se.n[2]]};
        const double a = cst(x).area;
        sum += a * se.stress;
        area += a;
        before += cst_strain_energy(x, se.stress, c);
      }
      pe.stress = sum / area;
      pe.last = {nd.x[pe.n[0]], nd.x[pe.n[1]], nd.x[pe.n[2]]};
      change += cst_strain_energy(pe.last, pe.stress, c) - before;
      st.submodels.elem_owner[e] = -1;
    }
    record.strain_change = change;
    record.deleted = st.time;
    st.energy.deletion_loss -= change;
    st.submodels.live.erase(st.submodels.live.begin() + static_cast<std::ptrdiff_t>(q));
    any = true;
  }
  if (any) {
    std::fill(st.submodels.elem_owner.begin(), st.submodels.elem_owner.end(), -1);
    for (std::size_t q = 0; q < st.submodels.live.size(); ++q)
      for (int e : st.submodels.live[q].parents) st.submodels.elem_owner[e] = static_cast<int>(q);
  }
  return any;
}

double submodel_strain(const ModelSetup& su, const ModelState& st) {
  const MeshState& mesh = st.mesh;
  double e = 0.0;
  for (const SubModel& s : st.submodels.live)
    for (const SubElement& se : s.elems)
      e += cst_strain_energy({s.x[se.n[0]], s.x[se.n[1]], s.x[se.n[2]]}, se.stress,
                         su.c[st.blocks[mesh.elem(se.parent).block].material]);
  return e;
}

double submodel_kinetic(const SubModel& s, const MeshState& mesh, const NodeState& nd) {
  double e = 0.0;
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    if (s.prescribed[i]) continue;
    const Element& pe = mesh.elem(s.home[i]);
    const double a = s.home_ab[i][0], b = s.home_ab[i][1];
    const Vec2 vc = nd.v[pe.n[0]] + a * (nd.v[pe.n[1]] - nd.v[pe.n[0]]) + b * (nd.v[pe.n[2]] - nd.v[pe.n[0]]);
    e += 0.5 * s.m[i] * length_squared(s.v[i] - vc);
  }
  return e;
}

double submodel_kinetic(const ModelState& st) {
  double e = 0.0;
  for (const SubModel& s : st.submodels.live) e += submodel_kinetic(s, st.mesh, st.nodes);
  return e;
}

}  // namespace dda::cdem
