// The impact study: the set-up of a cell (two CST-meshed squares of Paper B's
// material), the measuring helpers and the rigid-body impact law.
#include <algorithm>

#include "repro/B_9_impact_study/impact_study.hpp"

namespace impact {

dda::Material paper_b_material() { return dda::cdem::two_prisms_scene().materials.front(); }
double block_mass() { return paper_b_material().density * kSide * kSide; }
double normal_mass() { return 0.5 * block_mass(); }
double tangential_mass() {
  const double m = block_mass(), inertia = m * kSide * kSide / 6.0, r = 0.5 * kSide;
  return 1.0 / (2.0 * (1.0 / m + r * r / inertia));
}
double wave_time() {
  const dda::Material mat = paper_b_material();
  return 2.0 * kSide / std::sqrt(mat.young / mat.density);
}
std::vector<Vec2> square(double x0, double y0) {
  return {{x0, y0}, {x0 + kSide, y0}, {x0 + kSide, y0 + kSide}, {x0, y0 + kSide}};
}
Vec2 impact_velocity(const Cell& c) {
  const double a = c.angle_deg * kPi / 180.0;
  return {c.speed * std::cos(a), c.speed * std::sin(a)};
}
double gap_of(const Cell& c, double dt) { return impact_velocity(c).x * kApproachSteps * dt; }
dda::cdem::CdemScene scene_of(const Cell& c, double dt) {
  dda::cdem::CdemScene s;
  s.name = "B-9 impact study";
  s.materials = {paper_b_material()};
  s.dt = dt;
  dda::cdem::CdemBlock a, b;
  a.outline = square(-kSide - gap_of(c, dt), -0.5 * kSide);
  a.divisions = kDivisions;
  a.velocity = impact_velocity(c);
  a.name = "A";
  b.outline = square(0.0, -0.5 * kSide);
  b.divisions = kDivisions;
  b.name = "B";
  s.blocks = {a, b};
  s.options.subdivision = c.subdivision;  // tolerance: Paper B's 5e-3 m (the default)
  s.options.subdivision_mode =
      c.submodel ? dda::cdem::SubdivisionMode::kSubModel : dda::cdem::SubdivisionMode::kInPlace;
  s.options.strength.friction_deg = std::atan(c.mu) * 180.0 / kPi;
  if (c.coulomb) s.options.touch_impact = dda::cdem::TouchImpact::kCoulomb;
  return s;
}
std::vector<std::vector<int>> boundary_loops(const dda::cdem::CdemScene& s) {
  std::vector<std::vector<int>> loops;
  int base = 0;
  for (const dda::cdem::CdemBlock& b : s.blocks) {
    const dda::cdem::TriMesh mesh = dda::cdem::mesh_convex_polygon(b.outline, b.divisions);
    std::vector<std::pair<double, int>> on;
    const std::size_t n = b.outline.size();
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i)
      for (std::size_t k = 0; k < n; ++k) {
        const Vec2 p = b.outline[k], q = b.outline[(k + 1) % n], d = q - p;
        const double len = dda::length(d), t = dda::dot(mesh.nodes[i] - p, d) / (len * len);
        if (std::fabs(dda::cross(d, mesh.nodes[i] - p)) / len < 1e-12 && t >= 0.0 && t < 1.0) {
          on.push_back({static_cast<double>(k) + t, base + static_cast<int>(i)});
          break;
        }
      }
    std::sort(on.begin(), on.end());
    std::vector<int> loop;
    for (const auto& e : on) loop.push_back(e.second);
    loops.push_back(loop);
    base += static_cast<int>(mesh.nodes.size());
  }
  return loops;
}
double depth_in(Vec2 p, const std::vector<Vec2>& poly) {
  bool inside = false;
  double d = 1e300;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 a = poly[j], b = poly[i];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
    const Vec2 ab = b - a;
    const double t = std::clamp(dda::dot(p - a, ab) / dda::length_squared(ab), 0.0, 1.0);
    d = std::min(d, dda::length(p - (a + t * ab)));
  }
  return inside ? d : 0.0;
}
double max_node_depth(const dda::cdem::Model& m, const std::vector<std::vector<int>>& loops) {
  std::vector<std::vector<Vec2>> polys;
  for (const auto& loop : loops) {
    std::vector<Vec2> p;
    for (int i : loop) p.push_back(m.node_position(i));
    polys.push_back(p);
  }
  double worst = 0.0;
  for (int i = 0; i < m.node_count(); ++i) {
    if (m.node_kind(i) == dda::cdem::NodeKind::kDead) continue;
    for (int b = 0; b < static_cast<int>(polys.size()); ++b)
      if (b != m.node_block(i)) worst = std::max(worst, depth_in(m.node_position(i), polys[b]));
  }
  return worst;
}
double block_spin(const dda::cdem::Model& m, int b) {
  const Vec2 c = m.block_mean_position(b);
  double l = 0.0, j = 0.0;
  for (int i = 0; i < m.node_count(); ++i) {
    if (m.node_block(i) != b || m.node_kind(i) == dda::cdem::NodeKind::kDead) continue;
    const Vec2 r = m.node_position(i) - c;
    l += m.node_mass(i) * dda::cross(r, m.node_velocity(i));
    j += m.node_mass(i) * dda::length_squared(r);
  }
  return j > 0.0 ? l / j : 0.0;
}
double rigid_law_jt(double mu, double jn, double v_t0, bool* sticks) {
  const double stick = tangential_mass() * v_t0;
  if (sticks) *sticks = mu * jn >= stick;
  return std::min(stick, mu * jn);
}
}  // namespace impact
