// Paper B Sect. 5, the in-place refinement (SubdivisionMode::kInPlace,
// beyond the paper): coarse elements refined k x k in place and restricted
// back, mass and momentum moved exactly, and the mesh's lists rebuilt after
// each change.
#include <algorithm>
#include <cmath>
#include <limits>

#include "dda/cdem/mesh.hpp"
#include "geometry.hpp"
#include "model_ops.hpp"

namespace dda::cdem {

using namespace detail;
// PatchDeletion::kEnergyMatched: the largest factor by which the restricted
// velocity deviations or a parent's mean stress are scaled. Beyond it the
// fine-scale energy has no coarse counterpart worth amplifying (a nearly
// uniform coarse field would be turned into an invented one); the rest
// stays in deletion_loss.
constexpr double kMaxEnergyScale = 3.0;

// n of the patch steps dt/n: substep_safety times the element bound of
// the patch-evaluated elements.
void update_substeps(const ModelSetup& su, ModelState& st) {
  const MeshState& mesh = st.mesh;
  if (mesh.patch_eval.empty()) {
    st.patches.substeps = 1;
    return;
  }
  double omega = 0.0;
  for (int e : mesh.patch_eval)
    omega = std::max(omega, element_omega_max(mesh.elem(e), st.nodes.x, su.d[st.blocks[mesh.elem(e).block].material]));
  const double h = su.opt.substep_safety * 2.0 / omega;
  st.patches.substeps = std::max(1, static_cast<int>(std::ceil(su.dt / h - 1e-9)));
}

// After refining or deleting patches (masses m already set): inverse
// masses, element and node lists, boundary, substep count, hanging nodes.
void finish_mesh_change(const ModelSetup& su, ModelState& st) {
  NodeState& nd = st.nodes;
  MeshState& mesh = st.mesh;
  for (std::size_t i = 0; i < nd.x.size(); ++i)
    nd.inv_m[i] = (st.blocks[nd.block[i]].fixed || !(nd.m[i] > 0.0) || nd.kind[i] == NodeKind::kHanging) ? 0.0 : 1.0 / nd.m[i];
  rebuild_lists(mesh, nd, st.blocks);
  rebuild_boundary(mesh, nd.size(), st.blocks.size());
  update_substeps(su, st);
  for (int h : mesh.hanging) {
    nd.x[h] = lerp(nd.x[nd.hang_a[h]], nd.x[nd.hang_b[h]], nd.hang_w[h]);
    nd.v[h] = lerp(nd.v[nd.hang_a[h]], nd.v[nd.hang_b[h]], nd.hang_w[h]);
  }
}

// Refines coarse elements k x k at the current (synchronised) state. Mass
// and momentum move with 'parcels' (an element's lumped share at a node):
// the parent's corner parcels leave with the corner velocities, the
// children's parcels arrive with the velocity interpolated linearly over the
// parent; the lumped shares are exact for linear fields, so the masses come
// back to the same totals and the momentum is unchanged to round-off.
void refine(const ModelSetup& su, ModelState& st, const std::vector<int>& list_in) {
  NodeState& nd = st.nodes;
  MeshState& mesh = st.mesh;
  std::vector<int> list;
  for (int e : list_in)
    if (mesh.elem(e).active && mesh.elem(e).level == 0 && std::find(list.begin(), list.end(), e) == list.end()) list.push_back(e);
  if (list.empty()) return;
  const double energy_before = kinetic_energy(nd) + energy_of(su, st).strain;
  const double total_before = energy_of(su, st).total();
  const int k = st.patches.k;
  std::vector<double> mm = nd.m;
  std::vector<Vec2> p(nd.x.size());
  for (std::size_t i = 0; i < nd.x.size(); ++i) p[i] = (nd.kind[i] == NodeKind::kHanging ? 0.0 : nd.m[i]) * nd.v[i];
  std::vector<double> held(nd.x.size(), 0.0);  // lumped shares of hanging nodes (sitting on their masters)
  for (const Element& e : mesh.elems)
    if (e.active)
      for (int a : e.n)
        if (nd.kind[a] == NodeKind::kHanging) held[a] += e.mass / 3.0;
  const std::vector<NodeKind> old_kind = nd.kind;
  const std::vector<int> old_a = nd.hang_a, old_b = nd.hang_b;
  const std::vector<double> old_w = nd.hang_w;

  struct Parcel {
    int node;
    double mass;
    Vec2 vel;
  };
  std::vector<Parcel> add;
  auto new_node = [&](Vec2 pos, Vec2 vel, int block) {
    const int id = static_cast<int>(nd.x.size());
    nd.x.push_back(pos);
    nd.v.push_back(vel);
    nd.xs.push_back(pos);
    nd.f.push_back({});
    nd.iface.push_back({});
    nd.iimp.push_back({});
    nd.iface0.push_back({});
    nd.released_at.push_back(-std::numeric_limits<double>::infinity());
    nd.scratch.push_back({});
    nd.m.push_back(0.0);
    nd.inv_m.push_back(0.0);
    nd.block.push_back(block);
    nd.kind.push_back(NodeKind::kFine);
    nd.hang_a.push_back(-1);
    nd.hang_b.push_back(-1);
    nd.hang_w.push_back(0.0);
    nd.clone_count.push_back(0);
    mm.push_back(0.0);
    p.push_back({});
    st.blocks[block].nodes.push_back(id);
    return id;
  };
  for (int ei : list) {
    const std::array<int, 3> c = mesh.elem(ei).n;
    const int block = mesh.elem(ei).block;
    const double me = mesh.elem(ei).mass;
    const Vec3 stress = mesh.elem(ei).stress;
    const std::array<Vec2, 3> xc{nd.x[c[0]], nd.x[c[1]], nd.x[c[2]]};
    const std::array<Vec2, 3> vc{nd.v[c[0]], nd.v[c[1]], nd.v[c[2]]};
    for (int q = 0; q < 3; ++q) {
      mm[c[q]] -= me / 3.0;
      p[c[q]] -= (me / 3.0) * vc[q];
    }
    auto edge_nodes = [&](int a, int b, Vec2 xa, Vec2 xb, Vec2 va, Vec2 vb) {
      MeshEdge& info = mesh.edges.at(edge_key(a, b));
      if (info.nodes.empty()) {
        std::vector<int> ids;  // ordered from lo to hi
        const Vec2 xlo = a == info.lo ? xa : xb, xhi = a == info.lo ? xb : xa;
        const Vec2 vlo = a == info.lo ? va : vb, vhi = a == info.lo ? vb : va;
        for (int t = 1; t < k; ++t) {
          const double s = static_cast<double>(t) / k;
          ids.push_back(new_node(lerp(xlo, xhi, s), lerp(vlo, vhi, s), block));
        }
        mesh.edges.at(edge_key(a, b)).nodes = ids;
      }
      std::vector<int> ids = mesh.edges.at(edge_key(a, b)).nodes;
      if (a != mesh.edges.at(edge_key(a, b)).lo) std::reverse(ids.begin(), ids.end());
      return ids;
    };
    const std::vector<int> e01 = edge_nodes(c[0], c[1], xc[0], xc[1], vc[0], vc[1]);
    const std::vector<int> e12 = edge_nodes(c[1], c[2], xc[1], xc[2], vc[1], vc[2]);
    const std::vector<int> e02 = edge_nodes(c[0], c[2], xc[0], xc[2], vc[0], vc[2]);
    Lattice lat;
    lat.elem = ei;
    lat.k = k;
    lat.nodes.assign(static_cast<std::size_t>(lattice_count(k)), -1);
    auto interp = [&](const std::array<Vec2, 3>& f, int i, int j) {
      const double a = static_cast<double>(i) / k, b = static_cast<double>(j) / k;
      return (1.0 - a - b) * f[0] + a * f[1] + b * f[2];
    };
    for (int j = 0; j <= k; ++j)
      for (int i = 0; i + j <= k; ++i) {
        int id = lattice_boundary_node(i, j, k, c, e01, e12, e02);
        if (id < 0) id = new_node(interp(xc, i, j), interp(vc, i, j), block);
        lat.nodes[static_cast<std::size_t>(lattice_index(i, j, k))] = id;
      }
    // lattice (i, j) of each lattice slot, for the parcel velocities
    std::vector<std::pair<int, int>> ij(static_cast<std::size_t>(lattice_count(k)));
    for (int j = 0; j <= k; ++j)
      for (int i = 0; i + j <= k; ++i) ij[static_cast<std::size_t>(lattice_index(i, j, k))] = {i, j};
    for (const auto& t : lattice_triangles(k)) {
      Element ch;
      for (int q = 0; q < 3; ++q) ch.n[q] = lat.nodes[static_cast<std::size_t>(t[q])];
      ch.block = block;
      ch.level = 1;
      ch.parent = ei;
      ch.stress = stress;
      ch.last = {nd.x[ch.n[0]], nd.x[ch.n[1]], nd.x[ch.n[2]]};
      ch.mass = me / (k * k);
      for (int q = 0; q < 3; ++q) {
        const auto [i, j] = ij[static_cast<std::size_t>(t[q])];
        add.push_back({ch.n[q], ch.mass / 3.0, interp(vc, i, j)});
      }
      lat.children.push_back(static_cast<int>(mesh.elems.size()));
      mesh.elems.push_back(ch);
    }
    mesh.elem(ei).active = false;
    mesh.elem(ei).lattice = static_cast<int>(mesh.lattices.size());
    mesh.lattices.push_back(std::move(lat));
  }
  classify(mesh, nd);
  held.resize(nd.x.size(), 0.0);
  // Coarse nodes that leave the coarse level mid-step take their pending
  // patch impulse with them.
  for (std::size_t i = 0; i < old_kind.size(); ++i)
    if (old_kind[i] == NodeKind::kCoarse && nd.kind[i] != NodeKind::kCoarse) {
      p[i] += nd.iimp[i] - (0.5 * su.dt) * nd.iface0[i];
      nd.iimp[i] = Vec2{};
      nd.iface0[i] = Vec2{};
    }
  for (const Parcel& pc : add) {
    if (nd.kind[pc.node] == NodeKind::kHanging) {
      const int a = nd.hang_a[pc.node], b = nd.hang_b[pc.node];
      const double w = nd.hang_w[pc.node];
      mm[a] += (1.0 - w) * pc.mass;
      p[a] += (1.0 - w) * pc.mass * pc.vel;
      mm[b] += w * pc.mass;
      p[b] += w * pc.mass * pc.vel;
    } else {
      mm[pc.node] += pc.mass;
      p[pc.node] += pc.mass * pc.vel;
    }
  }
  for (std::size_t i = 0; i < old_kind.size(); ++i) {
    if (old_kind[i] != NodeKind::kHanging || nd.kind[i] == NodeKind::kHanging) continue;
    const int a = old_a[i], b = old_b[i];
    const double w = old_w[i], h = held[i];
    const Vec2 vh = lerp(nd.v[a], nd.v[b], w);
    mm[a] -= (1.0 - w) * h;
    p[a] -= (1.0 - w) * h * nd.v[a];
    mm[b] -= w * h;
    p[b] -= w * h * nd.v[b];
    mm[i] += h;
    p[i] += h * vh;
  }
  nd.m = lumped_masses(mesh, nd);
  for (std::size_t i = 0; i < nd.x.size(); ++i) {
    if (nd.kind[i] == NodeKind::kHanging || nd.kind[i] == NodeKind::kDead) continue;
    if (std::fabs(mm[i] - nd.m[i]) > 1e-9 * std::max(1.0, nd.m[i]))
      throw SimulationError("cdem refine: mass bookkeeping broke at node " + std::to_string(i));
    if (!st.blocks[nd.block[i]].fixed && nd.m[i] > 0.0) nd.v[i] = p[i] / nd.m[i];
  }
  finish_mesh_change(su, st);
  st.energy.remap_change += kinetic_energy(nd) + energy_of(su, st).strain - energy_before;
  st.energy.refine_loss += total_before - energy_of(su, st).total();
}

// Deletes the subdivided elements of refined coarse elements: every child
// parcel returns to the parent's corners with the linear weights of its node
// (a momentum-conserving restriction); the parent's stress becomes the
// area-weighted mean of its children's.
void unrefine(const ModelSetup& su, ModelState& st, const std::vector<int>& parents) {
  NodeState& nd = st.nodes;
  MeshState& mesh = st.mesh;
  if (parents.empty()) return;
  const double energy_before = kinetic_energy(nd) + energy_of(su, st).strain;
  const double total_before = energy_of(su, st).total();
  const double kinetic_before = kinetic_energy(nd);
  const bool match = su.opt.patch_deletion == PatchDeletion::kEnergyMatched;
  std::vector<double> mm(nd.x.size(), 0.0);
  std::vector<Vec2> p(nd.x.size());
  for (std::size_t i = 0; i < nd.x.size(); ++i)
    if (nd.kind[i] != NodeKind::kHanging) {
      mm[i] = nd.m[i];
      p[i] = nd.m[i] * nd.v[i];
    }
  const std::vector<NodeKind> old_kind = nd.kind;
  for (int ei : parents) {
    Element& parent = mesh.elem(ei);
    if (parent.active || parent.lattice < 0) continue;
    const Lattice lat = mesh.lattices[static_cast<std::size_t>(parent.lattice)];
    const int k = lat.k;
    const std::array<int, 3> c = parent.n;
    Vec3 stress_sum = Vec3::Zero();
    double area_sum = 0.0;
    for (int chi : lat.children) {
      Element& ch = mesh.elem(chi);
      const std::array<Vec2, 3> xc{nd.x[ch.n[0]], nd.x[ch.n[1]], nd.x[ch.n[2]]};
      const double ch_area = cst(xc).area;
      stress_sum += ch_area * ch.stress;
      area_sum += ch_area;
      for (int f : ch.n) {
        const auto it = std::find(lat.nodes.begin(), lat.nodes.end(), f);
        const int slot = static_cast<int>(it - lat.nodes.begin());
        int ii = 0, jj = 0;
        for (int j = 0; j <= k; ++j)
          for (int i = 0; i + j <= k; ++i)
            if (lattice_index(i, j, k) == slot) {
              ii = i;
              jj = j;
            }
        const double share = ch.mass / 3.0;
        Vec2 vel;
        if (nd.kind[f] == NodeKind::kHanging) {
          const int a = nd.hang_a[f], b = nd.hang_b[f];
          const double w = nd.hang_w[f];
          vel = lerp(nd.v[a], nd.v[b], w);
          mm[a] -= (1.0 - w) * share;
          p[a] -= (1.0 - w) * share * nd.v[a];
          mm[b] -= w * share;
          p[b] -= w * share * nd.v[b];
        } else {
          vel = nd.v[f];
          mm[f] -= share;
          p[f] -= share * vel;
        }
        const std::array<double, 3> nw{1.0 - static_cast<double>(ii + jj) / k, static_cast<double>(ii) / k,
                                       static_cast<double>(jj) / k};
        for (int q = 0; q < 3; ++q) {
          mm[c[q]] += nw[q] * share;
          p[c[q]] += nw[q] * share * vel;
        }
      }
      ch.active = false;
    }
    parent.active = true;
    parent.lattice = -1;
    parent.stress = area_sum > 0.0 ? Vec3(stress_sum / area_sum) : parent.stress;
    parent.last = {nd.x[c[0]], nd.x[c[1]], nd.x[c[2]]};
    if (match) {
      // PatchDeletion::kEnergyMatched, strain: the mean stress scaled so
      // that the parent's strain energy is its children's (capped).
      const Mat3& cm = su.c[st.blocks[parent.block].material];
      double fine_strain = 0.0;
      for (int chi : lat.children) {
        const Element& ch = mesh.elem(chi);
        fine_strain += cst_strain_energy({nd.x[ch.n[0]], nd.x[ch.n[1]], nd.x[ch.n[2]]}, ch.stress, cm);
      }
      const double coarse_strain = cst_strain_energy({nd.x[c[0]], nd.x[c[1]], nd.x[c[2]]}, parent.stress, cm);
      if (coarse_strain > 0.0)
        parent.stress *= std::min(kMaxEnergyScale, std::sqrt(std::max(1.0, fine_strain / coarse_strain)));
    }
  }
  // Edge nodes: kept (as hanging) only where the other side is still refined.
  for (int ei : parents) {
    const std::array<int, 3> c = mesh.elem(ei).n;
    for (int q = 0; q < 3; ++q) {
      MeshEdge& info = mesh.edges.at(edge_key(c[q], c[(q + 1) % 3]));
      bool other_refined = false;
      for (int s : info.elems)
        if (s >= 0 && s != ei && !mesh.elem(s).active && mesh.elem(s).lattice >= 0) other_refined = true;
      if (!other_refined) info.nodes.clear();
    }
  }
  classify(mesh, nd);
  // Nodes that became hanging hand their remaining parcels to the masters.
  for (std::size_t i = 0; i < old_kind.size(); ++i) {
    if (old_kind[i] == NodeKind::kHanging || nd.kind[i] != NodeKind::kHanging) continue;
    const int a = nd.hang_a[i], b = nd.hang_b[i];
    const double w = nd.hang_w[i];
    mm[a] += (1.0 - w) * mm[i];
    p[a] += (1.0 - w) * p[i];
    mm[b] += w * mm[i];
    p[b] += w * p[i];
    mm[i] = 0.0;
    p[i] = {};
  }
  nd.m = lumped_masses(mesh, nd);
  for (std::size_t i = 0; i < nd.x.size(); ++i) {
    if (nd.kind[i] == NodeKind::kHanging) continue;
    if (std::fabs(mm[i] - nd.m[i]) > 1e-9 * std::max(1.0, std::fabs(nd.m[i]) + std::fabs(mm[i])))
      throw SimulationError("cdem unrefine: mass bookkeeping broke at node " + std::to_string(i));
    if (nd.kind[i] == NodeKind::kDead) {
      nd.v[i] = {};
      continue;
    }
    if (!st.blocks[nd.block[i]].fixed && nd.m[i] > 0.0) nd.v[i] = p[i] / nd.m[i];
  }
  if (match) {
    // PatchDeletion::kEnergyMatched, kinetic: the restricted velocities of
    // the parents' corners, per block, spread about their mass-weighted mean
    // v_bar by mu = sqrt(1 + deficit / K_dev) (capped), K_dev the kinetic
    // energy of the deviations: sum m (v_bar + mu (v - v_bar)) keeps the
    // momentum, and the kinetic energy grows by the restriction's deficit.
    double kinetic_after = 0.0;
    for (std::size_t i = 0; i < nd.x.size(); ++i)
      if (nd.kind[i] == NodeKind::kCoarse || nd.kind[i] == NodeKind::kFine) kinetic_after += 0.5 * nd.m[i] * length_squared(nd.v[i]);
    double deficit = kinetic_before - kinetic_after;
    std::vector<int> corners;
    for (int ei : parents)
      for (int a : mesh.elem(ei).n)
        if ((nd.kind[a] == NodeKind::kCoarse || nd.kind[a] == NodeKind::kFine) && nd.inv_m[a] > 0.0 &&
            !st.blocks[nd.block[a]].fixed && std::find(corners.begin(), corners.end(), a) == corners.end())
          corners.push_back(a);
    // the deficit shared among the blocks in proportion to their deviations' energy
    std::vector<double> mass(st.blocks.size(), 0.0), k_dev(st.blocks.size(), 0.0);
    std::vector<Vec2> mom(st.blocks.size());
    for (int a : corners) {
      mass[nd.block[a]] += nd.m[a];
      mom[nd.block[a]] += nd.m[a] * nd.v[a];
    }
    for (int a : corners) {
      const int b = nd.block[a];
      k_dev[b] += 0.5 * nd.m[a] * length_squared(nd.v[a] - mom[b] / mass[b]);
    }
    double k_dev_sum = 0.0;
    for (double k : k_dev) k_dev_sum += k;
    if (deficit > 0.0 && k_dev_sum > 0.0)
      for (int a : corners) {
        const int b = nd.block[a];
        const double mu = std::min(kMaxEnergyScale, std::sqrt(1.0 + deficit / k_dev_sum));
        const Vec2 vbar = mom[b] / mass[b];
        nd.v[a] = vbar + mu * (nd.v[a] - vbar);
      }
  }
  finish_mesh_change(su, st);
  st.energy.remap_change += kinetic_energy(nd) + energy_of(su, st).strain - energy_before;
  st.energy.deletion_loss += total_before - energy_of(su, st).total();
}

}  // namespace dda::cdem
