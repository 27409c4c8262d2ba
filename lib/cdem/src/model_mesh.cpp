// Paper B Sect. 2: the blocks as meshes of constant-strain triangles with
// lumped nodal masses; scene checks, critical steps, and the mesh's state
// (node classes, element lists, boundary edges, lumped masses) that the
// in-place refinement (model_refine.cpp) changes.
#include "model_ops.hpp"

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

// The set-up and the initial state of a scene (su.scene and su.opt set):
// scene checks, materials, meshes, lumped masses, critical steps, the
// forces at t = 0 and E0.
void build_model(ModelSetup& su, ModelState& st) {
  const CdemScene& scene = su.scene;
  NodeState& nd = st.nodes;
  MeshState& mesh = st.mesh;
  if (!positive_finite(scene.dt)) scene_fail("dt", "must be a positive finite time step");
  if (!(std::isfinite(scene.duration) && scene.duration >= 0.0)) scene_fail("duration", "must be finite and >= 0");
  if (!is_finite(scene.gravity)) scene_fail("gravity", "must be finite");
  if (!positive_finite(su.opt.tolerance)) scene_fail("options.tolerance", "must be positive");
  if (!(std::isfinite(su.opt.strength.tensile) && su.opt.strength.tensile >= 0.0))
    scene_fail("options.strength.tensile", "must be >= 0");
  if (!(std::isfinite(su.opt.strength.cohesion) && su.opt.strength.cohesion >= 0.0))
    scene_fail("options.strength.cohesion", "must be >= 0");
  if (!(std::isfinite(su.opt.strength.friction_deg) && su.opt.strength.friction_deg >= 0.0 &&
        su.opt.strength.friction_deg < 90.0))
    scene_fail("options.strength.friction_deg", "must lie in [0, 90)");
  if (su.opt.min_subdivision < 1 || su.opt.max_subdivision < su.opt.min_subdivision || su.opt.max_subdivision > 64)
    scene_fail("options.min/max_subdivision", "need 1 <= min <= max <= 64");
  if (!(su.opt.substep_safety > 0.0 && su.opt.substep_safety <= 1.0))
    scene_fail("options.substep_safety", "must lie in (0, 1]");
  if (!(std::isfinite(su.opt.contact_point_mass) && su.opt.contact_point_mass >= 0.0))
    scene_fail("options.contact_point_mass", "must be finite and >= 0");
  if (su.opt.contact_point_mass > 0.0 && !su.opt.subdivision)
    scene_fail("options.contact_point_mass", "is set through the subdivision (Sect. 5): needs subdivision on");
  if (su.opt.contact_point_mass > 0.0 && su.opt.subdivision && su.opt.subdivision_mode == SubdivisionMode::kSubModel)
    scene_fail("options.contact_point_mass",
               "is set through the in-place refinement (SubdivisionMode::kInPlace); the sub-model (kSubModel) keeps "
               "the coarse contact masses");
  if (!(std::isfinite(su.opt.mass_damping) && su.opt.mass_damping >= 0.0))
    scene_fail("options.mass_damping", "must be >= 0");
  if (scene.materials.empty()) scene_fail("materials", "at least one material is needed");
  for (std::size_t i = 0; i < scene.materials.size(); ++i) {
    const Material& m = scene.materials[i];
    const std::string f = "materials[" + std::to_string(i) + "]";
    if (!positive_finite(m.density)) scene_fail(f + ".density", "must be positive");
    if (!positive_finite(m.young)) scene_fail(f + ".young", "must be positive");
    if (!(std::isfinite(m.poisson) && m.poisson > -1.0 && m.poisson < 0.5))
      scene_fail(f + ".poisson", "must lie in (-1, 0.5)");
    su.d.push_back(elastic_matrix(m.young, m.poisson));
    su.c.push_back(su.d.back().inverse());
    su.wave_speed.push_back(std::sqrt(m.young / m.density));
  }
  su.dt = scene.dt;

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
    const TriMesh tri_mesh = own_mesh ? cb.mesh : mesh_convex_polygon(cb.outline, cb.divisions);
    BlockState blk;
    blk.material = cb.material;
    blk.fixed = cb.fixed;
    const int base = static_cast<int>(nd.x.size());
    for (const Vec2& p : tri_mesh.nodes) {
      blk.nodes.push_back(static_cast<int>(nd.x.size()));
      nd.x.push_back(p);
      nd.v.push_back(cb.fixed ? Vec2{} : cb.velocity);
      nd.block.push_back(static_cast<int>(bi));
    }
    for (int i = 0; i < static_cast<int>(cb.outline.size()); ++i) blk.outline.push_back(base + i);
    const double rho = scene.materials[static_cast<std::size_t>(cb.material)].density;
    for (const auto& t : tri_mesh.triangles) {
      Element e;
      e.n = {base + t[0], base + t[1], base + t[2]};
      e.block = static_cast<int>(bi);
      e.last = {nd.x[e.n[0]], nd.x[e.n[1]], nd.x[e.n[2]]};
      const double a = cst(e.last).area;
      if (!(a > 0.0)) scene_fail(f, "meshing produced a degenerate triangle");
      e.mass = rho * a;
      mesh.elems.push_back(e);
    }
    st.blocks.push_back(std::move(blk));
  }
  const std::size_t n = nd.x.size();
  nd.xs = nd.x;
  nd.f.assign(n, Vec2{});
  nd.iface.assign(n, Vec2{});
  nd.iimp.assign(n, Vec2{});
  nd.iface0.assign(n, Vec2{});
  nd.released_at.assign(n, -std::numeric_limits<double>::infinity());
  nd.scratch.assign(n, Vec2{});
  nd.kind.assign(n, NodeKind::kCoarse);
  nd.hang_a.assign(n, -1);
  nd.hang_b.assign(n, -1);
  nd.hang_w.assign(n, 0.0);
  nd.clone_count.assign(n, 0);

  // Coarse edges: adjacency and outline.
  for (int ei = 0; ei < static_cast<int>(mesh.elems.size()); ++ei) {
    const Element& e = mesh.elems[ei];
    for (int k = 0; k < 3; ++k) {
      const int a = e.n[k], b = e.n[(k + 1) % 3];
      MeshEdge& info = mesh.edges[edge_key(a, b)];
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
  for (int ei = 0; ei < static_cast<int>(mesh.elems.size()); ++ei) {
    const Element& e = mesh.elems[ei];
    for (int k = 0; k < 3; ++k) {
      const int a = e.n[k], b = e.n[(k + 1) % 3];
      if (mesh.edges.at(edge_key(a, b)).elems[1] < 0) {
        mesh.coarse_bedges.push_back({a, b, e.block, false});
        mesh.coarse_bedge_elem.push_back(ei);
      }
    }
  }
  classify(mesh, nd);
  rebuild_lists(mesh, nd, st.blocks);
  rebuild_boundary(mesh, nd.size(), st.blocks.size());
  nd.m = lumped_masses(mesh, nd);
  nd.inv_m.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) nd.inv_m[i] = (st.blocks[nd.block[i]].fixed || !(nd.m[i] > 0.0)) ? 0.0 : 1.0 / nd.m[i];
  for (BlockState& b : st.blocks) b.initial_mean = block_mean_position(st, static_cast<int>(&b - st.blocks.data()));

  compute_critical_steps(su, st);
  if (su.opt.check_stability && su.dt > su.critical_dt) {
    std::ostringstream s;
    s << "time step " << su.dt << " s exceeds the critical step " << su.critical_dt
      << " s of the coarse mesh (2/omega_max; element bound " << su.element_critical_dt
      << " s): use a smaller dt or coarser elements (Paper B Sect. 5: c dt < element length)";
    scene_fail("dt", s.str());
  }
  setup_penalty(su, st);
  compute_coarse_forces(su, st);
  st.energy.initial = energy_of(su, st).total();
}

double element_omega_max(const Element& e, const std::vector<Vec2>& xn, const Mat3& d) {
  const std::array<Vec2, 3> x{xn[e.n[0]], xn[e.n[1]], xn[e.n[2]]};
  const auto k = element_stiffness(x, d);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> es(k, Eigen::EigenvaluesOnly);
  const double lambda = es.eigenvalues().maxCoeff();
  return std::sqrt(std::max(lambda, 0.0) / (e.mass / 3.0));
}

void compute_critical_steps(ModelSetup& su, const ModelState& st) {
  const NodeState& nd = st.nodes;
  const MeshState& mesh = st.mesh;
  double omega_elem = 0.0;
  for (int e : mesh.coarse_elems)
    omega_elem = std::max(omega_elem, element_omega_max(mesh.elem(e), nd.x, su.d[st.blocks[mesh.elem(e).block].material]));
  su.element_critical_dt = omega_elem > 0.0 ? 2.0 / omega_elem : std::numeric_limits<double>::infinity();
  // Power iteration on M^-1/2 K M^-1/2 of the assembled coarse mesh.
  const std::size_t n = nd.x.size();
  std::vector<Vec2> z(n), y(n), u(n);
  std::uint64_t seed = 0x9E3779B97F4A7C15ull;
  auto rnd = [&] {
    seed = seed * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(seed >> 11) / 9007199254740992.0 - 0.5;
  };
  for (std::size_t i = 0; i < n; ++i) z[i] = nd.inv_m[i] > 0.0 ? Vec2{rnd(), rnd()} : Vec2{};
  double lambda = 0.0;
  for (int it = 0; it < 400; ++it) {
    double zz = 0.0;
    for (std::size_t i = 0; i < n; ++i) zz += length_squared(z[i]);
    if (!(zz > 0.0)) break;
    for (std::size_t i = 0; i < n; ++i) {
      z[i] = z[i] / std::sqrt(zz);
      u[i] = std::sqrt(nd.inv_m[i]) * z[i];
      y[i] = Vec2{};
    }
    for (int ei : mesh.coarse_elems) {
      const Element& e = mesh.elem(ei);
      if (st.blocks[e.block].fixed) continue;
      const std::array<Vec2, 3> x{nd.x[e.n[0]], nd.x[e.n[1]], nd.x[e.n[2]]};
      const auto k = element_stiffness(x, su.d[st.blocks[e.block].material]);
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
      y[i] = std::sqrt(nd.inv_m[i]) * y[i];
      lambda += dot(z[i], y[i]);
    }
    z = y;
  }
  su.critical_dt = lambda > 0.0 ? 2.0 / std::sqrt(lambda) : std::numeric_limits<double>::infinity();
}

void classify(const MeshState& mesh, NodeState& nd) {
  const std::size_t n = nd.x.size();
  std::vector<int> cc(n, 0), fc(n, 0);
  for (const Element& e : mesh.elems) {
    if (!e.active) continue;
    for (int a : e.n) (e.level == 0 ? cc : fc)[a] += 1;
  }
  std::vector<char> hang(n, 0);
  for (auto& kv : mesh.edges) {
    const MeshEdge& ei = kv.second;
    if (ei.nodes.empty()) continue;
    int refined = 0, coarse = 0;
    for (int s : ei.elems) {
      if (s < 0) continue;
      const Element& e = mesh.elem(s);
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
        nd.hang_a[h] = ei.lo;
        nd.hang_b[h] = ei.hi;
        nd.hang_w[h] = static_cast<double>(t) / k;
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (hang[i])
      nd.kind[i] = NodeKind::kHanging;
    else if (fc[i] > 0)
      nd.kind[i] = NodeKind::kFine;
    else if (cc[i] > 0)
      nd.kind[i] = NodeKind::kCoarse;
    else
      nd.kind[i] = NodeKind::kDead;
  }
}

void rebuild_lists(MeshState& mesh, const NodeState& nd, const std::vector<BlockState>& blocks) {
  mesh.coarse_elems.clear();
  mesh.fine_elems.clear();
  mesh.coarse_eval.clear();
  mesh.patch_eval.clear();
  for (int i = 0; i < static_cast<int>(mesh.elems.size()); ++i) {
    const Element& e = mesh.elems[i];
    if (!e.active) continue;
    (e.level == 0 ? mesh.coarse_elems : mesh.fine_elems).push_back(i);
    bool fine_corner = e.level > 0;
    for (int a : e.n) fine_corner = fine_corner || nd.kind[a] == NodeKind::kFine;
    (fine_corner ? mesh.patch_eval : mesh.coarse_eval).push_back(i);
  }
  mesh.coarse_dofs.clear();
  mesh.fine_dofs.clear();
  mesh.hanging.clear();
  for (int i = 0; i < static_cast<int>(nd.x.size()); ++i) {
    if (nd.kind[i] == NodeKind::kHanging) {
      mesh.hanging.push_back(i);
      continue;
    }
    if (blocks[nd.block[i]].fixed) continue;
    if (nd.kind[i] == NodeKind::kCoarse)
      mesh.coarse_dofs.push_back(i);
    else if (nd.kind[i] == NodeKind::kFine)
      mesh.fine_dofs.push_back(i);
  }
}

void rebuild_boundary(MeshState& mesh, std::size_t node_count, std::size_t block_count) {
  mesh.bedges.clear();
  for (std::size_t i = 0; i < mesh.coarse_bedges.size(); ++i) {
    const BoundaryEdge& ce = mesh.coarse_bedges[i];
    const Element& e = mesh.elem(mesh.coarse_bedge_elem[i]);
    if (e.active) {
      mesh.bedges.push_back(ce);
      continue;
    }
    const MeshEdge& ei = mesh.edges.at(edge_key(ce.a, ce.b));
    std::vector<int> seq{ce.a};
    if (ce.a == ei.lo)
      seq.insert(seq.end(), ei.nodes.begin(), ei.nodes.end());
    else
      seq.insert(seq.end(), ei.nodes.rbegin(), ei.nodes.rend());
    seq.push_back(ce.b);
    for (std::size_t k = 0; k + 1 < seq.size(); ++k) mesh.bedges.push_back({seq[k], seq[k + 1], ce.block, true});
  }
  mesh.block_bedges.assign(block_count, {});
  for (std::size_t i = 0; i < mesh.bedges.size(); ++i)
    mesh.block_bedges[static_cast<std::size_t>(mesh.bedges[i].block)].push_back(static_cast<int>(i));
  std::vector<char> seen(node_count, 0);
  mesh.bnodes.clear();
  for (const BoundaryEdge& b : mesh.bedges)
    for (int v : {b.a, b.b})
      if (!seen[v]) {
        seen[v] = 1;
        mesh.bnodes.push_back(v);
      }
}

std::vector<double> lumped_masses(const MeshState& mesh, const NodeState& nd) {
  std::vector<double> s(nd.x.size(), 0.0);
  for (const Element& e : mesh.elems)
    if (e.active)
      for (int a : e.n) s[a] += e.mass / 3.0;
  for (int h = 0; h < static_cast<int>(nd.x.size()); ++h) {
    if (nd.kind[h] != NodeKind::kHanging) continue;
    s[nd.hang_a[h]] += (1.0 - nd.hang_w[h]) * s[h];
    s[nd.hang_b[h]] += nd.hang_w[h] * s[h];
    s[h] = 0.0;
  }
  return s;
}

}  // namespace dda::cdem
