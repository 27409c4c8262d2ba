// Paper B Sect. 2: the blocks as meshes of constant-strain triangles with
// lumped nodal masses; scene checks, critical steps, and the mesh's state
// (node classes, element lists, boundary edges, lumped masses) that the
// local subdivision (model_subdivision.cpp) changes.
#include "dda/cdem/model.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "dda/cdem/mesh.hpp"
#include "dda/polygon.hpp"
#include "geometry.hpp"

namespace dda::cdem {

using namespace detail;

namespace {

[[noreturn]] void scene_fail(const std::string& where, const std::string& why) { throw SceneError(where + ": " + why); }

bool positive_finite(double x) { return std::isfinite(x) && x > 0.0; }

}  // namespace

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
  if (!(std::isfinite(opt_.contact_point_mass) && opt_.contact_point_mass >= 0.0))
    scene_fail("options.contact_point_mass", "must be finite and >= 0");
  if (opt_.contact_point_mass > 0.0 && !opt_.subdivision)
    scene_fail("options.contact_point_mass", "is set through the subdivision (Sect. 5): needs subdivision on");
  if (opt_.contact_point_mass > 0.0 && opt_.subdivision && opt_.subdivision_mode == SubdivisionMode::kSubModel)
    scene_fail("options.contact_point_mass",
               "is set through the in-place refinement (SubdivisionMode::kInPlace); the sub-model (kSubModel) keeps "
               "the coarse contact masses");
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
    const bool own_mesh = !cb.mesh.triangles.empty();
    if (own_mesh) {
      const std::size_t nv = cb.outline.size();
      if (cb.mesh.nodes.size() < nv) scene_fail(f + ".mesh", "has fewer nodes than the outline");
      for (std::size_t i = 0; i < nv; ++i)
        if (!(cb.mesh.nodes[i] == cb.outline[i]))
          scene_fail(f + ".mesh.nodes[" + std::to_string(i) + "]", "must be the outline vertex " + std::to_string(i));
      for (const auto& t : cb.mesh.triangles)
        for (int q : t)
          if (q < 0 || q >= static_cast<int>(cb.mesh.nodes.size()))
            scene_fail(f + ".mesh.triangles", "node index out of range");
      for (const Vec2& p : cb.mesh.nodes)
        if (!is_finite(p)) scene_fail(f + ".mesh.nodes", "must be finite");
    }
    const TriMesh mesh = own_mesh ? cb.mesh : mesh_convex_polygon(cb.outline, cb.divisions);
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
      else if (info.elems[1] < 0)
        info.elems[1] = ei;
      else
        scene_fail("blocks[" + std::to_string(e.block) + "].mesh", "an edge is shared by more than two triangles");
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
  setup_penalty();
  compute_coarse_forces();
  initial_energy_ = energy().total();
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

}  // namespace dda::cdem
