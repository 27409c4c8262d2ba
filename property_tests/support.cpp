// Printing of the input types and double-precision distance measurement
// (see support.hpp).
#include "support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace prop {

Vec2 Motion::apply(Vec2 p) const { return centre + dda::rotate(p - centre, angle) + shift; }

std::string to_code(Vec2 p) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "{%.17g, %.17g}", p.x, p.y);
  return buf;
}

std::string to_code(const Points& p) {
  std::string s = "{";
  for (std::size_t i = 0; i < p.size(); ++i) s += (i ? ", " : "") + to_code(p[i]);
  return s + "}";
}

void showValue(const Points& p, std::ostream& os) { os << to_code(p); }
void showValue(const Samples& s, std::ostream& os) { os << to_code(s.v); }
void showValue(const PolygonCase& c, std::ostream& os) { os << "[" << c.family << "] " << to_code(c.v); }
void showValue(const PairCase& c, std::ostream& os) {
  os << "[" << c.family << "]\n    a = " << to_code(c.a) << "\n    b = " << to_code(c.b);
}
void showValue(const LineCase& c, std::ostream& os) {
  os << "[" << c.family << "] point = " << to_code(c.point) << ", normal = " << to_code(c.normal);
}
void showValue(const Motion& m, std::ostream& os) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", m.angle);
  os << "angle = " << buf << ", centre = " << to_code(m.centre) << ", shift = " << to_code(m.shift);
}

Polygon to_polygon(const Points& p) { return dda::make_polygon(p.data(), static_cast<int>(p.size())); }

Points points_of(const Polygon& poly) {
  Points p;
  for (int i = 0; i < poly.count; ++i) p.push_back(poly.vertex(i));
  return p;
}

bool is_valid(const Points& p) { return dda::validate_polygon(p.data(), static_cast<int>(p.size())).ok(); }

Points transformed(const Points& p, const Motion& m) {
  Points out;
  for (Vec2 v : p) out.push_back(m.apply(v));
  return out;
}

double segment_distance(Vec2 q, Vec2 a, Vec2 b) {
  // Relative to q, so that large offsets cancel before anything else.
  const Vec2 u = a - q, w = b - q, e = w - u;
  const double ee = dda::dot(e, e);
  const double s = ee > 0.0 ? std::clamp(-dda::dot(u, e) / ee, 0.0, 1.0) : 0.0;
  return dda::length(u + s * e);
}

double region_distance(Vec2 q, const Points& p) {
  bool inside = p.size() >= 3;
  double d = HUGE_VAL;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec2 a = p[i], b = p[(i + 1) % p.size()];
    if (dda::cross(b - a, q - a) < 0.0) inside = false;
    d = std::min(d, segment_distance(q, a, b));
  }
  return inside ? 0.0 : d;
}

double directed_hausdorff(const Points& from, const Points& to) {
  double h = 0.0;
  for (Vec2 x : from) h = std::max(h, region_distance(x, to));
  return h;
}

double hausdorff(const Points& p, const Points& q) { return std::max(directed_hausdorff(p, q), directed_hausdorff(q, p)); }

double max_abs_coordinate(const Points& p) {
  double c = 0.0;
  for (Vec2 v : p) c = std::max({c, std::fabs(v.x), std::fabs(v.y)});
  return c;
}

double diameter_of(const Points& p) {
  double d = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) d = std::max(d, dda::distance(p[i], p[j]));
  return d;
}

}  // namespace prop
