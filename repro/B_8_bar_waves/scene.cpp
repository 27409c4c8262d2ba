// Two elastic bars head on: the scenes of the two models (CDEM bars, Paper A's
// DDA bars).
#include <cmath>

#include "repro/B_8_bar_waves/bar_waves.hpp"

namespace bars {

std::vector<dda::Vec2> rect(double x0, double y0, double w, double h) {
  return {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}};
}
dda::cdem::CdemScene cdem_scene(const Setup& s, int ny, double dt, bool subdivision) {
  dda::cdem::CdemScene sc;
  sc.name = "B-8 two bars";
  dda::Material target = s.material;
  target.density *= s.target_density_factor;
  sc.materials = {s.material, target};
  sc.dt = dt;
  const int nx = static_cast<int>(std::lround(ny * s.length / s.width));
  const double y0 = -0.5 * s.width;
  dda::cdem::CdemBlock a, b;
  a.outline = rect(-s.gap - s.length, y0, s.length, s.width);
  a.mesh = dda::cdem::mesh_rectangle(a.outline.front(), s.length, s.width, nx, ny);
  a.velocity = {s.speed, 0.0};
  a.name = "striker";
  b.outline = rect(0.0, y0, s.length, s.width);
  b.mesh = dda::cdem::mesh_rectangle(b.outline.front(), s.length, s.width, nx, ny);
  b.material = 1;
  b.name = "target";
  sc.blocks = {a, b};
  sc.options.subdivision = subdivision;
  // B: the in-place refinement (beyond the paper), set explicitly: B-8 is a
  // study, not a paper figure, and its outputs do not follow the default.
  sc.options.subdivision_mode = dda::cdem::SubdivisionMode::kInPlace;
  return sc;
}
dda::Scene dda_scene(const Setup& s, double dt, double kn) {
  dda::Scene sc;
  sc.name = "B-8 two bars, DDA";
  dda::Material target = s.material;
  target.density *= s.target_density_factor;
  sc.materials = {s.material, target};
  sc.contact.kn = kn;
  sc.dt = dt;
  dda::BlockSpec a, b;
  a.vertices = rect(-s.gap - s.length, -0.5 * s.width, s.length, s.width);
  a.velocity = {s.speed, 0.0};
  a.name = "striker";
  b.vertices = rect(0.0, -0.5 * s.width, s.length, s.width);
  b.material = 1;
  b.name = "target";
  sc.blocks = {a, b};
  return sc;
}
}  // namespace bars
