// Exact reference geometry (the only translation unit that includes CGAL).
//
// Two flavours of EPECK are used:
//  - Epeck itself (lazy exact: interval filters, exact fallback) for hulls and
//    point location on points built from the input doubles;
//  - Epeck::Exact_kernel, the exact kernel that EPECK wraps (Cartesian
//    coordinates in CGAL::Exact_rational), for chains of constructions
//    (clipping, moments), where a lazy DAG would only add overhead because
//    every value is needed exactly anyway.
// Numbers are rounded to double once, from their exact value.
#include "exact.hpp"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace prop::exact {

namespace {

using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using LP = Epeck::Point_2;  // lazy exact point
using LFT = Epeck::FT;
using EK = Epeck::Exact_kernel;  // Simple_cartesian<Exact_rational>
using Q = EK::FT;
using QP = EK::Point_2;

double rounded(const Q& x) { return CGAL::to_double(x); }
Vec2 rounded(const QP& p) { return {rounded(p.x()), rounded(p.y())}; }
Points rounded(const std::vector<QP>& p) {
  Points out;
  for (const QP& q : p) out.push_back(rounded(q));
  return out;
}
QP exact_point(Vec2 v) { return QP(Q(v.x), Q(v.y)); }  // a double is a rational: exact
std::vector<QP> exact_points(const Points& p) {
  std::vector<QP> out;
  for (Vec2 v : p) out.push_back(exact_point(v));
  return out;
}
LP lazy_point(Vec2 v) { return LP(v.x, v.y); }

std::vector<LP> hull(std::vector<LP> pts) {
  std::vector<LP> h;
  CGAL::convex_hull_2(pts.begin(), pts.end(), std::back_inserter(h));
  return h;
}

std::vector<QP> exact_of(const std::vector<LP>& p) {
  std::vector<QP> out;
  for (const LP& q : p) out.push_back(CGAL::exact(q));
  return out;
}

Q cross(const QP& o, const QP& a, const QP& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Twice the signed area (shoelace about the first vertex).
Q twice_area(const std::vector<QP>& p) {
  Q s = 0;
  for (std::size_t i = 1; i + 1 < p.size(); ++i) s += cross(p[0], p[i], p[i + 1]);
  return s;
}

// Exact half-plane a x + b y + c >= 0; `norm` ~ |(a, b)| (in double: it only
// scales a tolerance shift, so its rounding is immaterial).
struct HP {
  Q a, b, c;
  double norm = 1.0;
};

// Inner (left) side of the directed edge p -> q: cross(q - p, x - p) >= 0.
HP edge_hp(Vec2 p, Vec2 q) {
  HP h;
  h.a = Q(p.y) - Q(q.y);
  h.b = Q(q.x) - Q(p.x);
  h.c = -(h.a * Q(p.x) + h.b * Q(p.y));
  h.norm = std::hypot(rounded(h.a), rounded(h.b));
  return h;
}

// normal . (x - point) <= 0.
HP line_hp(const HalfPlane& l) {
  HP h;
  h.a = -Q(l.normal.x);
  h.b = -Q(l.normal.y);
  h.c = Q(l.normal.x) * Q(l.point.x) + Q(l.normal.y) * Q(l.point.y);
  h.norm = std::hypot(l.normal.x, l.normal.y);
  return h;
}

// The half-plane moved outward by the length s (inward for s < 0).
HP shifted(const HP& h, double s) {
  HP g = h;
  g.c += Q(s) * Q(h.norm);
  return g;
}

Q eval(const HP& h, const QP& p) { return h.a * p.x() + h.b * p.y() + h.c; }

// Sutherland-Hodgman step for a convex polygon: keeps the closed inner side,
// adds the exact crossing where an edge changes side strictly.
std::vector<QP> clip(const std::vector<QP>& in, const HP& h) {
  const std::size_t n = in.size();
  std::vector<Q> f(n);
  bool all_in = true;
  for (std::size_t i = 0; i < n; ++i) {
    f[i] = eval(h, in[i]);
    if (CGAL::sign(f[i]) == CGAL::NEGATIVE) all_in = false;
  }
  if (all_in) return in;
  std::vector<QP> out;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;
    const CGAL::Sign si = CGAL::sign(f[i]), sj = CGAL::sign(f[j]);
    if (si != CGAL::NEGATIVE) out.push_back(in[i]);
    if ((si == CGAL::POSITIVE && sj == CGAL::NEGATIVE) || (si == CGAL::NEGATIVE && sj == CGAL::POSITIVE)) {
      const Q s = f[i] / (f[i] - f[j]);
      out.emplace_back(in[i].x() + s * (in[j].x() - in[i].x()), in[i].y() + s * (in[j].y() - in[i].y()));
    }
  }
  return out;
}

// Clips by every half-plane; a result without interior comes back empty.
std::vector<QP> clip_all(std::vector<QP> p, const std::vector<HP>& hps, double shift) {
  for (const HP& h : hps) {
    p = clip(p, shift == 0.0 ? h : shifted(h, shift));
    if (p.size() < 3) return {};
  }
  if (CGAL::sign(twice_area(p)) != CGAL::POSITIVE) return {};
  return p;
}

}  // namespace

const char* name(Contact c) {
  switch (c) {
    case Contact::kApart: return "apart";
    case Contact::kTouching: return "touching";
    case Contact::kOverlapping: return "overlapping";
  }
  return "?";
}

Points convex_hull(const Points& pts) {
  std::vector<LP> in;
  for (Vec2 v : pts) in.push_back(lazy_point(v));
  return rounded(exact_of(hull(in)));  // hull vertices are input doubles: rounding is exact
}

bool is_strictly_convex_ccw(const Points& p) {
  const std::size_t n = p.size();
  if (n < 3) return false;
  // Upper half-turn [0, pi) of an edge direction, decided by exact comparisons.
  auto upper = [&](std::size_t i) {
    const Vec2 a = p[i], b = p[(i + 1) % n];
    return b.y > a.y || (b.y == a.y && b.x > a.x);
  };
  int wraps = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t h = (i + n - 1) % n, j = (i + 1) % n;
    if (CGAL::orientation(lazy_point(p[h]), lazy_point(p[i]), lazy_point(p[j])) != CGAL::LEFT_TURN) return false;
    // Each strict left turn is less than pi, so the direction passes angle 0
    // exactly once per winding: count lower -> upper transitions.
    if (!upper(h) && upper(i)) ++wraps;
  }
  return wraps == 1;
}

PairTruth pair_truth(const Points& a, const Points& b) {
  PairTruth t;
  // Exact intersection: B clipped by the inner half-plane of every edge of A.
  std::vector<HP> hps;
  for (std::size_t i = 0; i < a.size(); ++i) hps.push_back(edge_hp(a[i], a[(i + 1) % a.size()]));
  const std::vector<QP> ip = clip_all(exact_points(b), hps, 0.0);
  const Q area2 = ip.empty() ? Q(0) : twice_area(ip);
  t.area = rounded(area2) / 2.0;

  // D = B - A; the sign of the origin's position in D decides touching.
  std::vector<LP> diff;
  for (Vec2 bj : b)
    for (Vec2 ai : a) diff.emplace_back(LFT(bj.x) - LFT(ai.x), LFT(bj.y) - LFT(ai.y));
  const std::vector<LP> d = hull(diff);
  const LP origin(0, 0);
  const CGAL::Bounded_side side = CGAL::bounded_side_2(d.begin(), d.end(), origin, Epeck());
  if (CGAL::sign(area2) == CGAL::POSITIVE) t.contact = Contact::kOverlapping;
  else if (side == CGAL::ON_BOUNDARY || side == CGAL::ON_BOUNDED_SIDE) t.contact = Contact::kTouching;
  else t.contact = Contact::kApart;
  // A disagreement of the two exact views (area > 0 vs origin strictly
  // inside D) would be a bug of this reference; pair_truth reports it by
  // making sigma NaN, which every check treats as a failure.
  const bool inside = side == CGAL::ON_BOUNDED_SIDE;
  const bool overlapping = t.contact == Contact::kOverlapping;

  const std::vector<QP> dq = exact_of(d);
  const QP o(0, 0);
  t.sigma = -HUGE_VAL;
  double sep2 = HUGE_VAL;
  for (std::size_t i = 0; i < dq.size(); ++i) {
    const QP& p = dq[i];
    const QP& q = dq[(i + 1) % dq.size()];
    const double len = std::sqrt(rounded(CGAL::squared_distance(p, q)));
    t.sigma = std::max(t.sigma, -rounded(cross(p, q, o)) / len);
    sep2 = std::min(sep2, rounded(CGAL::squared_distance(o, EK::Segment_2(p, q))));
  }
  t.separation = side == CGAL::ON_UNBOUNDED_SIDE ? std::sqrt(sep2) : 0.0;
  if (inside != overlapping) t.sigma = std::nan("");
  return t;
}

Points entrance_block(const Points& a, const Points& b, Vec2 a0) {
  std::vector<LP> pts;
  const LFT x0(a0.x), y0(a0.y);
  for (Vec2 bj : b)
    for (Vec2 ai : a) pts.emplace_back(LFT(bj.x) - LFT(ai.x) + x0, LFT(bj.y) - LFT(ai.y) + y0);
  return rounded(exact_of(hull(pts)));
}

Moments area_moments(const Points& pts) {
  // Deliberately not the kernel's Green's-theorem sums: a fan of triangles
  // from the vertex mean m, each with the closed forms
  //   int x^2 = A/6 (x1^2 + x2^2 + x3^2 + x1 x2 + x2 x3 + x3 x1),
  //   int x y = A/12 (2 x1 y1 + 2 x2 y2 + 2 x3 y3 + x1 y2 + x2 y1 + x1 y3 + x3 y1 + x2 y3 + x3 y2),
  // then the parallel-axis theorem to move to the centroid.
  const std::vector<QP> p = exact_points(pts);
  const std::size_t n = p.size();
  Q mx = 0, my = 0;
  for (const QP& v : p) {
    mx += v.x();
    my += v.y();
  }
  mx /= Q(static_cast<int>(n));
  my /= Q(static_cast<int>(n));
  Q s = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;  // about m
  for (std::size_t i = 0; i < n; ++i) {
    const QP& u = p[i];
    const QP& w = p[(i + 1) % n];
    const Q x1 = 0, y1 = 0, x2 = u.x() - mx, y2 = u.y() - my, x3 = w.x() - mx, y3 = w.y() - my;
    const Q at = (x2 * y3 - x3 * y2) / 2;
    s += at;
    sx += at * (x1 + x2 + x3) / 3;
    sy += at * (y1 + y2 + y3) / 3;
    sxx += at / 6 * (x1 * x1 + x2 * x2 + x3 * x3 + x1 * x2 + x2 * x3 + x3 * x1);
    syy += at / 6 * (y1 * y1 + y2 * y2 + y3 * y3 + y1 * y2 + y2 * y3 + y3 * y1);
    sxy += at / 12 * (2 * x1 * y1 + 2 * x2 * y2 + 2 * x3 * y3 + x1 * y2 + x2 * y1 + x1 * y3 + x3 * y1 + x2 * y3 + x3 * y2);
  }
  Moments m;
  m.area = rounded(s);
  const Q cx = sx / s, cy = sy / s;  // centroid relative to m
  m.cx = rounded(mx + cx);
  m.cy = rounded(my + cy);
  m.sxx = rounded(sxx - s * cx * cx);
  m.syy = rounded(syy - s * cy * cy);
  m.sxy = rounded(sxy - s * cx * cy);
  return m;
}

double exit_distance(const Points& pts, Vec2 q) {
  const std::vector<QP> p = exact_points(pts);
  const QP x = exact_point(q);
  double d = HUGE_VAL;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const QP& a = p[i];
    const QP& b = p[(i + 1) % p.size()];
    d = std::min(d, rounded(cross(a, b, x)) / std::sqrt(rounded(CGAL::squared_distance(a, b))));
  }
  return d;
}

Location locate(const Points& pts, Vec2 q) {
  std::vector<LP> p;
  for (Vec2 v : pts) p.push_back(lazy_point(v));
  switch (CGAL::bounded_side_2(p.begin(), p.end(), lazy_point(q), Epeck())) {
    case CGAL::ON_BOUNDED_SIDE: return Location::kInside;
    case CGAL::ON_BOUNDARY: return Location::kOnBoundary;
    case CGAL::ON_UNBOUNDED_SIDE: return Location::kOutside;
  }
  return Location::kOutside;
}

// ---------------------------------------------------------------------------

struct Region::Impl {
  double t = 0.0;
  std::vector<HP> outer_hps;  // every half-plane moved out by t
  std::vector<QP> p, pin, pout;
  Q area2 = 0;
};

Region::Region(const std::vector<Points>& polys, const std::vector<HalfPlane>& lines, double t)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.t = t;
  std::vector<HP> hps;
  for (const Points& poly : polys)
    for (std::size_t i = 0; i < poly.size(); ++i) hps.push_back(edge_hp(poly[i], poly[(i + 1) % poly.size()]));
  for (const HalfPlane& l : lines) hps.push_back(line_hp(l));
  for (const HP& h : hps) m.outer_hps.push_back(shifted(h, t));

  // P and P_in start from the first polygon, which contains both.
  const std::vector<QP> first = exact_points(polys.at(0));
  const std::vector<HP> others(hps.begin() + static_cast<std::ptrdiff_t>(polys[0].size()), hps.end());
  m.p = clip_all(first, others, 0.0);
  m.area2 = m.p.empty() ? Q(0) : twice_area(m.p);
  m.pin = clip_all(first, hps, -t);

  // P_out starts from a box around every input, grown until P_out keeps off
  // its sides (a corner of angle theta moves out by t / sin(theta / 2)).
  dda::Aabb box;
  for (const Points& poly : polys)
    for (Vec2 v : poly) {
      box.lo = {std::min(box.lo.x, v.x), std::min(box.lo.y, v.y)};
      box.hi = {std::max(box.hi.x, v.x), std::max(box.hi.y, v.y)};
    }
  double margin = 4.0 * (box.hi.x - box.lo.x + box.hi.y - box.lo.y + t);
  for (int attempt = 0; attempt < 16; ++attempt, margin *= 16.0) {
    const Q x0 = Q(box.lo.x) - Q(margin), x1 = Q(box.hi.x) + Q(margin);
    const Q y0 = Q(box.lo.y) - Q(margin), y1 = Q(box.hi.y) + Q(margin);
    m.pout = clip_all({QP(x0, y0), QP(x1, y0), QP(x1, y1), QP(x0, y1)}, hps, t);
    const bool touches_box = std::any_of(m.pout.begin(), m.pout.end(), [&](const QP& q) {
      return q.x() == x0 || q.x() == x1 || q.y() == y0 || q.y() == y1;
    });
    if (!touches_box) break;
  }
}

Region::~Region() = default;

double Region::area() const { return rounded(impl_->area2) / 2.0; }
bool Region::has_interior() const { return CGAL::sign(impl_->area2) == CGAL::POSITIVE; }
bool Region::inner_empty() const { return impl_->pin.empty(); }
Points Region::vertices() const { return rounded(impl_->p); }
Points Region::inner() const { return rounded(impl_->pin); }
Points Region::outer() const { return rounded(impl_->pout); }

double Region::hausdorff_bound() const {
  if (impl_->pin.empty()) return HUGE_VAL;
  return directed_hausdorff(outer(), inner());
}

int Region::first_vertex_outside_outer(const Points& k) const {
  for (std::size_t i = 0; i < k.size(); ++i) {
    const QP x = exact_point(k[i]);
    for (const HP& h : impl_->outer_hps)
      if (CGAL::sign(eval(h, x)) == CGAL::NEGATIVE) return static_cast<int>(i);
  }
  return -1;
}

int Region::first_inner_vertex_outside(const Points& k) const {
  const std::vector<QP> kq = exact_points(k);
  for (std::size_t i = 0; i < impl_->pin.size(); ++i)
    for (std::size_t j = 0; j < kq.size(); ++j)
      if (CGAL::sign(cross(kq[j], kq[(j + 1) % kq.size()], impl_->pin[i])) == CGAL::NEGATIVE)
        return static_cast<int>(i);
  return -1;
}

}  // namespace prop::exact
