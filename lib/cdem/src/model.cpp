#include "dda/cdem/model.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <sstream>

#include "dda/cdem/mesh.hpp"
#include "dda/polygon.hpp"

namespace dda::cdem {

namespace {

constexpr double kPi = 3.14159265358979323846;

[[noreturn]] void scene_fail(const std::string& where, const std::string& why) { throw SceneError(where + ": " + why); }

bool positive_finite(double x) { return std::isfinite(x) && x > 0.0; }

// Shape-function derivatives of a constant-strain triangle (CCW x0, x1, x2):
// dN_i/dx = b_i / (2A), dN_i/dy = c_i / (2A).
struct Cst {
  double area = 0.0;
  std::array<double, 3> b{}, c{};
};

Cst cst(const std::array<Vec2, 3>& x) {
  Cst g;
  g.b = {x[1].y - x[2].y, x[2].y - x[0].y, x[0].y - x[1].y};
  g.c = {x[2].x - x[1].x, x[0].x - x[2].x, x[1].x - x[0].x};
  g.area = 0.5 * cross(x[1] - x[0], x[2] - x[0]);
  return g;
}

// Element stiffness A B^T D B (6 x 6, DOFs x0 y0 x1 y1 x2 y2).
Eigen::Matrix<double, 6, 6> element_stiffness(const std::array<Vec2, 3>& x, const Mat3& d) {
  const Cst g = cst(x);
  Eigen::Matrix<double, 3, 6> b = Eigen::Matrix<double, 3, 6>::Zero();
  const double s = 1.0 / (2.0 * g.area);
  for (int i = 0; i < 3; ++i) {
    b(0, 2 * i) = g.b[i] * s;
    b(1, 2 * i + 1) = g.c[i] * s;
    b(2, 2 * i) = g.c[i] * s;
    b(2, 2 * i + 1) = g.b[i] * s;
  }
  return g.area * b.transpose() * d * b;
}

double point_segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 e = b - a;
  const double l2 = length_squared(e);
  const double t = l2 > 0.0 ? std::clamp(dot(p - a, e) / l2, 0.0, 1.0) : 0.0;
  return distance(p, a + t * e);
}

double point_triangle_distance(Vec2 p, const std::array<Vec2, 3>& x) {
  const bool inside =
      cross(x[1] - x[0], p - x[0]) >= 0.0 && cross(x[2] - x[1], p - x[1]) >= 0.0 && cross(x[0] - x[2], p - x[2]) >= 0.0;
  if (inside) return 0.0;
  return std::min({point_segment_distance(p, x[0], x[1]), point_segment_distance(p, x[1], x[2]),
                   point_segment_distance(p, x[2], x[0])});
}

// Touch of a node moving p0 -> p1 with the edge a0 -> a1, b0 -> b1 over one
// interval (all motions linear in s in [0, 1]): the collision path of
// Paper B Sect. 3. G(s) = cross(p - a, b - a) is the signed gap times the
// edge length (positive on the outer side of a CCW boundary edge) and is
// quadratic in s. A candidate ends the interval closer than tol; the touch
// is the first s where G = 0 with the foot of the node inside the edge.
// A node that starts on or up to tol behind the edge and approaches touches
// at s = 0.
bool swept_touch(Vec2 p0, Vec2 p1, Vec2 a0, Vec2 a1, Vec2 b0, Vec2 b1, double tol, double& s_out, double& xi_out) {
  const Vec2 w0 = p0 - a0, dw = (p1 - a1) - w0;
  const Vec2 e0 = b0 - a0, de = (b1 - a1) - e0;
  const double c0 = cross(w0, e0);
  const double c1 = cross(w0, de) + cross(dw, e0);
  const double c2 = cross(dw, de);
  const double l0 = length(e0), l1 = length(e0 + de);
  if (!(l0 > 0.0) || !(l1 > 0.0)) return false;
  const double gap0 = c0 / l0;
  const double gap1 = (c0 + c1 + c2) / l1;
  if (gap1 >= tol) return false;  // not within the contact tolerance at the end
  auto foot = [&](double s) {
    const Vec2 w = w0 + s * dw, e = e0 + s * de;
    return dot(w, e) / length_squared(e);
  };
  constexpr double kFootSlack = 1e-9;
  auto on_edge = [&](double xi) { return xi >= -kFootSlack && xi <= 1.0 + kFootSlack; };
  double s = -1.0;
  if (gap0 <= 0.0) {
    if (gap0 < -tol) return false;                 // behind the edge: not this edge's node
    if (!(c1 < 0.0 || gap1 < gap0)) return false;  // not approaching
    s = 0.0;
  } else {
    // smallest root of c0 + c1 s + c2 s^2 in (0, 1]
    const double scale = std::fabs(c0) + std::fabs(c1) + std::fabs(c2);
    if (std::fabs(c2) <= 1e-12 * scale) {
      if (!(c1 < 0.0)) return false;
      s = -c0 / c1;
    } else {
      const double disc = c1 * c1 - 4.0 * c2 * c0;
      if (disc < 0.0) return false;
      const double q = -0.5 * (c1 + std::copysign(std::sqrt(disc), c1));
      double r1 = q / c2, r2 = q != 0.0 ? c0 / q : 2.0;
      if (r1 > r2) std::swap(r1, r2);
      if (r1 > 0.0 && r1 <= 1.0)
        s = r1;
      else if (r2 > 0.0 && r2 <= 1.0)
        s = r2;
      else
        return false;
    }
    if (!(s > 0.0 && s <= 1.0 + 1e-12)) return false;
    s = std::min(s, 1.0);
  }
  const double xi = foot(s);
  if (!on_edge(xi)) return false;
  s_out = s;
  xi_out = std::clamp(xi, 0.0, 1.0);
  return true;
}

}  // namespace

// ---------------------------------------------------------------------------
// Scene conversion and set-up
// ---------------------------------------------------------------------------

CdemScene from_dda_scene(const dda::Scene& scene, int divisions, const CdemOptions& options) {
  CdemScene s;
  s.name = scene.name;
  s.materials = scene.materials;
  s.gravity = scene.gravity;
  s.dt = scene.dt;
  s.duration = scene.duration;
  s.options = options;
  for (const BlockSpec& b : scene.blocks) {
    CdemBlock c;
    c.outline = b.vertices;
    c.divisions = divisions;
    c.velocity = b.velocity;
    c.fixed = b.fixed;
    c.material = b.material;
    c.name = b.name;
    if (b.spin != 0.0) throw SceneError("from_dda_scene: initial spin is not supported by the CDEM model");
    s.blocks.push_back(std::move(c));
  }
  return s;
}

Model::Model(const CdemScene& scene) : scene_(scene), opt_(scene.options) { build(scene); }

void Model::build(const CdemScene& scene) {
  if (!positive_finite(scene.dt)) scene_fail("dt", "must be a positive finite time step");
  if (!(std::isfinite(scene.duration) && scene.duration >= 0.0)) scene_fail("duration", "must be finite and >= 0");
  if (!is_finite(scene.gravity)) scene_fail("gravity", "must be finite");
  if (!positive_finite(opt_.tolerance)) scene_fail("options.tolerance", "must be positive");
  if (!(std::isfinite(opt_.strength.tensile) && opt_.strength.tensile >= 0.0))
    scene_fail("options.strength.tensile", "must be >= 0");
  if (!(std::isfinite(opt_.strength.cohesion) && opt_.strength.cohesion >= 0.0))
    scene_fail("options.strength.cohesion", "must be >= 0");
  if (!(std::isfinite(opt_.strength.friction_deg) && opt_.strength.friction_deg >= 0.0 &&
        opt_.strength.friction_deg < 90.0))
    scene_fail("options.strength.friction_deg", "must lie in [0, 90)");
  if (opt_.min_subdivision < 1 || opt_.max_subdivision < opt_.min_subdivision || opt_.max_subdivision > 64)
    scene_fail("options.min/max_subdivision", "need 1 <= min <= max <= 64");
  if (!(opt_.substep_safety > 0.0 && opt_.substep_safety <= 1.0))
    scene_fail("options.substep_safety", "must lie in (0, 1]");
  if (!(std::isfinite(opt_.mass_damping) && opt_.mass_damping >= 0.0))
    scene_fail("options.mass_damping", "must be >= 0");
  if (scene.materials.empty()) scene_fail("materials", "at least one material is needed");
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    const std::string f = "materials[" + std::to_string(i) + "]";
    if (!positive_finite(m.density)) scene_fail(f + ".density", "must be positive");
    if (!positive_finite(m.young)) scene_fail(f + ".young", "must be positive");
    if (!(std::isfinite(m.poisson) && m.poisson > -1.0 && m.poisson < 0.5))
      scene_fail(f + ".poisson", "must lie in (-1, 0.5)");
    d_.push_back(elastic_matrix(m.young, m.poisson));
    c_.push_back(d_.back().inverse());
    wave_speed_.push_back(std::sqrt(m.young / m.density));
  }
  dt_ = scene.dt;

  for (std::size_t bi = 0; bi < scene.blocks.size(); ++bi) {
    const CdemBlock& cb = scene.blocks[bi];
    const std::string f = "blocks[" + std::to_string(bi) + "]";
    const PolygonCheck check = validate_polygon(cb.outline.data(), static_cast<int>(cb.outline.size()));
    if (!check.ok())
      scene_fail(f + ".outline" + (check.vertex >= 0 ? "[" + std::to_string(check.vertex) + "]" : ""),
                 describe(check.fault));
    if (cb.divisions < 1 || cb.divisions > 64) scene_fail(f + ".divisions", "must lie in [1, 64]");
    if (cb.material < 0 || cb.material >= static_cast<int>(scene.materials.size()))
      scene_fail(f + ".material", "no such material");
    if (!is_finite(cb.velocity)) scene_fail(f + ".velocity", "must be finite");
    const TriMesh mesh = mesh_convex_polygon(cb.outline, cb.divisions);
    Block blk;
    blk.material = cb.material;
    blk.fixed = cb.fixed;
    const int base = static_cast<int>(x_.size());
    for (const Vec2& p : mesh.nodes) {
      blk.nodes.push_back(static_cast<int>(x_.size()));
      x_.push_back(p);
      v_.push_back(cb.fixed ? Vec2{} : cb.velocity);
      node_block_.push_back(static_cast<int>(bi));
    }
    for (int i = 0; i < static_cast<int>(cb.outline.size()); ++i) blk.outline.push_back(base + i);
    const double rho = scene.materials[static_cast<std::size_t>(cb.material)].density;
    for (const auto& t : mesh.triangles) {
      Elem e;
      e.n = {base + t[0], base + t[1], base + t[2]};
      e.block = static_cast<int>(bi);
      e.last = {x_[e.n[0]], x_[e.n[1]], x_[e.n[2]]};
      const double a = cst(e.last).area;
      if (!(a > 0.0)) scene_fail(f, "meshing produced a degenerate triangle");
      e.mass = rho * a;
      elems_.push_back(e);
    }
    blocks_.push_back(std::move(blk));
  }
  const std::size_t n = x_.size();
  xs_ = x_;
  f_.assign(n, Vec2{});
  iface_.assign(n, Vec2{});
  iimp_.assign(n, Vec2{});
  iface0_.assign(n, Vec2{});
  released_at_.assign(n, -std::numeric_limits<double>::infinity());
  scratch_.assign(n, Vec2{});
  kind_.assign(n, NodeKind::kCoarse);
  hang_a_.assign(n, -1);
  hang_b_.assign(n, -1);
  hang_w_.assign(n, 0.0);
  clone_count_.assign(n, 0);

  // Coarse edges: adjacency and outline.
  for (int ei = 0; ei < static_cast<int>(elems_.size()); ++ei) {
    const Elem& e = elems_[ei];
    for (int k = 0; k < 3; ++k) {
      const int a = e.n[k], b = e.n[(k + 1) % 3];
      EdgeInfo& info = edges_[edge_key(a, b)];
      info.lo = std::min(a, b);
      info.hi = std::max(a, b);
      if (info.elems[0] < 0)
        info.elems[0] = ei;
      else
        info.elems[1] = ei;
    }
  }
  for (int ei = 0; ei < static_cast<int>(elems_.size()); ++ei) {
    const Elem& e = elems_[ei];
    for (int k = 0; k < 3; ++k) {
      const int a = e.n[k], b = e.n[(k + 1) % 3];
      if (edges_.at(edge_key(a, b)).elems[1] < 0) {
        coarse_bedges_.push_back({a, b, e.block, false});
        coarse_bedge_elem_.push_back(ei);
      }
    }
  }
  classify();
  rebuild_lists();
  rebuild_boundary();
  m_ = lumped_masses();
  inv_m_.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) inv_m_[i] = (blocks_[node_block_[i]].fixed || !(m_[i] > 0.0)) ? 0.0 : 1.0 / m_[i];
  for (Block& b : blocks_) b.initial_mean = block_mean_position(static_cast<int>(&b - blocks_.data()));

  compute_critical_steps();
  if (opt_.check_stability && dt_ > critical_dt_) {
    std::ostringstream s;
    s << "time step " << dt_ << " s exceeds the critical step " << critical_dt_
      << " s of the coarse mesh (2/omega_max; element bound " << element_critical_dt_
      << " s): use a smaller dt or coarser elements (Paper B Sect. 5: c dt < element length)";
    scene_fail("dt", s.str());
  }
  compute_coarse_forces();
}

std::uint64_t Model::edge_key(int a, int b) const {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b)), hi = static_cast<std::uint64_t>(std::max(a, b));
  return (lo << 32) | hi;
}

double Model::element_omega_max(const Elem& e) const {
  const std::array<Vec2, 3> x{x_[e.n[0]], x_[e.n[1]], x_[e.n[2]]};
  const auto k = element_stiffness(x, d_[blocks_[e.block].material]);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> es(k, Eigen::EigenvaluesOnly);
  const double lambda = es.eigenvalues().maxCoeff();
  return std::sqrt(std::max(lambda, 0.0) / (e.mass / 3.0));
}

void Model::compute_critical_steps() {
  double omega_elem = 0.0;
  for (int e : coarse_elems_) omega_elem = std::max(omega_elem, element_omega_max(elem(e)));
  element_critical_dt_ = omega_elem > 0.0 ? 2.0 / omega_elem : std::numeric_limits<double>::infinity();
  // Power iteration on M^-1/2 K M^-1/2 of the assembled coarse mesh.
  const std::size_t n = x_.size();
  std::vector<Vec2> z(n), y(n), u(n);
  std::uint64_t seed = 0x9E3779B97F4A7C15ull;
  auto rnd = [&] {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(seed >> 11) / 9007199254740992.0 - 0.5;
  };
  for (std::size_t i = 0; i < n; ++i) z[i] = inv_m_[i] > 0.0 ? Vec2{rnd(), rnd()} : Vec2{};
  double lambda = 0.0;
  for (int it = 0; it < 400; ++it) {
    double zz = 0.0;
    for (std::size_t i = 0; i < n; ++i) zz += length_squared(z[i]);
    if (!(zz > 0.0)) break;
    for (std::size_t i = 0; i < n; ++i) {
      z[i] = z[i] / std::sqrt(zz);
      u[i] = std::sqrt(inv_m_[i]) * z[i];
      y[i] = Vec2{};
    }
    for (int ei : coarse_elems_) {
      const Elem& e = elem(ei);
      if (blocks_[e.block].fixed) continue;
      const std::array<Vec2, 3> x{x_[e.n[0]], x_[e.n[1]], x_[e.n[2]]};
      const auto k = element_stiffness(x, d_[blocks_[e.block].material]);
      Eigen::Matrix<double, 6, 1> ue;
      for (int a = 0; a < 3; ++a) {
        ue(2 * a) = u[e.n[a]].x;
        ue(2 * a + 1) = u[e.n[a]].y;
      }
      const Eigen::Matrix<double, 6, 1> fe = k * ue;
      for (int a = 0; a < 3; ++a) y[e.n[a]] += Vec2{fe(2 * a), fe(2 * a + 1)};
    }
    lambda = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      y[i] = std::sqrt(inv_m_[i]) * y[i];
      lambda += dot(z[i], y[i]);
    }
    z = y;
  }
  critical_dt_ = lambda > 0.0 ? 2.0 / std::sqrt(lambda) : std::numeric_limits<double>::infinity();
}

// ---------------------------------------------------------------------------
// Topology: node classes, lists, boundary, masses
// ---------------------------------------------------------------------------

void Model::classify() {
  const std::size_t n = x_.size();
  std::vector<int> cc(n, 0), fc(n, 0);
  for (const Elem& e : elems_) {
    if (!e.active) continue;
    for (int a : e.n) (e.level == 0 ? cc : fc)[a] += 1;
  }
  std::vector<char> hang(n, 0);
  for (auto& kv : edges_) {
    EdgeInfo& ei = kv.second;
    if (ei.nodes.empty()) continue;
    int refined = 0, coarse = 0;
    for (int s : ei.elems) {
      if (s < 0) continue;
      const Elem& e = elem(s);
      if (e.active)
        ++coarse;
      else if (e.lattice >= 0)
        ++refined;
    }
    if (refined == 1 && coarse == 1) {
      const int k = static_cast<int>(ei.nodes.size()) + 1;
      for (int t = 1; t < k; ++t) {
        const int h = ei.nodes[static_cast<std::size_t>(t - 1)];
        hang[h] = 1;
        hang_a_[h] = ei.lo;
        hang_b_[h] = ei.hi;
        hang_w_[h] = static_cast<double>(t) / k;
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (hang[i])
      kind_[i] = NodeKind::kHanging;
    else if (fc[i] > 0)
      kind_[i] = NodeKind::kFine;
    else if (cc[i] > 0)
      kind_[i] = NodeKind::kCoarse;
    else
      kind_[i] = NodeKind::kDead;
  }
}

void Model::rebuild_lists() {
  coarse_elems_.clear();
  fine_elems_.clear();
  coarse_eval_.clear();
  patch_eval_.clear();
  for (int i = 0; i < static_cast<int>(elems_.size()); ++i) {
    const Elem& e = elems_[i];
    if (!e.active) continue;
    (e.level == 0 ? coarse_elems_ : fine_elems_).push_back(i);
    bool fine_corner = e.level > 0;
    for (int a : e.n) fine_corner = fine_corner || kind_[a] == NodeKind::kFine;
    (fine_corner ? patch_eval_ : coarse_eval_).push_back(i);
  }
  coarse_dofs_.clear();
  fine_dofs_.clear();
  hanging_.clear();
  for (int i = 0; i < static_cast<int>(x_.size()); ++i) {
    if (kind_[i] == NodeKind::kHanging) {
      hanging_.push_back(i);
      continue;
    }
    if (blocks_[node_block_[i]].fixed) continue;
    if (kind_[i] == NodeKind::kCoarse)
      coarse_dofs_.push_back(i);
    else if (kind_[i] == NodeKind::kFine)
      fine_dofs_.push_back(i);
  }
}

void Model::rebuild_boundary() {
  bedges_.clear();
  for (std::size_t i = 0; i < coarse_bedges_.size(); ++i) {
    const BEdge& ce = coarse_bedges_[i];
    const Elem& e = elem(coarse_bedge_elem_[i]);
    if (e.active) {
      bedges_.push_back(ce);
      continue;
    }
    const EdgeInfo& ei = edges_.at(edge_key(ce.a, ce.b));
    std::vector<int> seq{ce.a};
    if (ce.a == ei.lo)
      seq.insert(seq.end(), ei.nodes.begin(), ei.nodes.end());
    else
      seq.insert(seq.end(), ei.nodes.rbegin(), ei.nodes.rend());
    seq.push_back(ce.b);
    for (std::size_t k = 0; k + 1 < seq.size(); ++k) bedges_.push_back({seq[k], seq[k + 1], ce.block, true});
  }
  block_bedges_.assign(blocks_.size(), {});
  for (std::size_t i = 0; i < bedges_.size(); ++i)
    block_bedges_[static_cast<std::size_t>(bedges_[i].block)].push_back(static_cast<int>(i));
  std::vector<char> seen(x_.size(), 0);
  bnodes_.clear();
  for (const BEdge& b : bedges_)
    for (int v : {b.a, b.b})
      if (!seen[v]) {
        seen[v] = 1;
        bnodes_.push_back(v);
      }
}

std::vector<double> Model::lumped_masses() const {
  std::vector<double> s(x_.size(), 0.0);
  for (const Elem& e : elems_)
    if (e.active)
      for (int a : e.n) s[a] += e.mass / 3.0;
  for (int h = 0; h < static_cast<int>(x_.size()); ++h) {
    if (kind_[h] != NodeKind::kHanging) continue;
    s[hang_a_[h]] += (1.0 - hang_w_[h]) * s[h];
    s[hang_b_[h]] += hang_w_[h] * s[h];
    s[h] = 0.0;
  }
  return s;
}

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
        int id;
        if (i == 0 && j == 0)
          id = c[0];
        else if (i == k)
          id = c[1];
        else if (j == k)
          id = c[2];
        else if (j == 0)
          id = e01[static_cast<std::size_t>(i - 1)];
        else if (i == 0)
          id = e02[static_cast<std::size_t>(j - 1)];
        else if (i + j == k)
          id = e12[static_cast<std::size_t>(j - 1)];
        else
          id = new_node(interp(xc, i, j), interp(vc, i, j), block);
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
  for (std::size_t i = 0; i < x_.size(); ++i)
    inv_m_[i] = (blocks_[node_block_[i]].fixed || !(m_[i] > 0.0) || kind_[i] == NodeKind::kHanging) ? 0.0 : 1.0 / m_[i];
  rebuild_lists();
  rebuild_boundary();
  update_substeps();
  for (int h : hanging_) {
    x_[h] = lerp(x_[hang_a_[h]], x_[hang_b_[h]], hang_w_[h]);
    v_[h] = lerp(v_[hang_a_[h]], v_[hang_b_[h]], hang_w_[h]);
  }
  remap_change_ += kinetic_energy() + energy().strain - energy_before;
}

// Deletes the subdivided elements of refined coarse elements: every child
// parcel returns to the parent's corners with the linear weights of its node
// (a momentum-conserving restriction); the parent's stress becomes the
// area-weighted mean of its children's.
void Model::unrefine(const std::vector<int>& parents) {
  if (parents.empty()) return;
  const double energy_before = kinetic_energy() + energy().strain;
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
  for (std::size_t i = 0; i < x_.size(); ++i)
    inv_m_[i] = (blocks_[node_block_[i]].fixed || !(m_[i] > 0.0) || kind_[i] == NodeKind::kHanging) ? 0.0 : 1.0 / m_[i];
  rebuild_lists();
  rebuild_boundary();
  update_substeps();
  for (int h : hanging_) {
    x_[h] = lerp(x_[hang_a_[h]], x_[hang_b_[h]], hang_w_[h]);
    v_[h] = lerp(v_[hang_a_[h]], v_[hang_b_[h]], hang_w_[h]);
  }
  remap_change_ += kinetic_energy() + energy().strain - energy_before;
}

// ---------------------------------------------------------------------------
// Kinematics and forces
// ---------------------------------------------------------------------------

void Model::sync_positions(double t) {
  const double tau = t - step_t0_;
  for (int n : coarse_dofs_) x_[n] = xs_[n] + tau * v_[n];
  for (int h : hanging_) {
    x_[h] = lerp(x_[hang_a_[h]], x_[hang_b_[h]], hang_w_[h]);
    v_[h] = lerp(v_[hang_a_[h]], v_[hang_b_[h]], hang_w_[h]);
  }
}

void Model::add_node_force(int n, Vec2 f, bool patch_eval) {
  if (kind_[n] == NodeKind::kHanging) {
    add_node_force(hang_a_[n], (1.0 - hang_w_[n]) * f, patch_eval);
    add_node_force(hang_b_[n], hang_w_[n] * f, patch_eval);
    return;
  }
  if (patch_eval && kind_[n] == NodeKind::kCoarse)
    iface_[n] += f;
  else
    f_[n] += f;
}

// Incremental CST force (Paper B Eqs. 2-3): strain increment from the
// displacement since the last evaluation with B of the mid configuration,
// stress rotated by the element's incremental rotation and incremented with
// D d_eps; nodal forces -A B^T sigma with B of the current configuration.
void Model::element_force(Elem& e, bool patch_eval) {
  const std::array<Vec2, 3> x{x_[e.n[0]], x_[e.n[1]], x_[e.n[2]]};
  std::array<Vec2, 3> du, mid;
  bool moved = false;
  for (int i = 0; i < 3; ++i) {
    du[i] = x[i] - e.last[i];
    mid[i] = 0.5 * (x[i] + e.last[i]);
    moved = moved || du[i] != Vec2{};
  }
  if (moved) {
    const Cst g = cst(mid);
    if (!(g.area > 0.0)) {
      std::ostringstream s;
      s << "cdem: element of block " << e.block << " inverted at t = " << time_ << " (step " << steps_ << ")";
      throw SimulationError(s.str());
    }
    const double r = 1.0 / (2.0 * g.area);
    double exx = 0.0, eyy = 0.0, gxy = 0.0, rot = 0.0;
    for (int i = 0; i < 3; ++i) {
      exx += g.b[i] * du[i].x;
      eyy += g.c[i] * du[i].y;
      gxy += g.c[i] * du[i].x + g.b[i] * du[i].y;
      rot += g.b[i] * du[i].y - g.c[i] * du[i].x;
    }
    exx *= r;
    eyy *= r;
    gxy *= r;
    rot *= 0.5 * r;
    if (rot != 0.0) {
      const double cs = std::cos(rot), sn = std::sin(rot);
      const double sxx = e.stress[0], syy = e.stress[1], sxy = e.stress[2];
      e.stress[0] = cs * cs * sxx - 2.0 * cs * sn * sxy + sn * sn * syy;
      e.stress[1] = sn * sn * sxx + 2.0 * cs * sn * sxy + cs * cs * syy;
      e.stress[2] = cs * sn * (sxx - syy) + (cs * cs - sn * sn) * sxy;
    }
    e.stress += d_[blocks_[e.block].material] * Vec3(exx, eyy, gxy);
    e.last = x;
  }
  const Cst g = cst(x);
  if (!(g.area > 0.0)) {
    std::ostringstream s;
    s << "cdem: element of block " << e.block << " inverted at t = " << time_ << " (step " << steps_ << ")";
    throw SimulationError(s.str());
  }
  for (int i = 0; i < 3; ++i) {
    const Vec2 f{-0.5 * (g.b[i] * e.stress[0] + g.c[i] * e.stress[2]),
                 -0.5 * (g.b[i] * e.stress[2] + g.c[i] * e.stress[1])};
    add_node_force(e.n[i], f, patch_eval);
  }
}

void Model::compute_coarse_forces() {
  const Vec2 g = scene_.gravity;
  for (int n : coarse_dofs_) f_[n] = m_[n] * g - opt_.mass_damping * m_[n] * v_[n];
  for (int e : coarse_eval_)
    if (!blocks_[elem(e).block].fixed) element_force(elem(e), false);
  solve_clones(false, time_);
}

void Model::compute_patch_forces(double t) {
  const Vec2 g = scene_.gravity;
  for (int n : fine_dofs_) f_[n] = m_[n] * g - opt_.mass_damping * m_[n] * v_[n];
  for (int n : coarse_dofs_) iface_[n] = Vec2{};
  for (int e : patch_eval_)
    if (!blocks_[elem(e).block].fixed) element_force(elem(e), true);
  solve_clones(true, t);
}

void Model::kick_patch(double h) {
  for (int n : fine_dofs_) v_[n] += (h * inv_m_[n]) * f_[n];
  for (int n : coarse_dofs_) iimp_[n] += h * iface_[n];
}

// ---------------------------------------------------------------------------
// Clone nodes (Paper B Sect. 4)
// ---------------------------------------------------------------------------

bool Model::in_clone(int node) const { return clone_count_[node] > 0; }

std::vector<int> Model::clone_component(int ci) const {
  std::vector<int> comp{ci};
  std::vector<char> in(clones_.size(), 0);
  in[static_cast<std::size_t>(ci)] = 1;
  auto nodes_of = [&](const Clone& c) {
    std::vector<int> n{c.main};
    for (int q = 0; q < 2; ++q)
      if (c.t[q] >= 0 && c.w[q] != 0.0) n.push_back(c.t[q]);
    return n;
  };
  for (std::size_t head = 0; head < comp.size(); ++head) {
    const std::vector<int> a = nodes_of(clones_[static_cast<std::size_t>(comp[head])]);
    for (std::size_t j = 0; j < clones_.size(); ++j) {
      if (in[j] || clones_[j].fine != clones_[static_cast<std::size_t>(ci)].fine) continue;
      const std::vector<int> b = nodes_of(clones_[j]);
      bool share = false;
      for (int x : a)
        for (int y : b) share = share || x == y;
      if (share) {
        in[j] = 1;
        comp.push_back(static_cast<int>(j));
      }
    }
  }
  return comp;
}

// Perfectly inelastic impact (Eq. 4): the velocities of the clone's nodes
// are projected onto the tie (main = sum w_q target_q) with the impulse
// that conserves momentum; coupled clones (sharing nodes) are projected
// together by Gauss-Seidel. Returns the kinetic energy lost (Eq. 5).
double Model::project_component(int ci) {
  const std::vector<int> comp = clone_component(ci);
  std::vector<int> nodes;
  for (int c : comp) {
    const Clone& cl = clones_[static_cast<std::size_t>(c)];
    nodes.push_back(cl.main);
    for (int q = 0; q < 2; ++q)
      if (cl.t[q] >= 0 && cl.w[q] != 0.0) nodes.push_back(cl.t[q]);
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  auto ke = [&] {
    double e = 0.0, vmax = 0.0;
    for (int n : nodes) {
      e += 0.5 * m_[n] * length_squared(v_[n]);
      vmax = std::max(vmax, length(v_[n]));
    }
    return std::make_pair(e, vmax);
  };
  const auto [before, vscale] = ke();
  for (int it = 0; it < 500; ++it) {
    double worst = 0.0;
    for (int c : comp) {
      const Clone& cl = clones_[static_cast<std::size_t>(c)];
      Vec2 r = v_[cl.main];
      double w = inv_m_[cl.main];
      for (int q = 0; q < 2; ++q)
        if (cl.t[q] >= 0 && cl.w[q] != 0.0) {
          r -= cl.w[q] * v_[cl.t[q]];
          w += cl.w[q] * cl.w[q] * inv_m_[cl.t[q]];
        }
      if (!(w > 0.0)) continue;
      worst = std::max(worst, length(r));
      const Vec2 j = -(1.0 / w) * r;
      v_[cl.main] += inv_m_[cl.main] * j;
      for (int q = 0; q < 2; ++q)
        if (cl.t[q] >= 0 && cl.w[q] != 0.0) v_[cl.t[q]] -= (cl.w[q] * inv_m_[cl.t[q]]) * j;
    }
    if (worst <= 1e-14 * (vscale + 1e-300)) break;
  }
  return before - ke().first;
}

// Interaction forces of the clone nodes (Eq. 11) at the current forces f_:
// the force on each main node that gives it the acceleration of the point
// it is tied to, solved by Gauss-Seidel over coupled clones. Then the
// separation criteria: tension beyond sigma_t A_c (Eq. 6) removes the clone
// and its forces; shear beyond F_n tan(phi) + c A_c (Eqs. 7-9) limits the
// shear force to that value (Eq. 10) for this evaluation and removes the
// clone after it. The resulting forces are added to f_.
void Model::solve_clones(bool fine, double t) {
  std::vector<int> ids;
  for (int i = 0; i < static_cast<int>(clones_.size()); ++i)
    if (clones_[static_cast<std::size_t>(i)].fine == fine) ids.push_back(i);
  if (ids.empty()) return;
  std::vector<char> removed(clones_.size(), 0), limited(clones_.size(), 0);
  const double tan_phi = std::tan(opt_.strength.friction_deg * kPi / 180.0);
  for (std::size_t pass = 0; pass <= ids.size(); ++pass) {
    for (int i : ids) {
      const Clone& c = clones_[static_cast<std::size_t>(i)];
      scratch_[c.main] = inv_m_[c.main] * f_[c.main];
      for (int q = 0; q < 2; ++q)
        if (c.t[q] >= 0) scratch_[c.t[q]] = inv_m_[c.t[q]] * f_[c.t[q]];
    }
    for (int i : ids) {
      Clone& c = clones_[static_cast<std::size_t>(i)];
      if (removed[i]) continue;
      if (limited[i]) {
        scratch_[c.main] += inv_m_[c.main] * c.lambda;
        for (int q = 0; q < 2; ++q)
          if (c.t[q] >= 0) scratch_[c.t[q]] -= (c.w[q] * inv_m_[c.t[q]]) * c.lambda;
      } else {
        c.lambda = Vec2{};
      }
    }
    for (int it = 0; it < 500; ++it) {
      double worst = 0.0, scale = 0.0;
      for (int i : ids) {
        if (removed[i] || limited[i]) continue;
        Clone& c = clones_[static_cast<std::size_t>(i)];
        Vec2 r = scratch_[c.main];
        double w = inv_m_[c.main];
        for (int q = 0; q < 2; ++q)
          if (c.t[q] >= 0) {
            r -= c.w[q] * scratch_[c.t[q]];
            w += c.w[q] * c.w[q] * inv_m_[c.t[q]];
          }
        if (!(w > 0.0)) continue;
        const Vec2 dl = -(1.0 / w) * r;
        c.lambda += dl;
        scratch_[c.main] += inv_m_[c.main] * dl;
        for (int q = 0; q < 2; ++q)
          if (c.t[q] >= 0) scratch_[c.t[q]] -= (c.w[q] * inv_m_[c.t[q]]) * dl;
        worst = std::max(worst, length(dl));
        scale = std::max(scale, length(c.lambda));
      }
      if (worst <= 1e-13 * scale || worst == 0.0) break;
    }
    bool changed = false;
    for (int i : ids) {
      if (removed[i] || limited[i]) continue;
      Clone& c = clones_[static_cast<std::size_t>(i)];
      const Vec2 n = clone_normal(c);
      const Vec2 u = perp_left(n);
      const double fn = dot(c.lambda, n), fs = dot(c.lambda, u);
      // Round-off guard: forces below 1e-12 E A_c are zero (a fresh clone
      // carries only round-off).
      const double noise =
          1e-12 * scene_.materials[static_cast<std::size_t>(blocks_[node_block_[c.main]].material)].young * c.area;
      SeparationRecord rec;
      rec.time = t;
      rec.main_node = c.main;
      rec.main_block = node_block_[c.main];
      rec.target_block = node_block_[c.ea];
      rec.normal_force = fn;
      rec.shear_force = fs;
      rec.contact_area = c.area;
      rec.fine = c.fine;
      if (fn < 0.0 && -fn > opt_.strength.tensile * c.area + noise) {
        rec.criterion = SeparationCriterion::kTension;
        rec.limit = opt_.strength.tensile * c.area;
        removed[i] = 1;
        c.lambda = Vec2{};
        separations_.push_back(rec);
        changed = true;
        continue;
      }
      const double fs_max = std::max(fn, 0.0) * tan_phi + opt_.strength.cohesion * c.area;
      if (std::fabs(fs) > fs_max + noise) {
        rec.criterion = SeparationCriterion::kShear;
        rec.limit = fs_max;
        limited[i] = 1;
        c.lambda = fn * n + std::copysign(fs_max, fs) * u;
        separations_.push_back(rec);
        changed = true;
      }
    }
    if (!changed) break;
  }
  for (int i : ids) {
    if (removed[i]) continue;
    const Clone& c = clones_[static_cast<std::size_t>(i)];
    f_[c.main] += c.lambda;
    for (int q = 0; q < 2; ++q)
      if (c.t[q] >= 0) f_[c.t[q]] -= c.w[q] * c.lambda;
  }
  std::vector<Clone> keep;
  for (std::size_t i = 0; i < clones_.size(); ++i) {
    if (removed[i] || limited[i]) {
      const Clone& c = clones_[i];
      clone_count_[c.main] -= 1;
      released_at_[c.main] = t;
      for (int q = 0; q < 2; ++q)
        if (c.t[q] >= 0) {
          clone_count_[c.t[q]] -= 1;
          released_at_[c.t[q]] = t;
        }
      continue;
    }
    keep.push_back(clones_[i]);
  }
  clones_.swap(keep);
}

Vec2 Model::vertex_normal(int node) const {
  Vec2 n{};
  for (const BEdge& e : bedges_)
    if (e.a == node || e.b == node) n += normalized(perp_right(x_[e.b] - x_[e.a]));
  return normalized(n);
}

// Normal of a clone, pointing from the target into the main block: the
// touched edge's outward normal; for two merged nodes the difference of
// their vertex normals, so that it does not depend on which of the two was
// found as the main node (an apex on a flat face gets the face normal).
Vec2 Model::clone_normal(const Clone& c) const {
  if (c.t[1] < 0) {
    const Vec2 n = normalized(vertex_normal(c.t[0]) - vertex_normal(c.main));
    if (n != Vec2{}) return n;
  }
  return normalized(perp_right(x_[c.eb] - x_[c.ea]));
}

double Model::tributary_length(int node) const {
  double l = 0.0;
  for (const BEdge& e : bedges_)
    if (e.a == node || e.b == node) l += 0.5 * distance(x_[e.a], x_[e.b]);
  return l;
}

bool Model::locate_edge(int block, Vec2 p, int& a, int& b, double& xi) const {
  double best = std::numeric_limits<double>::infinity();
  for (const BEdge& e : bedges_) {
    if (e.block != block) continue;
    const double d = point_segment_distance(p, x_[e.a], x_[e.b]);
    if (d < best) {
      best = d;
      a = e.a;
      b = e.b;
    }
  }
  if (!std::isfinite(best)) return false;
  const Vec2 e = x_[b] - x_[a];
  xi = std::clamp(dot(p - x_[a], e) / length_squared(e), 0.0, 1.0);
  return true;
}

// ---------------------------------------------------------------------------
// Contact detection and touch processing (Paper B Sects. 2-3, 5)
// ---------------------------------------------------------------------------

std::vector<Model::Touch> Model::find_touches(bool coarse_level, double t_start, const std::vector<Vec2>& p0,
                                              const std::vector<Vec2>& p1) const {
  const double tol = opt_.tolerance;
  std::vector<Aabb> box(blocks_.size());
  auto grow = [](Aabb& b, Vec2 p) {
    b.lo = {std::min(b.lo.x, p.x), std::min(b.lo.y, p.y)};
    b.hi = {std::max(b.hi.x, p.x), std::max(b.hi.y, p.y)};
  };
  for (int n : bnodes_) {
    grow(box[node_block_[n]], p0[n]);
    grow(box[node_block_[n]], p1[n]);
  }
  for (Aabb& b : box) {
    b.lo = b.lo - Vec2{tol, tol};
    b.hi = b.hi + Vec2{tol, tol};
  }
  std::vector<Touch> out;
  for (int n : bnodes_) {
    const NodeKind kn = kind_[n];
    if (kn == NodeKind::kDead || kn == NodeKind::kHanging || in_clone(n)) continue;
    // A node whose clone was removed moves free for the rest of the coarse
    // step before it can touch again: a re-touch within dt is not resolved
    // by the step anyway, and without this wait a shear release re-forms at
    // once and a vibrating face chatters through ever shorter patch steps.
    // The penetration meanwhile (< dt |v|) is far below d_tol and is found
    // at s = 0 in the next step.
    if (released_at_[n] >= std::min(t_start, step_t0_)) continue;
    if (coarse_level && kn != NodeKind::kCoarse) continue;
    const bool node_fine = kn == NodeKind::kFine;
    const int bn = node_block_[n];
    Aabb nb;
    grow(nb, p0[n]);
    grow(nb, p1[n]);
    Touch best;
    best.s = 2.0;
    for (std::size_t ob = 0; ob < blocks_.size(); ++ob) {
      if (static_cast<int>(ob) == bn || (blocks_[bn].fixed && blocks_[ob].fixed) || !aabb_overlap(nb, box[ob]))
        continue;
      for (int ei : block_bedges_[ob]) {
        const BEdge& e = bedges_[static_cast<std::size_t>(ei)];
        const bool any_fine = node_fine || kind_[e.a] == NodeKind::kFine || kind_[e.b] == NodeKind::kFine;
        if (coarse_level == any_fine) continue;  // coarse step: all-coarse pairs; patch steps: the rest
        double s = 0.0, xi = 0.0;
        if (swept_touch(p0[n], p1[n], p0[e.a], p1[e.a], p0[e.b], p1[e.b], tol, s, xi) && s < best.s) {
          best.s = s;
          best.node = n;
          best.ea = e.a;
          best.eb = e.b;
          best.xi = xi;
        }
      }
    }
    if (best.node >= 0) out.push_back(best);
  }
  std::sort(out.begin(), out.end(), [](const Touch& a, const Touch& b) { return a.s < b.s; });
  return out;
}

bool Model::process_touch(const Touch& touch, bool fine_level, double t, double t0, double t1) {
  const int m = touch.node;
  if (in_clone(m) || kind_[m] == NodeKind::kDead || kind_[m] == NodeKind::kHanging) return false;
  int ea = touch.ea, eb = touch.eb;
  const int bm = node_block_[m], bt = node_block_[ea];
  double xi = touch.xi;
  {
    const Vec2 e = x_[eb] - x_[ea];
    xi = std::clamp(dot(x_[m] - x_[ea], e) / length_squared(e), 0.0, 1.0);
  }
  const Vec2 point = lerp(x_[ea], x_[eb], xi);
  TouchRecord rec;
  rec.time = t;
  rec.step_start = t0;
  rec.step_end = t1;
  rec.dt1 = t - t0;
  rec.dt2 = t1 - t;
  rec.fine = fine_level;
  rec.main_node = m;
  rec.main_block = bm;
  rec.target_block = bt;
  rec.point = point;

  if (opt_.subdivision) {
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

  Clone c;
  c.main = m;
  c.ea = ea;
  c.eb = eb;
  const double len = distance(x_[ea], x_[eb]);
  if (xi * len <= 1e-6 * len) {
    c.t = {ea, -1};
    c.w = {1.0, 0.0};
  } else if ((1.0 - xi) * len <= 1e-6 * len) {
    c.t = {eb, -1};
    c.w = {1.0, 0.0};
  } else {
    c.t = {ea, eb};
    c.w = {1.0 - xi, xi};
  }
  rec.node_to_node = c.t[1] < 0;
  c.area = tributary_length(m);
  c.fine = kind_[m] == NodeKind::kFine;
  for (int q = 0; q < 2; ++q) {
    const int a = c.t[q];
    if (a < 0 || blocks_[node_block_[a]].fixed) continue;
    if ((kind_[a] == NodeKind::kFine) != c.fine)
      throw SimulationError("cdem: clone nodes on two integration levels (internal error)");
  }
  rec.mass_main = m_[m];
  double inv_t = 0.0;
  Vec2 vt{};
  for (int q = 0; q < 2; ++q)
    if (c.t[q] >= 0) {
      inv_t += c.w[q] * c.w[q] * inv_m_[c.t[q]];
      vt += c.w[q] * v_[c.t[q]];
    }
  rec.mass_target = inv_t > 0.0 ? 1.0 / inv_t : 0.0;
  rec.v_main = v_[m];
  rec.v_target = vt;
  const double inv_sum = inv_m_[m] + inv_t;
  rec.energy_loss_eq5 = inv_sum > 0.0 ? 0.5 / inv_sum * length_squared(v_[m] - vt) : 0.0;
  clones_.push_back(c);
  clone_count_[m] += 1;
  for (int q = 0; q < 2; ++q)
    if (c.t[q] >= 0) clone_count_[c.t[q]] += 1;
  rec.energy_loss = project_component(static_cast<int>(clones_.size()) - 1);
  rec.v_clone = v_[m];
  impact_loss_ += rec.energy_loss;
  if (opt_.capture_touch_snapshots) {
    rec.snapshot.push_back(snapshot());
    rec.snapshot.back().time = t;
  }
  touches_.push_back(std::move(rec));
  return true;
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

// ---------------------------------------------------------------------------
// Stepping
// ---------------------------------------------------------------------------

// Without subdivision, Sect. 3 as written: the touching nodes move dt1 with
// their free velocity, take the inelastic impact, and move dt2 as a clone;
// every other node moves the full dt.
void Model::literal_two_stage(const std::vector<Touch>& touches, double t0) {
  std::vector<double> tau(x_.size(), 0.0);
  std::vector<char> changed(x_.size(), 0);
  for (const Touch& T : touches) {
    if (in_clone(T.node)) continue;
    std::vector<int> set{T.node, T.ea, T.eb};
    for (std::size_t head = 0; head < set.size(); ++head)
      for (const Clone& c : clones_) {
        std::vector<int> cn{c.main};
        for (int a : c.t)
          if (a >= 0) cn.push_back(a);
        if (std::find(cn.begin(), cn.end(), set[head]) == cn.end()) continue;
        for (int a : cn)
          if (std::find(set.begin(), set.end(), a) == set.end()) set.push_back(a);
      }
    bool stale = false;
    for (int a : set) stale = stale || changed[a];
    if (stale) continue;  // found again next step from the updated motion
    for (int a : set)
      if (kind_[a] == NodeKind::kCoarse && !blocks_[node_block_[a]].fixed) {
        x_[a] += ((T.s - tau[a]) * dt_) * v_[a];
        tau[a] = T.s;
      }
    if (process_touch(T, false, t0 + T.s * dt_, t0, t0 + dt_))
      for (int a : set) changed[a] = 1;
  }
  for (int n : coarse_dofs_) x_[n] += ((1.0 - tau[n]) * dt_) * v_[n];
}

// With subdivision: the coarse nodes move linearly over [t0, t1] with
// their coarse velocity; the refined patches are integrated with steps
// dt/n in between (kick-drift-kick), their coarse nodes acting as velocity
// boundary conditions (Eq. 12); patch-element forces on coarse nodes are
// summed into an impulse returned at t1. Touches split the patch step at
// the touch time (the two stages of Sect. 3 at the patch scale); a coarse
// touch at t0 + dt1 refines the contact zone there and the contact stage
// dt2 is integrated in the patch.
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
  long stalls = 0;
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
    p0 = x_;
    p1 = x_;
    for (int n : fine_dofs_) p1[n] = x_[n] + h * v_[n];
    for (int n : coarse_dofs_) p1[n] = xs_[n] + (t + h - step_t0_) * v_[n];
    const std::vector<Touch> found = find_touches(false, t, p0, p1);
    if (!found.empty()) {
      const double smin = found.front().s;
      for (const Touch& T : found)
        if (T.s <= smin + 1e-9) pending.push_back(T);
      if (smin < 1.0) {
        const double hn = smin * h;
        kick_patch(-0.5 * (h - hn));
        h = hn;
        if (h <= eps_t) {
          if (++stalls > 1000000) throw SimulationError("cdem: patch loop stalled on repeated touches");
          continue;
        }
      }
    }
    for (int n : fine_dofs_) x_[n] += h * v_[n];
    t += h;
    sync_positions(t);
    compute_patch_forces(t);
    kick_patch(0.5 * h);
    ++substeps_taken_;
  }
}

// Coarse nodes next to a patch (corners of coarse elements evaluated at the
// patch steps) get those elements' force in their half-kicks like any other
// force (f_ = coarse-step forces + iface_ at t0 and t1), and at t1 the
// difference between the impulse the patch steps integrated for them (iimp_)
// and what the two half-kicks gave (dt/2 at t0 and t1): so the impulses of
// every element on all its corners match (momentum exact) while the kicks
// stay centred (a return of the averaged impulse alone lags by dt/2 and
// pumps energy in at a rate ~ (omega dt)^2).
void Model::step() {
  const double t0 = time_, t1 = t0 + dt_;
  step_t0_ = t0;
  for (int n : coarse_dofs_) {
    iface0_[n] = iface_[n];
    v_[n] += (0.5 * dt_ * inv_m_[n]) * f_[n];
  }
  for (int n : coarse_dofs_) xs_[n] = x_[n];
  std::vector<Vec2> p0 = x_, p1 = x_;
  for (int n : coarse_dofs_) p1[n] = x_[n] + dt_ * v_[n];
  const std::vector<Touch> touches = find_touches(true, t0, p0, p1);
  if (!opt_.subdivision) {
    literal_two_stage(touches, t0);
  } else {
    patch_loop(t0, t1, touches);
    sync_positions(t1);
  }
  time_ = t1;
  if (patch_eval_.empty())
    for (int n : coarse_dofs_) iface_[n] = Vec2{};
  compute_coarse_forces();
  for (int n : coarse_dofs_) {
    v_[n] += inv_m_[n] * ((0.5 * dt_) * f_[n] + iimp_[n] - (0.5 * dt_) * iface0_[n]);
    iimp_[n] = Vec2{};
    iface0_[n] = Vec2{};
    f_[n] += iface_[n];
  }
  if (opt_.subdivision && dissolve_free_patches()) {
    for (int n : coarse_dofs_) iface_[n] = Vec2{};
    if (!patch_eval_.empty()) compute_patch_forces(t1);
    compute_coarse_forces();
    for (int n : coarse_dofs_) f_[n] += iface_[n];
  }
  ++steps_;
  check_state();
}

void Model::advance_to(double t) {
  while (time_ < t - 0.5 * dt_) step();
}

void Model::check_state() const {
  for (std::size_t i = 0; i < x_.size(); ++i) {
    if (kind_[i] == NodeKind::kDead) continue;
    if (!is_finite(x_[i]) || !is_finite(v_[i])) {
      std::ostringstream s;
      s << "cdem: non-finite state at node " << i << " of block " << node_block_[i] << ", t = " << time_ << " (step "
        << steps_ << ")";
      throw SimulationError(s.str());
    }
  }
}

// ---------------------------------------------------------------------------
// Read-out
// ---------------------------------------------------------------------------

double Model::kinetic_energy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < x_.size(); ++i)
    if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) e += 0.5 * m_[i] * length_squared(v_[i]);
  return e;
}

CdemEnergy Model::energy() const {
  CdemEnergy en;
  en.kinetic = kinetic_energy();
  for (const std::vector<int>* list : {&coarse_elems_, &fine_elems_})
    for (int ei : *list) {
      const Elem& e = elem(ei);
      const double a = cst({x_[e.n[0]], x_[e.n[1]], x_[e.n[2]]}).area;
      en.strain += 0.5 * a * e.stress.dot(c_[blocks_[e.block].material] * e.stress);
    }
  for (std::size_t i = 0; i < x_.size(); ++i)
    if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) en.gravity -= m_[i] * dot(scene_.gravity, x_[i]);
  return en;
}

Vec2 Model::momentum() const {
  Vec2 p{};
  for (std::size_t i = 0; i < x_.size(); ++i)
    if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) p += m_[i] * v_[i];
  return p;
}

double Model::block_mass(int b) const {
  double m = 0.0;
  for (int i : blocks_[b].nodes)
    if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) m += m_[i];
  return m;
}

Vec2 Model::block_momentum(int b) const {
  Vec2 p{};
  for (int i : blocks_[b].nodes)
    if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) p += m_[i] * v_[i];
  return p;
}

Vec2 Model::block_velocity(int b) const { return block_momentum(b) / block_mass(b); }

Vec2 Model::block_mean_position(int b) const {
  Vec2 p{};
  double m = 0.0;
  for (int i : blocks_[b].nodes)
    if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) {
      p += m_[i] * x_[i];
      m += m_[i];
    }
  return p / m;
}

Vec2 Model::block_displacement(int b) const { return block_mean_position(b) - blocks_[b].initial_mean; }

double Model::block_max_velocity_x(int b) const {
  double v = -std::numeric_limits<double>::infinity();
  for (int i : blocks_[b].nodes)
    if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) v = std::max(v, v_[i].x);
  return v;
}

double Model::block_min_velocity_x(int b) const {
  double v = std::numeric_limits<double>::infinity();
  for (int i : blocks_[b].nodes)
    if (kind_[i] == NodeKind::kCoarse || kind_[i] == NodeKind::kFine) v = std::min(v, v_[i].x);
  return v;
}

std::vector<Vec2> Model::block_outline(int b) const {
  std::vector<Vec2> o;
  for (int i : blocks_[b].outline) o.push_back(x_[i]);
  return o;
}

std::vector<CloneView> Model::clones() const {
  std::vector<CloneView> out;
  for (const Clone& c : clones_) {
    CloneView v;
    v.main_node = c.main;
    v.target = c.t;
    v.weight = c.w;
    v.point = x_[c.main];
    v.force = c.lambda;
    v.fine = c.fine;
    out.push_back(v);
  }
  return out;
}

int Model::active_elements(bool fine) const {
  return static_cast<int>(fine ? fine_elems_.size() : coarse_elems_.size());
}

Snapshot Model::snapshot() const {
  Snapshot s;
  s.time = time_;
  for (const Elem& e : elems_) {
    if (!e.active) continue;
    Snapshot::Tri t;
    t.x = {x_[e.n[0]], x_[e.n[1]], x_[e.n[2]]};
    t.velocity = (v_[e.n[0]] + v_[e.n[1]] + v_[e.n[2]]) / 3.0;
    t.block = e.block;
    t.fine = e.level > 0;
    s.tris.push_back(t);
  }
  for (const Clone& c : clones_) s.clone_points.push_back(x_[c.main]);
  return s;
}

}  // namespace dda::cdem
