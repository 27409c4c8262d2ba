// What several unit tests build or fit: axis-aligned rectangles, a jointed
// rock column's scene, the order of convergence fitted to errors.
#pragma once
#include <cmath>
#include <vector>

#include "dda/joint_sets.hpp"
#include "dda/polygon.hpp"
#include "dda/simulation.hpp"

namespace dda::test {

// The rectangle [x0, x0 + w] x [y0, y0 + h], counter-clockwise from (x0, y0).
inline std::vector<Vec2> rect_vertices(double x0, double y0, double w, double h) {
  return {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}};
}
inline Polygon rect(double x0, double y0, double w, double h) {
  const std::vector<Vec2> p = rect_vertices(x0, y0, w, h);
  return make_polygon(p.data(), 4);
}

// The blocks `region` cut by `sets` (pieces under `min_area` dropped) under
// gravity: rock (2700 kg/m^3, E 2 GPa, nu 0.3), kn 2 GPa, kt 1 GPa, friction
// `friction_deg` and 35 deg between groups 0 and 1, the sweep broad phase.
inline Scene jointed_rock(const std::vector<Vec2>& region, const std::vector<JointSet>& sets, double min_area,
                          double friction_deg) {
  const GeneratedBlocks g = generate_blocks(region, sets, min_area);
  Scene s;
  s.materials = {{2700.0, 2e9, 0.3}};
  s.contact.kn = 2e9;
  s.contact.kt = 1e9;
  s.contact.friction_deg = friction_deg;
  s.contact.friction_rules = {{0, 1, 35.0}};
  s.gravity = {0.0, -9.81};
  s.broad_phase = BroadPhase::kSweep;
  for (const Polygon& p : g.blocks) {
    BlockSpec b;
    b.vertices.assign(p.v.begin(), p.v.begin() + p.count);
    s.blocks.push_back(b);
  }
  return s;
}

// Least-squares slope of log(y) against log(x): the order of convergence of
// errors y at steps x.
inline double fitted_order(const std::vector<double>& x, const std::vector<double>& y) {
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  const double n = static_cast<double>(x.size());
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double lx = std::log(x[k]), ly = std::log(y[k]);
    sx += lx;
    sy += ly;
    sxx += lx * lx;
    sxy += lx * ly;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

}  // namespace dda::test
