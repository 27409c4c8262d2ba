// The generators of generators.hpp. All randomness comes from rapidcheck
// (gen::exec), so every case is reproducible from the seed and shrinks.
#include "generators.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "exact.hpp"

namespace prop::gen {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegree = kPi / 180.0;

// Every helper below draws with operator* and so must run inside gen::exec.

// rapidcheck's inRange scales its range with the test "size" (size 0 gives
// only the lower bound); our ranges mean what they say, so fix the size.
rc::Gen<std::int64_t> raw_index(std::int64_t lo, std::int64_t hi) {
  return rc::gen::resize(rc::kNominalSize, rc::gen::inRange<std::int64_t>(lo, hi));
}

double draw_uniform(double lo, double hi) { return *uniform(lo, hi); }
double draw_log(double lo, double hi) { return *log_uniform(lo, hi); }
int draw_index(int lo, int hi) { return *index(lo, hi); }
// True with probability num / den.
bool draw_chance(int num, int den) { return draw_index(0, den) < num; }
Vec2 draw_direction() {
  const double phi = draw_uniform(0.0, 2.0 * kPi);
  return {std::cos(phi), std::sin(phi)};
}

Vec2 vertex_mean(const Points& p) {
  Vec2 m{};
  for (Vec2 v : p) m += v;
  return m / static_cast<double>(p.size());
}

double radius_about(const Points& p, Vec2 c) {
  double r = 0.0;
  for (Vec2 v : p) r = std::max(r, dda::distance(v, c));
  return r;
}

// Outward unit normal of edge i (from v[i] to v[i+1]) of a CCW polygon.
Vec2 edge_normal(const Points& p, std::size_t i) {
  return dda::normalized(dda::perp_right(p[(i + 1) % p.size()] - p[i]));
}

// Index of the vertex of p extreme in direction -u (smallest u . w).
std::size_t lowest_along(const Points& p, Vec2 u) {
  std::size_t j = 0;
  for (std::size_t k = 1; k < p.size(); ++k)
    if (dda::dot(u, p[k]) < dda::dot(u, p[j])) j = k;
  return j;
}

// x -> pivot + s R(angle) (x - pivot).
Points similar(const Points& p, double s, double angle, Vec2 pivot) {
  Points out;
  for (Vec2 v : p) out.push_back(pivot + s * dda::rotate(v - pivot, angle));
  return out;
}

Points moved(const Points& p, Vec2 t) {
  Points out;
  for (Vec2 v : p) out.push_back(v + t);
  return out;
}

// ---- base shapes in a local frame, diameter about 1 .. 2 ------------------

Points hull_shape() {
  const int k = draw_index(3, 9);
  Points pts;
  for (int i = 0; i < k; ++i) pts.push_back({draw_uniform(-1.0, 1.0), draw_uniform(-1.0, 1.0)});
  return exact::convex_hull(pts);
}

Points regular_shape(int n) {
  const bool exact_regular = draw_chance(1, 3);
  const double phase = draw_uniform(0.0, 2.0 * kPi);
  const double angle_jitter = exact_regular ? 0.0 : draw_uniform(0.0, 0.45);
  const double radius_jitter = exact_regular ? 0.0 : draw_uniform(0.0, 0.3);
  Points pts;
  for (int i = 0; i < n; ++i) {
    const double t = phase + 2.0 * kPi * (i + angle_jitter * draw_uniform(-0.5, 0.5)) / n;
    const double r = 1.0 - radius_jitter * draw_uniform(0.0, 1.0);
    pts.push_back({r * std::cos(t), r * std::sin(t)});
  }
  return exact::convex_hull(pts);  // radius jitter may dent it: keep it convex
}

Points sliver_shape() {
  const double alpha = draw_log(0.5 * kDegree, 30.0 * kDegree);
  const double r = draw_uniform(0.2, 1.5);
  return {{-0.5, 0.0}, {0.5, 0.0}, {r * std::cos(alpha) - 0.5, r * std::sin(alpha)}};
}

Points thin_shape() {
  const double w = draw_log(1e-6, 1.0);
  const double shear = draw_chance(1, 2) ? 0.0 : draw_uniform(-2.0, 2.0) * w;
  return {{-0.5, -w / 2}, {0.5, -w / 2}, {0.5 + shear, w / 2}, {-0.5 + shear, w / 2}};
}

Points cornercut_shape() {
  Points p = draw_chance(1, 2) ? regular_shape(draw_index(3, 7)) : hull_shape();
  const int cuts = draw_index(1, 3);
  for (int c = 0; c < cuts && p.size() < 8 && p.size() >= 3; ++c) {
    const double d = diameter_of(p);
    const std::size_t i = static_cast<std::size_t>(draw_index(0, static_cast<int>(p.size())));
    const Vec2 v = p[i], prev = p[(i + p.size() - 1) % p.size()], next = p[(i + 1) % p.size()];
    const double e1 = draw_log(1e-6, 1e-2) * d;
    const double e2 = draw_chance(1, 2) ? e1 : draw_log(1e-6, 1e-2) * d;
    const Vec2 c1 = v + e1 * dda::normalized(prev - v);
    const Vec2 c2 = v + e2 * dda::normalized(next - v);
    p[i] = c1;
    p.insert(p.begin() + static_cast<std::ptrdiff_t>(i) + 1, c2);
  }
  return p;
}

// A sharp corner: a needle (isosceles triangle) or a thin kite whose apex
// angle is log-uniform in 1e-6 .. 0.3 rad (down to 1e-6 rad, far below the
// 0.5-degree slivers above): where distances to edge lines and Euclidean
// distances to the polygon differ by 1 / sin(theta / 2).
Points needle_shape() {
  const double theta = draw_log(1e-6, 0.3);
  const double h = std::tan(0.5 * theta);
  if (draw_chance(1, 2)) return {{-0.5, 0.0}, {0.5, -h}, {0.5, h}};
  const double back = draw_uniform(0.5, 0.9);  // the kite's blunt back vertex, beyond the wide end
  return {{-0.5, 0.0}, {0.4, -0.9 * h}, {0.4 + back * 0.1, 0.0}, {0.4, 0.9 * h}};
}

Points grid_shape() {
  const int k = draw_index(3, 9);
  Points pts;
  for (int i = 0; i < k; ++i) pts.push_back({0.25 * draw_index(0, 7) - 0.75, 0.25 * draw_index(0, 7) - 0.75});
  return exact::convex_hull(pts);
}

Points base_shape(std::string& family) {
  switch (draw_index(0, 16)) {
    case 14: case 15: family = "needle"; return needle_shape();
    case 0: case 1: case 2: family = "hull"; return hull_shape();
    case 3: case 4: case 5: family = "regular"; return regular_shape(draw_index(3, 9));
    case 6: case 7: family = "sliver"; return sliver_shape();
    case 8: case 9: family = "thin"; return thin_shape();
    case 10: case 11: case 12: family = "cornercut"; return cornercut_shape();
    default: family = "grid"; return grid_shape();
  }
}

// ---- the common similarity ------------------------------------------------

struct Similarity {
  double scale = 1.0, angle = 0.0;
  Vec2 offset{};
  Vec2 apply(Vec2 p) const { return offset + scale * dda::rotate(p, angle); }
};

double draw_angle() {
  switch (draw_index(0, 7)) {
    case 0: case 1: return 0.0;
    case 2: case 3: return (draw_chance(1, 2) ? 1.0 : -1.0) * draw_log(1e-12, 1e-3);
    default: return draw_uniform(-kPi, kPi);
  }
}

// An offset coordinate for a polygon of size `size`: 0, of its size, up to
// 1e6 absolute (the first families; capped at 1e9 times the size
// for tiny blocks), or "far": 1e6 .. 1e9 times its size (offsets
// up to 1e9 relative to the block size).
double draw_offset_coordinate(double size) {
  const double sign = draw_chance(1, 2) ? 1.0 : -1.0;
  switch (draw_index(0, 4)) {
    case 0: return 0.0;
    case 1: return draw_uniform(-10.0, 10.0) * size;
    case 2: return sign * std::min(draw_log(1.0, 1e6), 1e9 * size);  // at most 1e9 times the size
    default: return sign * draw_log(1e6, 1e9) * size;
  }
}

// A scale: 1, 0.1 .. 10, or tiny (1e-6 .. 1e-4) or huge
// (1e4 .. 1e6) blocks.
double draw_scale(std::string& family) {
  switch (draw_index(0, 6)) {
    case 0: case 1: return 1.0;
    case 2: case 3: return draw_log(0.1, 10.0);
    case 4: family += " scale=tiny"; return draw_log(1e-6, 1e-4);
    default: family += " scale=huge"; return draw_log(1e4, 1e6);
  }
}

Similarity draw_similarity(std::string& family) {
  Similarity s;
  if (draw_chance(1, 6)) {
    // Exact: power-of-two scale and an integer offset keep dyadic
    // coordinates (the grid family) exactly collinear.
    family += " world=dyadic";
    s.scale = std::ldexp(1.0, draw_index(-4, 5));
    s.offset = {static_cast<double>(*raw_index(-1000000, 1000001)), static_cast<double>(*raw_index(-1000000, 1000001))};
    return s;
  }
  family += " world=similar";
  s.scale = draw_scale(family);
  s.angle = draw_angle();
  s.offset = {draw_offset_coordinate(s.scale), draw_offset_coordinate(s.scale)};
  return s;
}

Points apply_similarity(const Similarity& s, const Points& p) {
  Points out;
  for (Vec2 v : p) out.push_back(s.apply(v));
  return out;
}

// ---- pair families --------------------------------------------------------

// A gap along a contact normal: 0 (exact contact) or +-1e-16 .. 1e-2 of size.
// A gap along a contact normal: 0 (exact contact), +-1e-16 .. 1e-2 of size,
// or a deep penetration of 1e-2 .. 0.5 of size (a needle's tip deep in the
// other block: the wedge against a square).
double draw_gap(double size, std::string& family) {
  switch (draw_index(0, 6)) {
    case 0: case 1: case 2: family += " gap=0"; return 0.0;
    case 3: family += " gap>0"; return draw_log(1e-16, 1e-2) * size;
    case 4: family += " gap<0"; return -draw_log(1e-16, 1e-2) * size;
    default: family += " gap<<0"; return -draw_log(1e-2, 0.5) * size;
  }
}

// A second shape sized relative to A (ratio 1, or 0.05 .. 20) and turned.
Points partner_shape(double size_a, std::string& family) {
  std::string sub;
  Points b = base_shape(sub);
  family += "(" + sub + ")";
  const double ratio = draw_chance(1, 2) ? 1.0 : draw_log(0.05, 20.0);
  return similar(b, ratio * size_a / std::max(diameter_of(b), 1e-300), draw_uniform(-kPi, kPi), {0.0, 0.0});
}

// Places b so that its vertex extreme along -u sits at `at` (bit for bit).
Points place_extreme_at(const Points& b, Vec2 u, Vec2 at) {
  const std::size_t j = lowest_along(b, u);
  Points out;
  for (std::size_t k = 0; k < b.size(); ++k) out.push_back(k == j ? at : at + (b[k] - b[j]));
  return out;
}

Vec2 draw_interior_point(const Points& p) {
  Vec2 s{};
  double w = 0.0;
  for (Vec2 v : p) {
    const double wi = draw_uniform(0.0, 1.0) + 1e-3;
    s += wi * v;
    w += wi;
  }
  return s / w;
}

PairCase independent_pair(Points a, std::string family) {
  Points b = partner_shape(diameter_of(a), family);
  const Vec2 ca = vertex_mean(a), cb = vertex_mean(b);
  const double reach = radius_about(a, ca) + radius_about(b, cb);
  const Vec2 target = ca + draw_uniform(0.0, 1.1) * reach * draw_direction();
  return {a, moved(b, target - cb), "independent " + family};
}

PairCase rotated_copy(Points a, std::string family) {
  Vec2 pivot;
  switch (draw_index(0, 3)) {
    case 0: pivot = vertex_mean(a); family += " about=centre"; break;
    case 1: pivot = a[static_cast<std::size_t>(draw_index(0, static_cast<int>(a.size())))]; family += " about=vertex"; break;
    default: pivot = vertex_mean(a) + draw_uniform(0.0, 2.0) * diameter_of(a) * draw_direction(); family += " about=point";
  }
  const double angle = (draw_chance(1, 2) ? 1.0 : -1.0) * draw_log(1e-12, 1e-1);
  return {a, similar(a, 1.0, angle, pivot), "rotated-copy " + family};
}

PairCase shifted_copy(Points a, std::string family) {
  const Vec2 t = draw_log(1e-16, 1.0) * diameter_of(a) * draw_direction();
  return {a, moved(a, t), "shifted-copy " + family};
}

// Sometimes turns a contact by a tiny angle (1e-12 .. 1e-3 rad, either
// sense) about a point of contact, which stays shared bit for bit: a hinge
// opening a hair-thin gap or closing into a hair-thin overlap.
Points hinged(const Points& b, Vec2 pivot, std::string& family) {
  if (!draw_chance(1, 3)) return b;
  family += " hinged";
  return similar(b, 1.0, (draw_chance(1, 2) ? 1.0 : -1.0) * draw_log(1e-12, 1e-3), pivot);
}

PairCase vertex_vertex(Points a, std::string family) {
  const std::size_t n = a.size(), i = static_cast<std::size_t>(draw_index(0, static_cast<int>(n)));
  const double lambda = draw_uniform(0.0, 1.0);
  const Vec2 u = dda::normalized(lambda * edge_normal(a, (i + n - 1) % n) + (1.0 - lambda) * edge_normal(a, i));
  const Points b = partner_shape(diameter_of(a), family);
  const double g = draw_gap(diameter_of(a), family);
  const Vec2 at = g == 0.0 ? a[i] : a[i] + g * u;
  const Points placed = place_extreme_at(b, u, at);
  return {a, hinged(placed, at, family), "vertex-vertex " + family};
}

PairCase vertex_edge(Points a, std::string family) {
  const std::size_t n = a.size(), i = static_cast<std::size_t>(draw_index(0, static_cast<int>(n)));
  const double s = draw_chance(1, 4) ? 0.5 : draw_uniform(0.02, 0.98);
  const Vec2 u = edge_normal(a, i);
  const Points b = partner_shape(diameter_of(a), family);
  const double g = draw_gap(diameter_of(a), family);
  const Vec2 at = dda::lerp(a[i], a[(i + 1) % n], s) + g * u;
  const Points placed = place_extreme_at(b, u, at);
  return {a, hinged(placed, at, family), "vertex-edge " + family};
}

PairCase edge_edge(Points a, std::string family) {
  const std::size_t n = a.size(), i = static_cast<std::size_t>(draw_index(0, static_cast<int>(n)));
  const Vec2 p = a[i], q = a[(i + 1) % n], e = q - p, u = edge_normal(a, i);
  const double len = dda::length(e);
  // B's contact edge runs from hi to lo along A's edge line (opposite sense).
  double s_lo = 0.0, s_hi = 1.0;
  Vec2 lo = p, hi = q;
  if (draw_chance(1, 2)) {
    family += " part";
    s_lo = draw_uniform(-0.5, 1.5);
    s_hi = draw_uniform(-0.5, 1.5);
    if (s_hi < s_lo) std::swap(s_lo, s_hi);
    if (s_hi - s_lo < 1e-3) s_hi = s_lo + 1e-3;
    lo = dda::lerp(p, q, s_lo);
    hi = dda::lerp(p, q, s_hi);
  } else {
    family += " full";
  }
  Points pts = {hi, lo};
  const int k = draw_index(1, 7);
  for (int c = 0; c < k; ++c) {
    const double s = draw_uniform(s_lo - 0.5, s_hi + 0.5);
    pts.push_back(p + s * e + draw_uniform(0.05, 1.0) * len * u);
  }
  Points b = exact::convex_hull(pts);
  const double g = draw_gap(diameter_of(a), family);
  if (g != 0.0) b = moved(b, g * u);
  else b = hinged(b, draw_chance(1, 2) ? hi : lo, family);
  return {a, b, "edge-edge " + family};
}

// Edges crossing at a small angle: B's edge laid along A's edge
// i (B outside it), then turned by +-1e-6 .. 2e-2 rad about a point of that
// edge (or of the edge moved by a gap, for near-parallel edges that cross
// or just miss): a sliver of overlap on one side of the crossing.
PairCase crossing(Points a, std::string family) {
  const std::size_t n = a.size(), i = static_cast<std::size_t>(draw_index(0, static_cast<int>(n)));
  const Vec2 u = edge_normal(a, i);
  const Points b = partner_shape(diameter_of(a), family);
  const Vec2 on = dda::lerp(a[i], a[(i + 1) % n], draw_uniform(0.0, 1.0));
  // B's edge j turned onto A's edge line, its start vertex at `on`.
  const std::size_t j = static_cast<std::size_t>(draw_index(0, static_cast<int>(b.size())));
  const Vec2 eb = b[(j + 1) % b.size()] - b[j];
  const Vec2 ea = a[i] - a[(i + 1) % n];  // B's edge runs against A's (B lies outside edge i)
  const double align = std::atan2(dda::cross(eb, ea), dda::dot(eb, ea));
  Points placed = similar(b, 1.0, align, b[j]);
  placed = moved(placed, on - placed[j]);
  placed[j] = on;
  const double g = draw_chance(1, 2) ? 0.0 : (draw_chance(1, 2) ? 1.0 : -1.0) * draw_log(1e-16, 1e-3) * diameter_of(a);
  const Vec2 pivot = dda::lerp(a[i], a[(i + 1) % n], draw_uniform(-0.5, 1.5));
  const double angle = (draw_chance(1, 2) ? 1.0 : -1.0) * draw_log(1e-6, 2e-2);
  family += g == 0.0 ? " gap=0" : " gap!=0";
  return {a, moved(similar(placed, 1.0, angle, pivot), g * u), "crossing " + family};
}

// A shared vertex with collinear edges: B's edge k starts at A's
// vertex i (bit for bit) and runs along A's edge i, in the same sense (both
// interiors on the same side: an overlap along a collinear edge) or, turned
// by pi, along the extension of A's edge i - 1 ... edge i (B beside A).
PairCase shared_vertex(Points a, std::string family) {
  const std::size_t n = a.size(), i = static_cast<std::size_t>(draw_index(0, static_cast<int>(n)));
  const Points b = partner_shape(diameter_of(a), family);
  const std::size_t k = static_cast<std::size_t>(draw_index(0, static_cast<int>(b.size())));
  const bool same = draw_chance(1, 2);
  const Vec2 ea = same ? a[(i + 1) % n] - a[i] : a[i] - a[(i + 1) % n];
  const Vec2 eb = b[(k + 1) % b.size()] - b[k];
  const double align = std::atan2(dda::cross(eb, ea), dda::dot(eb, ea));
  Points placed = similar(b, 1.0, align, b[k]);
  placed = moved(placed, a[i] - placed[k]);
  placed[k] = a[i];
  family += same ? " sense=same" : " sense=opposite";
  return {a, placed, "shared-vertex " + family};
}

PairCase contained(Points a, std::string family) {
  Vec2 c;
  switch (draw_index(0, 3)) {
    case 0: c = vertex_mean(a); family += " about=centre"; break;
    case 1: c = a[static_cast<std::size_t>(draw_index(0, static_cast<int>(a.size())))]; family += " about=vertex"; break;
    default: c = draw_interior_point(a); family += " about=interior";
  }
  double k = 0.0;
  switch (draw_index(0, 5)) {
    case 0: k = 1.0 - draw_log(1e-15, 1e-3); break;
    case 1: k = 1.0 + draw_log(1e-15, 1e-3); break;
    default: k = draw_log(1e-3, 0.999);
  }
  Points b;
  for (Vec2 v : a) b.push_back(v == c ? c : c + k * (v - c));
  return {a, b, "contained " + family};
}

// Two hulls of grid points, the second shifted by whole grid steps: exact
// shared vertices, collinear edges and corner contacts are common.
PairCase grid_pair() {
  const Points a = grid_shape(), b = grid_shape();
  const Vec2 t{0.25 * draw_index(-6, 7), 0.25 * draw_index(-6, 7)};
  return {a, moved(b, t), "grid"};
}

Vec2 draw_sample_point(const Points& p, Vec2 centre) {
  const std::size_t n = p.size(), i = static_cast<std::size_t>(draw_index(0, static_cast<int>(n)));
  const double d = diameter_of(p);
  switch (draw_index(0, 6)) {
    case 0: return draw_interior_point(p);
    case 1: {
      const Vec2 on = dda::lerp(p[i], p[(i + 1) % n], draw_uniform(0.0, 1.0));
      return on + (draw_chance(1, 2) ? 1.0 : -1.0) * draw_log(1e-16, 1e-2) * d * edge_normal(p, i);
    }
    case 2: return p[i];
    case 3: return centre + draw_log(1e-12, 1e-1) * d * draw_direction();
    case 4: return centre;
    default: return vertex_mean(p) + draw_uniform(0.0, 2.0) * d * draw_direction();
  }
}

}  // namespace

rc::Gen<double> uniform(double lo, double hi) {
  return rc::gen::map(raw_index(0, std::int64_t{1} << 53),
                      [lo, hi](std::int64_t k) { return lo + (hi - lo) * std::ldexp(static_cast<double>(k), -53); });
}

rc::Gen<double> log_uniform(double lo, double hi) {
  return rc::gen::map(uniform(std::log(lo), std::log(hi)),
                      [lo, hi](double x) { return std::clamp(std::exp(x), lo, hi); });
}

rc::Gen<int> index(int lo, int hi) { return rc::gen::resize(rc::kNominalSize, rc::gen::inRange<int>(lo, hi)); }

rc::Gen<PolygonCase> polygon() {
  return rc::gen::exec([] {
    PolygonCase c;
    c.v = base_shape(c.family);
    const Similarity s = draw_similarity(c.family);
    c.v = apply_similarity(s, c.v);
    return c;
  });
}

rc::Gen<PairCase> polygon_pair() {
  return rc::gen::exec([] {
    std::string fa;
    Points a = base_shape(fa);
    PairCase pc;
    switch (draw_index(0, 23)) {
      case 19: case 20: pc = crossing(a, fa); break;
      case 21: case 22: pc = shared_vertex(a, fa); break;
      case 0: case 1: case 2: pc = independent_pair(a, fa); break;
      case 3: pc = {a, a, "identical " + fa}; break;
      case 4: case 5: pc = rotated_copy(a, fa); break;
      case 6: pc = shifted_copy(a, fa); break;
      case 7: case 8: case 9: pc = vertex_vertex(a, fa); break;
      case 10: case 11: pc = vertex_edge(a, fa); break;
      case 12: case 13: case 14: pc = edge_edge(a, fa); break;
      case 15: case 16: pc = contained(a, fa); break;
      default: pc = grid_pair();
    }
    const Similarity s = draw_similarity(pc.family);
    pc.a = apply_similarity(s, pc.a);
    pc.b = apply_similarity(s, pc.b);
    if (draw_chance(1, 2)) {
      std::swap(pc.a, pc.b);
      pc.family += " swapped";
    }
    return pc;
  });
}

rc::Gen<LineCase> cutting_line(const Points& p) {
  return rc::gen::exec([p] {
    const std::size_t n = p.size(), i = static_cast<std::size_t>(draw_index(0, static_cast<int>(n)));
    const double d = diameter_of(p);
    LineCase l;
    switch (draw_index(0, 6)) {
      case 0: {
        const Vec2 c = vertex_mean(p);
        l = {c + draw_uniform(-0.6, 0.6) * d * draw_direction(), draw_direction(), "random"};
        break;
      }
      case 1: l = {p[i], draw_direction(), "through-vertex"}; break;
      case 2: {
        const std::size_t j = (i + static_cast<std::size_t>(draw_index(1, static_cast<int>(n)))) % n;
        l = {p[i], dda::normalized(dda::perp_right(p[j] - p[i])), "through-two-vertices"};
        break;
      }
      case 3: l = {p[i], (draw_chance(1, 2) ? 1.0 : -1.0) * edge_normal(p, i), "along-edge"}; break;
      case 4: {
        const double lambda = draw_uniform(0.0, 1.0);
        const Vec2 u = lambda * edge_normal(p, (i + n - 1) % n) + (1.0 - lambda) * edge_normal(p, i);
        l = {p[i], (draw_chance(1, 2) ? 1.0 : -1.0) * dda::normalized(u), "tangent-at-vertex"};
        break;
      }
      default: l = {p[i] + draw_uniform(0.0, 1.0) * (p[(i + 1) % n] - p[i]), draw_direction(), "through-edge-point"};
    }
    if (draw_chance(1, 3)) {
      l.point += (draw_chance(1, 2) ? 1.0 : -1.0) * draw_log(1e-16, 1e-2) * d * l.normal;
      l.family += " shifted";
    }
    return l;
  });
}

rc::Gen<Samples> sample_points(const Points& p, Vec2 centre, int count) {
  return rc::gen::exec([p, centre, count] {
    Samples s;
    for (int i = 0; i < count; ++i) s.v.push_back(draw_sample_point(p, centre));
    return s;
  });
}

rc::Gen<Motion> rigid_motion(const Points& p) {
  return rc::gen::exec([p] {
    const double d = diameter_of(p);
    Motion m;
    m.angle = draw_angle();
    m.centre = draw_chance(1, 3) ? Vec2{0.0, 0.0} : vertex_mean(p) + draw_uniform(0.0, 2.0) * d * draw_direction();
    m.shift = {draw_offset_coordinate(d), draw_offset_coordinate(d)};
    return m;
  });
}

}  // namespace prop::gen
