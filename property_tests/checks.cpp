// Implementation of the checks of checks.hpp (see there for the list and
// tolerances.hpp for every tolerance and its reason).
#include "checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>

#include "dda/overlap.hpp"
#include "dda/potential.hpp"
#include "exact.hpp"
#include "tolerances.hpp"

namespace prop {

namespace {

std::string format(const char* f, ...) {
  char buf[1024];
  va_list args;
  va_start(args, f);
  std::vsnprintf(buf, sizeof buf, f, args);
  va_end(args);
  return buf;
}

const char* name(dda::OverlapState s) {
  switch (s) {
    case dda::OverlapState::kSeparate: return "separate";
    case dda::OverlapState::kTouching: return "touching";
    case dda::OverlapState::kOverlapping: return "overlapping";
  }
  return "?";
}

const char* name(dda::PointLocation l) {
  switch (l) {
    case dda::PointLocation::kInside: return "inside";
    case dda::PointLocation::kOnBoundary: return "on boundary";
    case dda::PointLocation::kOutside: return "outside";
  }
  return "?";
}

// Verdicts overlap_state may give for an exact contact and its sigma.
bool verdict_allowed(dda::OverlapState s, const exact::PairTruth& t, double band) {
  using S = dda::OverlapState;
  switch (t.contact) {
    case exact::Contact::kOverlapping: return s == S::kOverlapping || (s == S::kTouching && -t.sigma <= band);
    case exact::Contact::kTouching: return s == S::kTouching;
    case exact::Contact::kApart: return s == S::kSeparate || (s == S::kTouching && t.sigma <= band);
  }
  return false;
}

// A clipping result K (intersection polygon, or a part of split_polygon) of a
// clipper with tolerance `tol`, against the exact region r (built with t =
// kSandwich tol): strictly convex, CCW and simple; no edge of length <= tol
// (the clipper's promise: no duplicate vertex); within P_out(t); covering
// P_in(t); area within area_tol of the exact area.
std::string check_clip_result(const char* what, const Points& k, const exact::Region& r, double tol, double area_tol) {
  if (!k.empty()) {
    if (k.size() < 3) return format("%s has %zu vertices", what, k.size());
    for (std::size_t i = 0; i < k.size(); ++i) {
      const double len = dda::distance(k[i], k[(i + 1) % k.size()]);
      if (!(len > tol)) return format("%s edge %zu has length %.3g <= tol %.3g", what, i, len, tol);
    }
    if (!exact::is_strictly_convex_ccw(k))
      return format("%s is not strictly convex, CCW and simple: %s", what, to_code(k).c_str());
    const int out = r.first_vertex_outside_outer(k);
    if (out >= 0) return format("%s vertex %d %s lies outside P_out(t)", what, out, to_code(k[static_cast<std::size_t>(out)]).c_str());
  }
  const double a = k.empty() ? 0.0 : dda::area(to_polygon(k));
  if (!(std::fabs(a - r.area()) <= area_tol))
    return format("%s area %.17g, exact %.17g, |diff| %.3g > %.3g", what, a, r.area(), std::fabs(a - r.area()), area_tol);
  if (!r.inner_empty()) {
    if (k.empty()) return format("%s is empty but the exact region shrunk by t is not (exact area %.17g)", what, r.area());
    const int in = r.first_inner_vertex_outside(k);
    if (in >= 0)
      return format("%s misses vertex %d %s of P_in(t)", what, in, to_code(r.inner()[static_cast<std::size_t>(in)]).c_str());
  }
  return "";
}

}  // namespace

std::string check_overlap(const Points& a, const Points& b, std::string* contact) {
  const Polygon pa = to_polygon(a), pb = to_polygon(b);
  const double tol = dda::pair_tolerance(pa, pb);
  const exact::PairTruth t = exact::pair_truth(a, b);
  if (contact) *contact = exact::name(t.contact);
  if (std::isnan(t.sigma)) return "exact reference: area > 0 and 'origin inside B - A' disagree";
  const double band = tol::kVerdictBand * tol;
  const dda::OverlapState ab = dda::overlap_state(pa, pb), ba = dda::overlap_state(pb, pa);
  // One verdict from one computation: kOverlapping iff the
  // intersection polygon is not empty, in either order.
  for (int order = 0; order < 2; ++order) {
    const Polygon& c = order == 0 ? pa : pb;
    const Polygon& g = order == 0 ? pb : pa;
    Polygon ip;
    const dda::OverlapState s = dda::overlap_and_intersection(c, g, tol, ip, nullptr);
    if ((s == dda::OverlapState::kOverlapping) != (ip.count >= 3))
      return format("overlap_and_intersection(%s) = %s with an intersection polygon of %d vertices; exact: %s, area %.17g",
                    order == 0 ? "A,B" : "B,A", name(s), ip.count, exact::name(t.contact), t.area);
  }
  if (verdict_allowed(ab, t, band) && verdict_allowed(ba, t, band)) return "";
  // An overlap deeper than the band may still be touching when the exact
  // intersection is a sliver thinner than the clipper's resolution: its
  // inner parallel region P_in(kSandwich tol) is empty, so the IP may be
  // empty (check_clip_result) and the verdict follows the IP.
  if (t.contact == exact::Contact::kOverlapping && ab != dda::OverlapState::kSeparate &&
      ba != dda::OverlapState::kSeparate) {
    const exact::Region r({b, a}, {}, tol::kSandwich * tol);
    if (r.inner_empty()) return "";
  }
  return format("overlap_state(A,B) = %s, (B,A) = %s; exact: %s, area %.17g, sigma %.17g (band %.3g), separation %.3g",
                name(ab), name(ba), exact::name(t.contact), t.area, t.sigma, band, t.separation);
}

std::string check_entrance(const Points& a, const Points& b, Vec2 a0) {
  const Polygon pa = to_polygon(a), pb = to_polygon(b);
  const double tol = dda::pair_tolerance(pa, pb);
  const dda::EntranceBlock e = dda::entrance_block(pa, pb, a0);
  const int k = e.poly.count;
  if (k < 3 || k > pa.count + pb.count) return format("entrance block has %d vertices (inputs %d + %d)", k, pa.count, pb.count);
  const Points ev = points_of(e.poly);
  for (int i = 0; i < k; ++i) {
    const dda::EntranceEdgeSource s = e.source[static_cast<std::size_t>(i)];
    const Polygon& edge_poly = s.from_b ? pb : pa;
    const Polygon& vertex_poly = s.from_b ? pa : pb;
    if (s.edge < 0 || s.edge >= edge_poly.count || s.vertex < 0 || s.vertex >= vertex_poly.count)
      return format("edge %d: source indices (%d, %d) out of range", i, s.edge, s.vertex);
    // The edge starts at b_j - a_i + a0 of its own pair, with the source edge's normal.
    const Vec2 bj = s.from_b ? pb.vertex(s.edge) : pb.vertex(s.vertex);
    const Vec2 ai = s.from_b ? pa.vertex(s.vertex) : pa.vertex(s.edge);
    if (e.poly.vertex(i) != bj - ai + a0) return format("edge %d does not start at the vertex of its source pair", i);
    const Vec2 n = e.poly.normal(i);
    if (n != (s.from_b ? pb.normal(s.edge) : -pa.normal(s.edge))) return format("edge %d: normal is not its source edge's", i);
    if (!(std::fabs(dda::length(n) - 1.0) <= tol::kUnitNormal)) return format("edge %d: |n| - 1 = %.3g", i, dda::length(n) - 1.0);
    // Pair rule (Table 1): the vertex is extreme against the edge's outward normal.
    const Vec2 en = s.from_b ? pb.normal(s.edge) : pa.normal(s.edge);
    for (int j = 0; j < vertex_poly.count; ++j)
      if (dda::dot(en, vertex_poly.vertex(s.vertex)) > dda::dot(en, vertex_poly.vertex(j)) + tol::kPairRuleSlack * tol)
        return format("edge %d (%s edge %d, vertex %d): vertex %d is more extreme", i, s.from_b ? "B" : "A", s.edge, s.vertex, j);
    // Every edge line supports E, and the edge lies on its line.
    for (int j = 0; j < k; ++j) {
      const double out = dda::dot(n, e.poly.vertex(j) - e.poly.vertex(i));
      if (out > tol::kEntranceSupport * tol) return format("vertex %d is %.3g outside the line of edge %d (tol %.3g)", j, out, i, tol);
      if (j == e.poly.next(i) && std::fabs(out) > tol::kEntranceSupport * tol)
        return format("edge %d ends %.3g off its own line (tol %.3g)", i, out, tol);
    }
  }
  const Points ex = exact::entrance_block(a, b, a0);
  const double h = hausdorff(ev, ex);
  if (!(h <= tol::kEntranceHausdorff * tol))
    return format("Hausdorff(entrance block, exact B - A + a0) = %.3g > %.3g\n  kernel %s\n  exact  %s", h,
                  tol::kEntranceHausdorff * tol, to_code(ev).c_str(), to_code(ex).c_str());
  return "";
}

// overlap_and_intersection(CP, TP): overlap_state's verdict, and when
// overlapping intersection_polygon's vertices bit for bit; every IP edge lies
// on its source edge's line (both end points within kSandwich tol of it) and
// carries that edge's normal; an edge merged from two sources (unknown) has a
// unit normal. The verdict is the same with any witness axis given (every
// axis index, and one out of range as left by another pair), and a
// kSeparate verdict leaves a witness that separates the pair by itself.
std::string check_fused(const Polygon& pc, const Polygon& pt, double tol) {
  Polygon ip;
  std::array<dda::IpEdge, dda::kMaxVertices> src;
  const dda::OverlapState s = dda::overlap_and_intersection(pc, pt, tol, ip, src.data());
  if (s != dda::overlap_state(pc, pt, tol)) return "overlap_and_intersection: verdict differs from overlap_state";
  for (int w = -1; w <= pc.count + pt.count; ++w) {
    int witness = w;
    Polygon ipw;
    const dda::OverlapState sw = dda::overlap_and_intersection(pc, pt, tol, ipw, src.data(), &witness);
    if (sw != s) return format("overlap_and_intersection: verdict differs with witness axis %d", w);
    if (sw != dda::OverlapState::kSeparate) continue;
    if (witness < 0 || witness >= pc.count + pt.count) return format("kSeparate left witness %d out of range", witness);
    int again = witness;
    if (dda::overlap_and_intersection(pc, pt, tol, ipw, src.data(), &again) != dda::OverlapState::kSeparate || again != witness)
      return format("witness axis %d: not kept on a second call", witness);
  }
  src = {};  // the witness calls wrote the sources: the checks below use a fresh call's
  if (dda::overlap_and_intersection(pc, pt, tol, ip, src.data()) != s) return "overlap_and_intersection: not repeatable";
  if (s != dda::OverlapState::kOverlapping) return ip.count == 0 ? "" : "overlap_and_intersection: IP not emptied";
  const Polygon ref = dda::intersection_polygon(pc, pt, tol);
  if (ip.count != ref.count) return format("overlap_and_intersection: %d IP vertices, intersection_polygon %d", ip.count, ref.count);
  for (int i = 0; i < ip.count; ++i) {
    if (ip.vertex(i) != ref.vertex(i)) return format("overlap_and_intersection: IP vertex %d differs", i);
    const dda::IpEdge e = src[static_cast<std::size_t>(i)];
    if (!e.known()) {  // merged from two nearly collinear edges: normal from its end points
      if (!(std::fabs(length(ip.normal(i)) - 1.0) <= tol::kUnitNormal)) return format("IP edge %d: normal not unit", i);
      continue;
    }
    const Polygon& owner = e.on_contact ? pc : pt;
    if (e.edge < 0 || e.edge >= owner.count) return format("IP edge %d: source edge %d out of range", i, e.edge);
    const Vec2 n = owner.normal(e.edge), v = owner.vertex(e.edge);
    if (ip.normal(i) != n) return format("IP edge %d: normal is not its source edge's", i);
    const double d0 = dot(n, ip.vertex(i) - v), d1 = dot(n, ip.vertex(ip.next(i)) - v);
    if (!(std::fabs(d0) <= tol::kSandwich * tol && std::fabs(d1) <= tol::kSandwich * tol))
      return format("IP edge %d is %.3g / %.3g off the line of its source (%s edge %d), tol %.3g", i, d0, d1,
                    e.on_contact ? "contact" : "target", e.edge, tol);
  }
  return "";
}

std::string check_intersection(const Points& cp, const Points& tp) {
  const Polygon pc = to_polygon(cp), pt = to_polygon(tp);
  const double tol = dda::pair_tolerance(pc, pt);
  const Points k1 = points_of(dda::intersection_polygon(pc, pt));
  const Points k2 = points_of(dda::intersection_polygon(pt, pc));
  const exact::Region r({tp, cp}, {}, tol::kSandwich * tol);
  // The IP lies in both inputs: its chords are no longer than the smaller diameter.
  const double diam = std::min(diameter_of(cp), diameter_of(tp));
  const double area_tol = dda::kIpAreaBound * static_cast<double>(cp.size() + tp.size()) * tol * diam;
  std::string f = check_clip_result("IP(CP,TP)", k1, r, tol, area_tol);
  // Every IP vertex within kIpVertexReach tol (Euclidean) of both inputs
  // (overlap.hpp), whatever the angles: distances to edge lines (the
  // sandwich above) allow tol / sin(theta / 2) at a corner of angle theta.
  const double reach = dda::kIpVertexReach * tol + tol::kMeasureSlack * tol;
  for (const Points* k : {&k1, &k2})
    for (std::size_t i = 0; i < k->size() && f.empty(); ++i) {
      const Vec2 q = (*k)[i];
      const double dc = region_distance(q, cp), dt = region_distance(q, tp);
      if (!(dc <= reach && dt <= reach))
        f = format("IP(%s) vertex %zu %s is %.3g from CP and %.3g from TP (%.3g tol; bound %.3g tol)",
                   k == &k1 ? "CP,TP" : "TP,CP", i, to_code(q).c_str(), dc, dt, std::max(dc, dt) / tol, reach / tol);
    }
  if (f.empty()) f = check_clip_result("IP(TP,CP)", k2, r, tol, area_tol);
  if (f.empty()) f = check_fused(pc, pt, tol);
  if (f.empty()) f = check_fused(pt, pc, tol);
  if (!f.empty()) return f;
  if (!k1.empty() && !k2.empty() && !r.inner_empty()) {
    const double h = hausdorff(k1, k2), bound = r.hausdorff_bound() + tol::kMeasureSlack * tol;
    if (!(h <= bound)) return format("Hausdorff(IP(CP,TP), IP(TP,CP)) = %.3g > %.3g", h, bound);
  }
  return "";
}

std::string check_motion(const Points& cp, const Points& tp, const Motion& m) {
  const Points cp2 = transformed(cp, m), tp2 = transformed(tp, m);
  const Polygon pc = to_polygon(cp), pt = to_polygon(tp), pc2 = to_polygon(cp2), pt2 = to_polygon(tp2);
  const double tol = std::max(dda::pair_tolerance(pc, pt), dda::pair_tolerance(pc2, pt2));
  const Points k = points_of(dda::intersection_polygon(pc, pt));
  const Points k2 = points_of(dda::intersection_polygon(pc2, pt2));
  const Points mk = transformed(k, m);
  const exact::Region r({tp2, cp2}, {}, (tol::kSandwich + tol::kMotionRounding) * tol);
  const double diam = std::min(diameter_of(cp), diameter_of(tp));
  const double area_tol = dda::kIpAreaBound * static_cast<double>(cp.size() + tp.size()) * tol * diam;
  const double a1 = k.empty() ? 0.0 : dda::area(to_polygon(k)), a2 = k2.empty() ? 0.0 : dda::area(to_polygon(k2));
  // Each of the two areas is within area_tol of the (nearly equal) exact areas.
  if (!(std::fabs(a1 - a2) <= 2.0 * area_tol))
    return format("area of IP %.17g, of IP after the motion %.17g (tolerance %.3g)", a1, a2, 2.0 * area_tol);
  if (r.inner_empty()) return "";
  if (k.empty() || k2.empty()) return format("IP empty before (%d) or after (%d) the motion", int(k.empty()), int(k2.empty()));
  const double h = hausdorff(mk, k2), bound = r.hausdorff_bound() + tol::kMeasureSlack * tol;
  if (!(h <= bound))
    return format("Hausdorff(moved IP, IP of moved inputs) = %.3g > %.3g\n  moved IP %s\n  IP       %s", h, bound,
                  to_code(mk).c_str(), to_code(k2).c_str());
  return "";
}

std::string check_moments(const Points& p) {
  const Polygon poly = to_polygon(p);
  const dda::AreaMoments m = dda::area_moments(poly);
  const exact::Moments ex = exact::area_moments(p);
  const double g = dda::geometric_tolerance(poly), len = dda::perimeter(poly), d = dda::diameter(poly);
  const double area_tol = tol::kMomentArea * g * len;
  const double centroid_tol = tol::kMomentCentroid * g * len * d / ex.area + g;
  const double second_tol = tol::kMomentSecond * g * len * d * d;
  struct Item {
    const char* name;
    double kernel, exact, tol;
  };
  const Item items[] = {
      {"area_moments.area", m.area, ex.area, area_tol},   {"area()", dda::area(poly), ex.area, area_tol},
      {"centroid.x", m.centroid.x, ex.cx, centroid_tol},  {"centroid.y", m.centroid.y, ex.cy, centroid_tol},
      {"sxx", m.sxx, ex.sxx, second_tol},                 {"syy", m.syy, ex.syy, second_tol},
      {"sxy", m.sxy, ex.sxy, second_tol},
  };
  for (const Item& it : items)
    if (!(std::fabs(it.kernel - it.exact) <= it.tol))
      return format("%s = %.17g, exact %.17g, |diff| %.3g > %.3g", it.name, it.kernel, it.exact,
                    std::fabs(it.kernel - it.exact), it.tol);
  return "";
}

std::string check_split(const Points& p, const LineCase& line) {
  const Polygon poly = to_polygon(p);
  Polygon below, above;
  dda::split_polygon(poly, line.point, line.normal, below, above);
  const double g = dda::geometric_tolerance(poly);
  const double area_tol = tol::kClipArea * static_cast<double>(p.size() + 2) * g * dda::diameter(poly);
  const exact::Region rb({p}, {{line.point, line.normal}}, tol::kSandwich * g);
  const exact::Region ra({p}, {{line.point, -line.normal}}, tol::kSandwich * g);
  const Points kb = points_of(below), ka = points_of(above);
  // The two parts add up to the whole (the exact whole: rb + ra), each part
  // within area_tol of its exact area.
  const double sum = dda::area(below) + dda::area(above), whole = rb.area() + ra.area();
  if (!(std::fabs(sum - whole) <= 2.0 * area_tol))
    return format("area(below) + area(above) = %.17g, exact area %.17g, |diff| %.3g > %.3g", sum, whole,
                  std::fabs(sum - whole), 2.0 * area_tol);
  std::string f = check_clip_result("below", kb, rb, g, area_tol);
  if (f.empty()) f = check_clip_result("above", ka, ra, g, area_tol);
  return f;
}

std::string check_exit(const Points& p, const Points& samples) {
  const Polygon poly = to_polygon(p);
  const double g = dda::geometric_tolerance(poly);
  const double exit_tol = tol::kExitTol * g, band = tol::kLocateBand * g;
  const dda::InscribedCircle ic = dda::inscribed_circle(poly);
  if (!(ic.radius > 0.0)) return format("inscribed radius %.17g", ic.radius);
  if (exact::locate(p, ic.centre) != exact::Location::kInside) return "inscribed centre is not inside (exact)";
  const double at_centre = dda::exit_distance(poly, ic.centre);
  if (!(std::fabs(at_centre - ic.radius) <= exit_tol))
    return format("inscribed radius %.17g but exit distance at its centre %.17g (|diff| %.3g > %.3g)", ic.radius, at_centre,
                  std::fabs(at_centre - ic.radius), exit_tol);
  Points all = samples;
  all.push_back(ic.centre);
  for (Vec2 q : all) {
    const std::string at = "at " + to_code(q) + ": ";
    const double d = dda::exit_distance(poly, q), de = exact::exit_distance(p, q);
    if (!(std::fabs(d - de) <= exit_tol))
      return at + format("exit distance %.17g, exact %.17g, |diff| %.3g > %.3g", d, de, std::fabs(d - de), exit_tol);
    if (!(d <= ic.radius + exit_tol))
      return at + format("exit distance %.17g exceeds the inscribed radius %.17g", d, ic.radius);
    // Point location: exact on the boundary => on; outside the band => exact side.
    const dda::PointLocation loc = dda::locate_point(poly, q);
    const exact::Location el = exact::locate(p, q);
    const bool ok = el == exact::Location::kOnBoundary ? loc == dda::PointLocation::kOnBoundary
                    : de > band                         ? loc == dda::PointLocation::kInside
                    : de < -band                        ? loc == dda::PointLocation::kOutside
                    : el == exact::Location::kInside    ? loc != dda::PointLocation::kOutside
                                                        : loc != dda::PointLocation::kInside;
    if (!ok) return at + format("locate_point says %s; exact exit distance %.17g (band %.3g)", name(loc), de, band);
    // The gradient of phi is -kn/H times the normal of a nearest edge inside, 0 outside.
    const Vec2 grad = dda::potential_gradient(poly, q, 1.0, 1.0);
    if (de > exit_tol) {
      bool nearest = false;
      // Edge i is a nearest edge if its distance is within round-off of the
      // exact minimum: exit_tol for the exact value, exit_tol for n . (v - q).
      for (int i = 0; i < poly.count && !nearest; ++i)
        nearest = grad == -poly.normal(i) && dda::dot(poly.normal(i), poly.vertex(i) - q) <= de + 2.0 * exit_tol;
      if (!nearest) return at + format("potential gradient (%.17g, %.17g) is not minus a nearest edge normal", grad.x, grad.y);
    } else if (de < -exit_tol && grad != Vec2{}) {
      return at + format("potential gradient (%.17g, %.17g) outside the polygon", grad.x, grad.y);
    }
  }
  return "";
}

}  // namespace prop
