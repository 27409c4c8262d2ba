// Paper A Sect. 3.2.2: the reconstructed polygons and their geometry
// (potential_fields.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "repro/3_2_2_potential_fields/potential_fields.hpp"

namespace potential_fields {

// Replaces corner i of a closed polyline by two points on its neighbouring
// edges so that the new (cut) edge has length `len`.
std::vector<Vec2> cut_corner(const std::vector<Vec2>& pts, std::size_t i, double len) {
  const std::size_t n = pts.size();
  const Vec2 v = pts[i], a = pts[(i + n - 1) % n], b = pts[(i + 1) % n];
  const Vec2 ua = dda::normalized(a - v), ub = dda::normalized(b - v);
  const double t = len / dda::length(ua - ub);
  std::vector<Vec2> out;
  for (std::size_t k = 0; k < n; ++k) {
    if (k == i) {
      out.push_back(v + t * ua);
      out.push_back(v + t * ub);
    } else {
      out.push_back(pts[k]);
    }
  }
  return out;
}

// (a) Reconstructed Fig. 4b polygon: a ~1.2 m convex pentagon whose corners
// 1 and 3 are cut by edges of 0.03 m and 0.05 m.
std::vector<Vec2> small_edge_polygon() {
  std::vector<Vec2> p = {{0.0, 0.0}, {1.0, -0.05}, {1.15, 0.55}, {0.55, 1.0}, {-0.1, 0.65}};
  p = cut_corner(p, 3, 0.05);  // cut the later corner first: indices below stay valid
  p = cut_corner(p, 1, 0.03);
  return p;
}

// (b) Reconstructed Fig. 5 polygon: simple, CCW, 13 vertices, 4 reflex.
std::vector<Vec2> concave_polygon() {
  return {{0.0, 0.0},  {0.55, 0.05}, {0.7, 0.35},  {0.85, 0.1}, {1.3, 0.15}, {1.2, 0.5},  {0.95, 0.55},
          {1.25, 0.95}, {0.75, 1.1},  {0.55, 0.75}, {0.3, 1.05}, {-0.05, 0.8}, {0.2, 0.5}};
}

double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 e = b - a;
  const double ee = dda::dot(e, e);
  const double t = ee > 0.0 ? std::clamp(dda::dot(p - a, e) / ee, 0.0, 1.0) : 0.0;
  return dda::distance(p, a + t * e);
}

// Shortest distance from p to the boundary of the closed polygon `pts`.
double boundary_distance(const std::vector<Vec2>& pts, Vec2 p) {
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < pts.size(); ++i) d = std::min(d, segment_distance(p, pts[i], pts[(i + 1) % pts.size()]));
  return d;
}

// Crossing-number point-in-polygon test (any simple polygon).
bool inside_simple(const std::vector<Vec2>& pts, Vec2 p) {
  bool in = false;
  for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
    const Vec2 a = pts[i], b = pts[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
  }
  return in;
}

double signed_area(const std::vector<Vec2>& pts) {
  double s = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) s += dda::cross(pts[i], pts[(i + 1) % pts.size()]);
  return 0.5 * s;
}

bool segments_cross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double o1 = dda::cross(b - a, c - a), o2 = dda::cross(b - a, d - a);
  const double o3 = dda::cross(d - c, a - c), o4 = dda::cross(d - c, b - c);
  return ((o1 > 0) != (o2 > 0)) && ((o3 > 0) != (o4 > 0));
}

// Throws unless the polygon is simple (no two non-adjacent edges cross) and CCW.
void check_simple_ccw(const std::vector<Vec2>& pts) {
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through vertex 0
      if (segments_cross(pts[i], pts[(i + 1) % n], pts[j], pts[(j + 1) % n]))
        throw std::runtime_error("concave polygon: edges " + std::to_string(i) + " and " + std::to_string(j) + " cross");
    }
  if (signed_area(pts) <= 0.0) throw std::runtime_error("concave polygon: not counter-clockwise");
}

int reflex_count(const std::vector<Vec2>& pts) {
  int r = 0;
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i)
    if (dda::cross(pts[i] - pts[(i + n - 1) % n], pts[(i + 1) % n] - pts[i]) < 0.0) ++r;
  return r;
}


// Eqs. 13-14 applied to any polygon (edge lines): min_i n_i . (v_i - p).
double edge_line_distance(const std::vector<Vec2>& pts, Vec2 p) {
  double dl = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < pts.size(); ++e) {
    const Vec2 a = pts[e], b = pts[(e + 1) % pts.size()];
    dl = std::min(dl, dda::dot(dda::normalized(dda::perp_right(b - a)), a - p));
  }
  return dl;
}

}  // namespace potential_fields
