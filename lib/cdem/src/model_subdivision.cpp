// Paper B Sect. 5: local subdivision of the elements around a contact,
// integrated with steps dt/n inside the coarse step (Eq. 12), and the
// deletion of a patch after its clone nodes separated.
#include "dda/cdem/model.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <sstream>

#include "dda/cdem/mesh.hpp"
#include "geometry.hpp"

namespace dda::cdem {

using namespace detail;

// PatchDeletion::kEnergyMatched: the largest factor by which the restricted
// velocity deviations or a parent's mean stress are scaled. Beyond it the
// fine-scale energy has no coarse counterpart worth amplifying (a nearly
// uniform coarse field would be turned into an invented one); the rest
// stays in deletion_loss.
constexpr double kMaxEnergyScale = 3.0;

void Model::update_substeps() {
  if (patch_eval_.empty()) {
    substeps_ = 1;
    return;
  }
  double omega = 0.0;
  for (int e : patch_eval_) omega = std::max(omega, element_omega_max(elem(e)));
  const double h = opt_.substep_safety * 2.0 / omega;
  substeps_ = std::max(1, static_cast<int>(std::ceil(dt_ / h - 1e-9)));
}

// After refining or deleting patches (masses m_ already set): inverse
// masses, element and node lists, boundary, substep count, hanging nodes.
void Model::finish_mesh_change() {
  for (std::size_t i = 0; i < x_.size(); ++i)
    inv_m_[i] = (blocks_[node_block_[i]].fixed || !(m_[i] > 0.0) || kind_[i] == NodeKind::kHanging) ? 0.0 : 1.0 / m_[i];
  rebuild_lists();
  rebuild_boundary();
  update_substeps();
  for (int h : hanging_) {
    x_[h] = lerp(x_[hang_a_[h]], x_[hang_b_[h]], hang_w_[h]);
    v_[h] = lerp(v_[hang_a_[h]], v_[hang_b_[h]], hang_w_[h]);
  }
}

// Refines coarse elements k_ x k_ at the current (synchronised) state. Mass
// and momentum move with 'parcels' (an element's lumped share at a node):
// the parent's corner parcels leave with the corner velocities, the
// children's parcels arrive with the velocity interpolated linearly over the
// parent; the lumped shares are exact for linear fields, so the masses come
// back to the same totals and the momentum is unchanged to round-off.
void Model::refine(const std::vector<int>& list_in) {
  std::vector<int> list;
  for (int e : list_in)
    if (elem(e).active && elem(e).level == 0 && std::find(list.begin(), list.end(), e) == list.end()) list.push_back(e);
  if (list.empty()) return;
  const double energy_before = kinetic_energy() + energy().strain;
  const double total_before = energy().total();
  const int k = k_;
  std::vector<double> mm = m_;
  std::vector<Vec2> p(x_.size());
  for (std::size_t i = 0; i < x_.size(); ++i) p[i] = (kind_[i] == NodeKind::kHanging ? 0.0 : m_[i]) * v_[i];
  std::vector<double> held(x_.size(), 0.0);  // lumped shares of hanging nodes (sitting on their masters)
  for (const Elem& e : elems_)
    if (e.active)
      for (int a : e.n)
        if (kind_[a] == NodeKind::kHanging) held[a] += e.mass / 3.0;
  const std::vector<NodeKind> old_kind = kind_;
  const std::vector<int> old_a = hang_a_, old_b = hang_b_;
  const std::vector<double> old_w = hang_w_;

  struct Parcel {
    int node;
    double mass;
    Vec2 vel;
  };
  std::vector<Parcel> add;
  auto new_node = [&](Vec2 pos, Vec2 vel, int block) {
    const int id = static_cast<int>(x_.size());
    x_.push_back(pos);
    v_.push_back(vel);
    xs_.push_back(pos);
    f_.push_back({});
    iface_.push_back({});
    iimp_.push_back({});
    iface0_.push_back({});
    released_at_.push_back(-std::numeric_limits<double>::infinity());
    scratch_.push_back({});
    m_.push_back(0.0);
    inv_m_.push_back(0.0);
    node_block_.push_back(block);
    kind_.push_back(NodeKind::kFine);
    hang_a_.push_back(-1);
    hang_b_.push_back(-1);
    hang_w_.push_back(0.0);
    clone_count_.push_back(0);
    mm.push_back(0.0);
    p.push_back({});
    blocks_[block].nodes.push_back(id);
    return id;
  };
  for (int ei : list) {
    const std::array<int, 3> c = elem(ei).n;
    const int block = elem(ei).block;
    const double me = elem(ei).mass;
    const Vec3 stress = elem(ei).stress;
    const std::array<Vec2, 3> xc{x_[c[0]], x_[c[1]], x_[c[2]]};
    const std::array<Vec2, 3> vc{v_[c[0]], v_[c[1]], v_[c[2]]};
    for (int q = 0; q < 3; ++q) {
      mm[c[q]] -= me / 3.0;
      p[c[q]] -= (me / 3.0) * vc[q];
    }
    auto edge_nodes = [&](int a, int b, Vec2 xa, Vec2 xb, Vec2 va, Vec2 vb) {
      EdgeInfo& info = edges_.at(edge_key(a, b));
      if (info.nodes.empty()) {
        std::vector<int> ids;  // ordered from lo to hi
        const Vec2 xlo = a == info.lo ? xa : xb, xhi = a == info.lo ? xb : xa;
        const Vec2 vlo = a == info.lo ? va : vb, vhi = a == info.lo ? vb : va;
        for (int t = 1; t < k; ++t) {
          const double s = static_cast<double>(t) / k;
          ids.push_back(new_node(lerp(xlo, xhi, s), lerp(vlo, vhi, s), block));
        }
        edges_.at(edge_key(a, b)).nodes = ids;
      }
      std::vector<int> ids = edges_.at(edge_key(a, b)).nodes;
      if (a != edges_.at(edge_key(a, b)).lo) std::reverse(ids.begin(), ids.end());
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
      Elem ch;
      for (int q = 0; q < 3; ++q) ch.n[q] = lat.nodes[static_cast<std::size_t>(t[q])];
      ch.block = block;
      ch.level = 1;
      ch.parent = ei;
      ch.stress = stress;
      ch.last = {x_[ch.n[0]], x_[ch.n[1]], x_[ch.n[2]]};
      ch.mass = me / (k * k);
      for (int q = 0; q < 3; ++q) {
        const auto [i, j] = ij[static_cast<std::size_t>(t[q])];
        add.push_back({ch.n[q], ch.mass / 3.0, interp(vc, i, j)});
      }
      lat.children.push_back(static_cast<int>(elems_.size()));
      elems_.push_back(ch);
    }
    elem(ei).active = false;
    elem(ei).lattice = static_cast<int>(lattices_.size());
    lattices_.push_back(std::move(lat));
  }
  classify();
  held.resize(x_.size(), 0.0);
  // Coarse nodes that leave the coarse level mid-step take their pending
  // patch impulse with them.
  for (std::size_t i = 0; i < old_kind.size(); ++i)
    if (old_kind[i] == NodeKind::kCoarse && kind_[i] != NodeKind::kCoarse) {
      p[i] += iimp_[i] - (0.5 * dt_) * iface0_[i];
      iimp_[i] = Vec2{};
      iface0_[i] = Vec2{};
    }
  for (const Parcel& pc : add) {
    if (kind_[pc.node] == NodeKind::kHanging) {
      const int a = hang_a_[pc.node], b = hang_b_[pc.node];
      const double w = hang_w_[pc.node];
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
    if (old_kind[i] != NodeKind::kHanging || kind_[i] == NodeKind::kHanging) continue;
    const int a = old_a[i], b = old_b[i];
    const double w = old_w[i], h = held[i];
    const Vec2 vh = lerp(v_[a], v_[b], w);
    mm[a] -= (1.0 - w) * h;
    p[a] -= (1.0 - w) * h * v_[a];
    mm[b] -= w * h;
    p[b] -= w * h * v_[b];
    mm[i] += h;
    p[i] += h * vh;
  }
  m_ = lumped_masses();
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (kind_[i] == NodeKind::kHanging || kind_[i] == NodeKind::kDead) continue;
    if (std::fabs(mm[i] - m_[i]) > 1e-9 * std::max(1.0, m_[i]))
      throw SimulationError("cdem refine: mass bookkeeping broke at node " + std::to_string(i));
    if (!blocks_[node_block_[i]].fixed && m_[i] > 0.0) v_[i] = p[i] / m_[i];
  }
  finish_mesh_change();
  remap_change_ += kinetic_energy() + energy().strain - energy_before;
  refine_loss_ += total_before - energy().total();
}

// Deletes the subdivided elements of refined coarse elements: every child
// parcel returns to the parent's corners with the linear weights of its node
// (a momentum-conserving restriction); the parent's stress becomes the
// area-weighted mean of its children's.
void Model::unrefine(const std::vector<int>& parents) {
  if (parents.empty()) return;
  const double energy_before = kinetic_energy() + energy().strain;
  const double total_before = energy().total();
  const double kinetic_before = kinetic_energy();
  const bool match = opt_.patch_deletion == PatchDeletion::kEnergyMatched;
  std::vector<double> mm(x_.size(), 0.0);
  std::vector<Vec2> p(x_.size());
  for (std::size_t i = 0; i < x_.size(); ++i)
    if (kind_[i] != NodeKind::kHanging) {
      mm[i] = m_[i];
      p[i] = m_[i] * v_[i];
    }
  const std::vector<NodeKind> old_kind = kind_;
  for (int ei : parents) {
    Elem& parent = elem(ei);
    if (parent.active || parent.lattice < 0) continue;
    const Lattice lat = lattices_[static_cast<std::size_t>(parent.lattice)];
    const int k = lat.k;
    const std::array<int, 3> c = parent.n;
    Vec3 stress_sum = Vec3::Zero();
    double area_sum = 0.0;
    for (int chi : lat.children) {
      Elem& ch = elem(chi);
      const std::array<Vec2, 3> xc{x_[ch.n[0]], x_[ch.n[1]], x_[ch.n[2]]};
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
        if (kind_[f] == NodeKind::kHanging) {
          const int a = hang_a_[f], b = hang_b_[f];
          const double w = hang_w_[f];
          vel = lerp(v_[a], v_[b], w);
          mm[a] -= (1.0 - w) * share;
          p[a] -= (1.0 - w) * share * v_[a];
          mm[b] -= w * share;
          p[b] -= w * share * v_[b];
        } else {
          vel = v_[f];
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
    parent.last = {x_[c[0]], x_[c[1]], x_[c[2]]};
    if (match) {
      // PatchDeletion::kEnergyMatched, strain: the mean stress scaled so
      // that the parent's strain energy is its children's (capped).
      const Mat3& cm = c_[blocks_[parent.block].material];
      double fine_strain = 0.0;
      for (int chi : lat.children) {
        const Elem& ch = elem(chi);
        fine_strain += cst_strain_energy({x_[ch.n[0]], x_[ch.n[1]], x_[ch.n[2]]}, ch.stress, cm);
      }
      const double coarse_strain = cst_strain_energy({x_[c[0]], x_[c[1]], x_[c[2]]}, parent.stress, cm);
      if (coarse_strain > 0.0)
        parent.stress *= std::min(kMaxEnergyScale, std::sqrt(std::max(1.0, fine_strain / coarse_strain)));
    }
  }
  // Edge nodes: kept (as hanging) only where the other side is still refined.
  for (int ei : parents) {
    const std::array<int, 3> c = elem(ei).n;
    for (int q = 0; q < 3; ++q) {
      EdgeInfo& info = edges_.at(edge_key(c[q], c[(q + 1) % 3]));
      bool other_refined = false;
      for (int s : info.elems)
        if (s >= 0 && s != ei && !elem(s).active && elem(s).lattice >= 0) other_refined = true;
      if (!other_refined) info.nodes.clear();
    }
  }
  classify();
  // Nodes that became hanging hand their remaining parcels to the masters.
  for (std::size_t i = 0; i < old_kind.size(); ++i) {
    if (old_kind[i] == NodeKind::kHanging || kind_[i] != NodeKind::kHanging) continue;
    const int a = hang_a_[i], b = hang_b_[i];
    const double w = hang_w_[i];
    mm[a] += (1.0 - w) * mm[i];
    p[a] += (1.0 - w) * p[i];
    mm[b] += w * mm[i];
    p[b] += w * p[i];
    mm[i] = 0.0;
    p[i] = {};
  }
  m_ = lumped_masses();
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (kind_[i] == NodeKind::kHanging) continue;
    if (std::fabs(mm[i] - m_[i]) > 1e-9 * std::max(1.0, std::fabs(m_[i]) + std::fabs(mm[i])))
      throw SimulationError("cdem unrefine: mass bookkeeping broke at node " + std::to_string(i));
    if (kind_[i] == NodeKind::kDead) {
      v_[i] = {};
      continue;
    }
    if (!blocks_[node_block_[i]].fixed && m_[i] > 0.0) v_[i] = p[i] / m_[i];
  }
  if (match) {
    // PatchDeletion::kEnergyMatched, kinetic: the restricted velocities of
    // the parents' corners, per block, spread about their mass-weighted mean
    // v_bar by mu = sqrt(1 + deficit / K_dev) (capped), K_dev the kinetic
    // energy of the deviations: sum m (v_bar + mu (v - v_bar)) keeps the
    // momentum, and the kinetic energy grows by the restriction's deficit.
    double kinetic_after = 0.0;
    for (std::size_t i = 0; i < x_.size(); ++i)
      if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) kinetic_after += 0.5 * m_[i] * length_squared(v_[i]);
    double deficit = kinetic_before - kinetic_after;
    std::vector<int> corners;
    for (int ei : parents)
      for (int a : elem(ei).n)
        if ((kind_[a] == NodeKind::kCoarse || kind_[a] == NodeKind::kFine) && inv_m_[a] > 0.0 &&
            !blocks_[node_block_[a]].fixed && std::find(corners.begin(), corners.end(), a) == corners.end())
          corners.push_back(a);
    // the deficit shared among the blocks in proportion to their deviations' energy
    std::vector<double> mass(blocks_.size(), 0.0), k_dev(blocks_.size(), 0.0);
    std::vector<Vec2> mom(blocks_.size());
    for (int a : corners) {
      mass[node_block_[a]] += m_[a];
      mom[node_block_[a]] += m_[a] * v_[a];
    }
    for (int a : corners) {
      const int b = node_block_[a];
      k_dev[b] += 0.5 * m_[a] * length_squared(v_[a] - mom[b] / mass[b]);
    }
    double k_dev_sum = 0.0;
    for (double k : k_dev) k_dev_sum += k;
    if (deficit > 0.0 && k_dev_sum > 0.0)
      for (int a : corners) {
        const int b = node_block_[a];
        const double mu = std::min(kMaxEnergyScale, std::sqrt(1.0 + deficit / k_dev_sum));
        const Vec2 vbar = mom[b] / mass[b];
        v_[a] = vbar + mu * (v_[a] - vbar);
      }
  }
  finish_mesh_change();
  remap_change_ += kinetic_energy() + energy().strain - energy_before;
  deletion_loss_ += total_before - energy().total();
}

// At a touch (Sect. 5): the coarse elements of both blocks within c dt2 of
// the contact point are refined k x k (k fixed by the first touch from the
// element size h_e: k = ceil(h_e / (c dt2)), clamped), plus the coarse
// elements at the clone's nodes, so that the clone ties patch nodes; the
// touched edge (ea, eb, xi) is then located again among the new sub-edges.
void Model::refine_contact_zone(int m, Vec2 point, int& ea, int& eb, double& xi, TouchRecord& rec) {
  const int bm = node_block_[m], bt = node_block_[ea];
  const double rm = wave_speed_[blocks_[bm].material] * rec.dt2;
  const double rt = wave_speed_[blocks_[bt].material] * rec.dt2;
  const double eps = 1e-12 * (length(point) + 1.0);
  auto tri = [&](int e) { return std::array<Vec2, 3>{x_[elem(e).n[0]], x_[elem(e).n[1]], x_[elem(e).n[2]]}; };
  auto touches_node = [&](int e, std::initializer_list<int> nodes) {
    for (int a : elem(e).n)
      for (int b : nodes)
        if (a == b) return true;
    return false;
  };
  if (k_ == 0) {
    double he = 0.0;
    for (int e : coarse_elems_) {
      const int b = elem(e).block;
      if ((b == bm || b == bt) && point_triangle_distance(point, tri(e)) <= eps)
        he = std::max(he, std::sqrt(2.0 * cst(tri(e)).area));
    }
    const double r = std::min(rm, rt);
    int k = opt_.max_subdivision;
    if (r > 0.0 && he > 0.0) k = static_cast<int>(std::ceil(he / r - 1e-9));
    k_ = std::clamp(k, opt_.min_subdivision, opt_.max_subdivision);
    if (opt_.contact_point_mass > 0.0) {
      // CdemOptions::contact_point_mass (Sect. 4.1): the touching node's
      // lumped mass M becomes M / k^2 once its elements are refined k x k.
      const int km = std::max(opt_.min_subdivision,
                              static_cast<int>(std::ceil(std::sqrt(m_[m] / opt_.contact_point_mass) - 1e-9)));
      if (km > opt_.max_subdivision) {
        std::ostringstream msg;
        msg << "cdem: contact_point_mass " << opt_.contact_point_mass << " kg/m needs k = " << km
            << " for the touching node's mass " << m_[m] << " kg/m, above max_subdivision " << opt_.max_subdivision;
        throw SceneError(msg.str());
      }
      k_ = km;
    }
  }
  std::vector<int> set;
  for (int e : coarse_elems_) {
    const int b = elem(e).block;
    const double d = (b == bm || b == bt) ? point_triangle_distance(point, tri(e)) : 1e300;
    if ((b == bm && d <= rm + eps) || (b == bt && d <= rt + eps)) set.push_back(e);
  }
  rec.refined_elements = static_cast<int>(set.size());
  refine(set);
  for (int it = 0; it < 4; ++it) {
    if (!locate_edge(bt, point, ea, eb, xi)) throw SimulationError("cdem: touched block lost its boundary");
    std::vector<int> more;
    for (int e : coarse_elems_)
      for (int a : {m, ea, eb})
        if (kind_[a] == NodeKind::kCoarse && touches_node(e, {a})) more.push_back(e);
    if (more.empty()) break;
    rec.refined_elements += static_cast<int>(more.size());
    refine(more);
  }
  rec.subdivision = k_;
  rec.radius = std::max(rm, rt);
}

bool Model::dissolve_free_patches() {
  std::vector<int> parents;
  for (int i = 0; i < static_cast<int>(elems_.size()); ++i)
    if (!elems_[i].active && elems_[i].lattice >= 0) parents.push_back(i);
  if (parents.empty()) return false;
  // components: parents joined by shared coarse edges
  std::vector<int> root(parents.size());
  std::iota(root.begin(), root.end(), 0);
  std::function<int(int)> find = [&](int i) { return root[i] == i ? i : root[i] = find(root[i]); };
  for (std::size_t i = 0; i < parents.size(); ++i) {
    const Elem& e = elem(parents[i]);
    for (int q = 0; q < 3; ++q) {
      const EdgeInfo& info = edges_.at(edge_key(e.n[q], e.n[(q + 1) % 3]));
      for (int s : info.elems) {
        if (s < 0 || s == parents[i]) continue;
        const auto it = std::find(parents.begin(), parents.end(), s);
        if (it != parents.end()) root[find(static_cast<int>(i))] = find(static_cast<int>(it - parents.begin()));
      }
    }
  }
  std::vector<char> busy(x_.size(), 0);
  for (const Clone& c : clones_) {
    busy[c.main] = 1;
    busy[c.ea] = 1;
    busy[c.eb] = 1;
    for (int a : c.t)
      if (a >= 0) busy[a] = 1;
  }
  std::vector<char> keep(parents.size(), 0);
  for (std::size_t i = 0; i < parents.size(); ++i) {
    const Lattice& lat = lattices_[static_cast<std::size_t>(elem(parents[i]).lattice)];
    for (int n : lat.nodes)
      if (busy[n]) keep[static_cast<std::size_t>(find(static_cast<int>(i)))] = 1;
  }
  std::vector<int> go;
  for (std::size_t i = 0; i < parents.size(); ++i)
    if (!keep[static_cast<std::size_t>(find(static_cast<int>(i)))]) go.push_back(parents[i]);
  if (go.empty()) return false;
  unrefine(go);
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
void Model::patch_loop(double t0, double t1, std::vector<Touch> coarse_touches) {
  std::sort(coarse_touches.begin(), coarse_touches.end(), [](const Touch& a, const Touch& b) { return a.s < b.s; });
  if (patch_eval_.empty() && coarse_touches.empty()) return;
  std::size_t next = 0;
  auto event_time = [&](std::size_t i) { return t0 + coarse_touches[i].s * dt_; };
  const double eps_t = 1e-12 * dt_;
  double t = t0;
  sync_positions(t);
  if (!patch_eval_.empty()) compute_patch_forces(t);
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
    const Vec2 e = x_[T.eb] - x_[T.ea];
    return cross(x_[T.node] - x_[T.ea], e) / length(e);
  };
  while (true) {
    bool changed = false;
    while (next < coarse_touches.size() && event_time(next) <= t + eps_t) {
      const Touch& T = coarse_touches[next++];
      if (kind_[T.node] != NodeKind::kCoarse || kind_[T.ea] != NodeKind::kCoarse || kind_[T.eb] != NodeKind::kCoarse)
        continue;  // now inside a patch: the patch detection finds it
      changed = process_touch(T, false, t, t0, t1) || changed;
    }
    for (const Touch& T : pending) changed = process_touch(T, true, t, t0, t1) || changed;
    pending.clear();
    if (changed && !patch_eval_.empty()) compute_patch_forces(t);
    if (t >= t1 - eps_t) break;
    double h = std::min(dt_ / substeps_, t1 - t);
    if (next < coarse_touches.size()) h = std::min(h, event_time(next) - t);
    h = std::max(h, 0.0);
    if (patch_eval_.empty()) {
      t += h;
      sync_positions(t);
      continue;
    }
    kick_patch(0.5 * h);
    // The drift over [t, t + h], split at the touches on its path.
    double tau = 0.0;  // fraction of h drifted
    long groups = 0;
    while (true) {
      p0 = x_;
      p1 = x_;
      for (int n : fine_dofs_) p1[n] = x_[n] + ((1.0 - tau) * h) * v_[n];
      for (int n : coarse_dofs_) p1[n] = xs_[n] + (t + h - step_t0_) * v_[n];
      // released_at_ is compared with the step start: a node released at the
      // last force evaluation touches again from the next patch step.
      const std::vector<Touch> found = find_touches(false, t, p0, p1);
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
      for (int n : fine_dofs_) x_[n] += hs * v_[n];
      tau += smin * (1.0 - tau);
      const double te = t + tau * h;
      sync_positions(te);
      bool any = false;
      for (const Touch& T : group) any = process_touch(T, true, te, t0, t1) || any;
      // A group that nothing was done for is found again at once; so is a
      // contact that does not let the drift advance.
      if ((!any && smin <= 0.0) || ++groups > kMaxStalls) {
        const Touch& T = group.front();
        std::ostringstream msg;
        msg << "cdem: patch step stalled at t = " << te << " s (step " << steps_ + 1 << "): node " << T.node
            << " of block " << node_block_[T.node] << " touches block " << node_block_[T.ea] << " again at once "
            << "(depth " << std::max(0.0, -signed_gap(T)) << " m, " << groups << " touch groups in this patch step); "
            << "the contact cannot be resolved: try a smaller dt or friction > 0";
        throw ContactError(msg.str(), T.node, node_block_[T.node], node_block_[T.ea], steps_ + 1, te,
                           std::max(0.0, -signed_gap(T)));
      }
    }
    for (int n : fine_dofs_) x_[n] += ((1.0 - tau) * h) * v_[n];
    t += h;
    sync_positions(t);
    compute_patch_forces(t);
    kick_patch(0.5 * h);
    ++substeps_taken_;
  }
}

}  // namespace dda::cdem
