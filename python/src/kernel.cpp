// _core.kernel: the contact kernel of Paper A on numpy polygons, for
// probing the method interactively. Polygons are (n, 2) arrays of the
// counter-clockwise vertices of a convex block (3 to 16 vertices), checked
// as the library checks a block (ValueError naming the vertex and reason).
#include <pybind11/stl.h>

#include <string>

#include "bindings.hpp"
#include "dda/contact.hpp"
#include "dda/overlap.hpp"
#include "dda/potential.hpp"

namespace dda::py_bindings {

namespace {

double tolerance_or(double tol, const Polygon& a, const Polygon& b) { return tol < 0.0 ? pair_tolerance(a, b) : tol; }

Integration integration_from(const std::string& s) {
  if (s == "paper_bisector") return Integration::kPaperBisector;
  if (s == "exact_envelope") return Integration::kExactEnvelope;
  throw py::value_error("integration: expected 'paper_bisector' or 'exact_envelope', got '" + s + "'");
}

SmallEdgeRays rays_from(const std::string& s) {
  if (s == "virtual_and_vertex") return SmallEdgeRays::kVirtualAndVertex;
  if (s == "virtual_replaces_vertex") return SmallEdgeRays::kVirtualReplacesVertex;
  throw py::value_error("small_edge_rays: expected 'virtual_and_vertex' or 'virtual_replaces_vertex', got '" + s +
                        "'");
}

LoadingPoint loading_point_from(const std::string& s) {
  if (s == "paper") return LoadingPoint::kPaper;
  if (s == "within_ip") return LoadingPoint::kWithinIp;
  throw py::value_error("loading_point: expected 'paper' or 'within_ip', got '" + s + "'");
}

double positive(double x, const char* what) {
  if (!(std::isfinite(x) && x > 0.0)) throw py::value_error(std::string(what) + ": must be positive and finite");
  return x;
}

// One side of the potential: phi = kn / H max(0, d_exit), small edges
// (shorter than small_edge_fraction H) with a virtual node, as a
// simulation sets up each block (lib/src/simulation/setup.cpp).
PotentialSide side_of(const Polygon& p, double kn, double h, double small_edge_fraction, SmallEdgeRays rays) {
  PotentialSide s;
  s.poly = p;
  s.kn_over_h = positive(kn, "kn") / positive(h, "h");
  s.small_edge = small_edge_fraction * h;
  s.small_edge_rays = rays;
  return s;
}

// f(point) for each row of an (k, 2) array or for one (2,) point.
template <class F>
py::object at_points(const py::handle& points, F f) {
  const DoubleArray a = DoubleArray::ensure(points);
  if (!a) throw py::value_error("points: expected an (k, 2) array or one (x, y) point");
  if (a.ndim() == 1 && a.shape(0) == 2) return py::float_(f(Vec2{a.at(0), a.at(1)}));
  if (a.ndim() != 2 || a.shape(1) != 2) throw py::value_error("points: expected an (k, 2) array or one (x, y) point");
  py::array_t<double> out(a.shape(0));
  auto w = out.mutable_unchecked<1>();
  const auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) w(i) = f(Vec2{r(i, 0), r(i, 1)});
  return std::move(out);
}

py::array_t<double> vec2_array(Vec2 v) {
  py::array_t<double> a(2);
  a.mutable_at(0) = v.x, a.mutable_at(1) = v.y;
  return a;
}

}  // namespace

void bind_kernel(py::module_& m) {
  m.attr("MAX_BLOCK_VERTICES") = kMaxBlockVertices;
  m.attr("IP_VERTEX_REACH") = kIpVertexReach;
  m.attr("IP_AREA_BOUND") = kIpAreaBound;

  m.def(
      "check_polygon", [](const py::handle& p) { return vertices_array(polygon_from(p, "polygon")); },
      py::arg("polygon"),
      "The polygon as the library accepts a block (ValueError naming the vertex and the reason otherwise).");
  m.def(
      "geometric_tolerance", [](const py::handle& p) { return geometric_tolerance(polygon_from(p, "polygon")); },
      py::arg("polygon"), "Absolute tolerance of the polygon's predicates, m.");
  m.def(
      "pair_tolerance",
      [](const py::handle& a, const py::handle& b) {
        return pair_tolerance(polygon_from(a, "a"), polygon_from(b, "b"));
      },
      py::arg("a"), py::arg("b"), "The tolerance of a pair: the larger of the two polygons', m.");
  m.def(
      "overlap_state",
      [](const py::handle& a, const py::handle& b, double tol) {
        const Polygon pa = polygon_from(a, "a"), pb = polygon_from(b, "b");
        switch (overlap_state(pa, pb, tol)) {
          case OverlapState::kSeparate: return "separate";
          case OverlapState::kTouching: return "touching";
          case OverlapState::kOverlapping: return "overlapping";
        }
        return "separate";
      },
      py::arg("a"), py::arg("b"), py::arg("tol") = -1.0,
      "'separate', 'touching' or 'overlapping' (Paper A Sect. 3.1.2, the entrance block); tol < 0: the pair's.");
  m.def(
      "intersection_polygon",
      [](const py::handle& contact, const py::handle& target, double tol) {
        const Polygon a = polygon_from(contact, "contact"), b = polygon_from(target, "target");
        return vertices_array(intersection_polygon(a, b, tolerance_or(tol, a, b)));
      },
      py::arg("contact"), py::arg("target"), py::arg("tol") = -1.0,
      "(m, 2) the intersection polygon by cutting (Sect. 3.1.3), CCW; (0, 2) when the interiors do not overlap.");
  m.def(
      "entrance_block",
      [](const py::handle& a, const py::handle& b) {
        const Polygon pa = polygon_from(a, "a"), pb = polygon_from(b, "b");
        return vertices_array(entrance_block(pa, pb, pa.vertex(0)).poly);
      },
      py::arg("a"), py::arg("b"), "(m, 2) the entrance block E(A, B) = B - A + a0 (Eq. 9), a0 = a[0].");
  m.def(
      "exit_distance",
      [](const py::handle& poly, const py::handle& points) {
        const Polygon p = polygon_from(poly, "polygon");
        return at_points(points, [&](Vec2 x) { return exit_distance(p, x); });
      },
      py::arg("polygon"), py::arg("points"),
      "d_exit at the points (Eqs. 13-14): the shortest distance to leave the polygon, negative outside.");
  m.def(
      "potential",
      [](const py::handle& poly, const py::handle& points, double kn, double h) {
        const Polygon p = polygon_from(poly, "polygon");
        positive(kn, "kn"), positive(h, "h");
        return at_points(points, [&](Vec2 x) { return potential(p, x, kn, h); });
      },
      py::arg("polygon"), py::arg("points"), py::arg("kn"), py::arg("h"),
      "phi = kn d_exit / H inside the polygon, 0 outside (Eq. 12), Pa.");
  m.def(
      "potential_gradient",
      [](const py::handle& poly, const py::handle& points, double kn, double h) {
        const Polygon p = polygon_from(poly, "polygon");
        positive(kn, "kn"), positive(h, "h");
        const std::vector<Vec2> x = points_from(points, "points");
        std::vector<Vec2> g(x.size());
        for (std::size_t i = 0; i < x.size(); ++i) g[i] = potential_gradient(p, x[i], kn, h);
        return vertices_array(g);
      },
      py::arg("polygon"), py::arg("points"), py::arg("kn"), py::arg("h"), "(k, 2) gradient of phi at the points.");
  m.def(
      "inscribed_circle",
      [](const py::handle& poly) {
        const InscribedCircle c = inscribed_circle(polygon_from(poly, "polygon"));
        return py::make_tuple(vec2_array(c.centre), c.radius);
      },
      py::arg("polygon"), "(centre (2,), radius): the largest inscribed circle.");
  m.def(
      "normal_contact_force",
      [](const py::handle& cp, const py::handle& tp, double kn, double h_cp, double h_tp,
         const std::string& integration, double small_edge_fraction, const std::string& small_edge_rays,
         const std::string& loading_point, double tol) {
        const Polygon a = polygon_from(cp, "cp"), b = polygon_from(tp, "tp");
        const double t = tolerance_or(tol, a, b);
        const SmallEdgeRays rays = rays_from(small_edge_rays);
        const PotentialSide sa = side_of(a, kn, h_cp, small_edge_fraction, rays);
        const PotentialSide sb = side_of(b, kn, h_tp, small_edge_fraction, rays);
        const Polygon ip = intersection_polygon(a, b, t);
        const NormalForce f =
            normal_contact_force(sa, sb, ip, integration_from(integration), t, nullptr, loading_point_from(loading_point));
        py::dict d;
        d["force"] = vec2_array(f.force);
        d["point"] = vec2_array(f.point);
        d["moment"] = f.moment;
        d["couple"] = f.couple;
        d["ip_centroid"] = vec2_array(f.ip_centroid);
        d["ip_area"] = f.ip_area;
        d["ip_perimeter"] = f.ip_perimeter;
        d["segments"] = f.segments;
        d["valid"] = f.valid;
        d["energy"] = ip.count >= 3 ? contact_energy(sa, sb, ip, t) : 0.0;
        d["intersection"] = vertices_array(ip);
        return d;
      },
      py::arg("cp"), py::arg("tp"), py::arg("kn"), py::arg("h_cp"), py::arg("h_tp"),
      py::arg("integration") = "paper_bisector", py::arg("small_edge_fraction") = 0.05,
      py::arg("small_edge_rays") = "virtual_and_vertex", py::arg("loading_point") = "paper", py::arg("tol") = -1.0,
      "The normal contact force on the contact polygon cp from the target tp (Eqs. 10-20), with the\n"
      "boundary integral split by 'paper_bisector' (Sect. 3.2.3) or 'exact_envelope'. Returns a dict:\n"
      "force (2,) N/m, point (2,) the loading point pg, moment and couple N m/m, ip_centroid, ip_area,\n"
      "ip_perimeter, segments, valid (False when the net force vanishes), energy (the penalty energy\n"
      "stored, J/m) and intersection (the IP).");
}

}  // namespace dda::py_bindings
