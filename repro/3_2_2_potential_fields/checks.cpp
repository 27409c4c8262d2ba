// Paper A Sect. 3.2.2: the check rows of both figures and their criteria
// (potential_fields.hpp), shared with the negative controls.
#include <algorithm>
#include <cmath>
#include <limits>

#include "repro/3_2_2_potential_fields/potential_fields.hpp"

namespace potential_fields {

std::string figure_tag(const std::string& fig) { return fig + " (reconstructed polygon)"; }

void add_common_claims(std::vector<Claim>& claims, const std::string& fig, const Grid& g, double bmax) {
  const InteriorStats s = interior_stats(g);
  const double zero_tol = 1e-12 * kKn / kH;  // round-off of a unit-size coordinate difference
  claims.push_back({kSection, figure_tag(fig) + ": potential is zero on the boundary and positive inside",
                    "'the potential values of any points on polygon boundary should be equal and the definition "
                    "satisfies this requirement' (Sect. 3.2.2, Eq. 12)",
                    "max |phi| on boundary = " + format_short(bmax, 3) + " Pa; min phi at " +
                        std::to_string(s.interior) + " interior grid points = " + format_short(s.min_phi, 4) + " Pa",
                    "boundary <= " + format_short(zero_tol, 2) + " Pa; interior min > 0",
                    bmax <= zero_tol && s.interior > 0 && s.min_phi > 0.0});
  claims.back().control = kFieldControl;
  claims.back().scope = repro::Scope::kPaper;
  claims.push_back({kSection, figure_tag(fig) + ": every interior point has a defined potential (no undefined inner region)",
                    "'the proposed definition ensures the potential value can be obtained for each point inside a "
                    "polygon' (Sect. 3.2.2, Fig. 4)",
                    std::to_string(s.undefined) + " of " + std::to_string(s.interior) +
                        " interior grid points with phi <= 0 or non-finite",
                    "0 points", s.interior > 0 && s.undefined == 0});
  claims.back().control = kFieldControl;
  claims.back().scope = repro::Scope::kPaper;
  const double slope = max_slope(g);
  claims.push_back({kSection, figure_tag(fig) + ": phi is continuous with slope at most kn/H",
                    "d_exit is a shortest distance, so it changes no faster than p moves (kn/H = 1 Pa/m)",
                    "max |finite difference| over " + std::to_string(g.nx) + "x" + std::to_string(g.ny) +
                        " grid = " + format_short(slope, 6) + " Pa/m",
                    "<= kn/H * (1 + 1e-9)", slope <= (kKn / kH) * (1.0 + 1e-9)});
  claims.back().control = kFieldControl;
  claims.back().scope = repro::Scope::kExtension;  // a property Eqs. 12-14 imply, not a statement of the paper
}

// Fig. 4b: phi at depth delta = min edge / 4 below every edge midpoint
// equals kn delta / H (relative deviation <= 1e-9).
Claim equal_penetration_row(const dda::Polygon& poly, const Field& phi) {
  double min_edge = std::numeric_limits<double>::infinity(), max_edge = 0.0;
  for (int i = 0; i < poly.count; ++i) {
    min_edge = std::min(min_edge, dda::length(poly.edge(i)));
    max_edge = std::max(max_edge, dda::length(poly.edge(i)));
  }
  const double delta = 0.25 * min_edge;
  double worst_rel = 0.0;
  for (int i = 0; i < poly.count; ++i) {
    const Vec2 mid = 0.5 * (poly.vertex(i) + poly.vertex(poly.next(i)));
    const double v = phi(mid - delta * poly.normal(i));
    worst_rel = std::max(worst_rel, std::fabs(v - kKn * delta / kH) / (kKn * delta / kH));
  }
  Claim c{kSection, figure_tag("Fig. 4b") + ": the same penetration below any edge, small edges included, gives the same potential",
          "'with the same H value ... it ensures the contact potential of the points with the same penetrations "
          "keeps equal' (Sect. 3.2.2)",
          "max relative deviation from kn*delta/H at delta = " + format_short(delta, 3) + " m below the " +
              std::to_string(poly.count) + " edge midpoints (edges " + format_short(min_edge, 3) + " to " +
              format_short(max_edge, 3) + " m) = " + format_short(worst_rel, 3),
          "<= 1e-9", worst_rel <= kPenetrationTolerance};
  c.control = std::string("repro_controls: ") + kControlPenetration;
  return c;
}

// Fig. 4b: the grid's d_exit (Eqs. 13-14) equals the distance to the boundary
// segments of pts at every interior grid point (<= 1e-12 m).
Claim edge_lines_row(const std::vector<Vec2>& pts, const Grid& g) {
  double line_vs_segment = 0.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t k = g.idx(i, j);
      if (g.inside[k])
        line_vs_segment = std::max(line_vs_segment, std::fabs(g.d_exit[k] - boundary_distance(pts, g.at(i, j))));
    }
  Claim c{kSection, figure_tag("Fig. 4b") + ": Eqs. 13-14 (edge lines) equal the shortest distance to the boundary",
          "'Using this definition for convex polygons, the shortest distance ... can be obtained by' Eq. 13 "
          "(Sect. 3.2.2)",
          "max |d_exit - distance to boundary segments| at interior grid points = " + format_short(line_vs_segment, 3) +
              " m",
          "<= 1e-12 m", line_vs_segment <= kLineTolerance};
  c.control = std::string("repro_controls: ") + kControlEdgeLines;
  return c;
}

// Fig. 4b: the grid's largest phi lies within one grid step (kn h / H) below
// kn r / H, r the inscribed radius of poly, and phi(centre) = kn r / H.
Claim inscribed_row(const dda::Polygon& poly, const Grid& g, const Field& phi) {
  const dda::InscribedCircle ic = dda::inscribed_circle(poly);
  const double phi_max_grid = interior_stats(g).max_phi, phi_ic = kKn * ic.radius / kH;
  const double phi_at_centre = phi(ic.centre);
  const bool ic_ok = phi_max_grid <= phi_ic * (1 + 1e-12) && phi_max_grid >= phi_ic - kKn * g.h / kH &&
                     std::fabs(phi_at_centre - phi_ic) <= 1e-12;
  Claim c{kSection, figure_tag("Fig. 4b") + ": the largest potential is kn*r/H at the inscribed-circle centre",
          "follows from Eqs. 12-14 (max of d_exit = inscribed radius r)",
          "r = " + format_short(ic.radius, 6) + " m; phi(centre) = " + format_short(phi_at_centre, 6) +
              " Pa; grid max = " + format_short(phi_max_grid, 6) + " Pa",
          "grid max in [kn*r/H - kn*h/H, kn*r/H], h = " + format_short(g.h, 3) + " m", ic_ok};
  c.control = std::string("repro_controls: ") + kControlInscribed;
  return c;
}

// Fig. 5: the grid's phi equals kn/H times the distance to a dense sampling
// of the boundary of pts (spacing <= kSampleSpacing) at every third interior
// grid point, within kn/H times half the sample spacing: an independent
// evaluation of the nearest boundary point.
Claim nearest_point_row(const std::vector<Vec2>& pts, const Grid& g) {
  std::vector<Vec2> samples;
  double max_seg = 0.0;  // largest gap between consecutive samples
  for (std::size_t e = 0; e < pts.size(); ++e) {
    const Vec2 a = pts[e], b = pts[(e + 1) % pts.size()];
    const int n = std::max(1, static_cast<int>(std::ceil(dda::distance(a, b) / kSampleSpacing)));
    max_seg = std::max(max_seg, dda::distance(a, b) / n);
    for (int s = 0; s < n; ++s) samples.push_back(dda::lerp(a, b, static_cast<double>(s) / n));
  }
  double worst_sample = 0.0;
  long checked = 0;
  for (int j = 0; j < g.ny; j += 3)
    for (int i = 0; i < g.nx; i += 3) {
      const std::size_t k = g.idx(i, j);
      if (!g.inside[k]) continue;
      double ds = std::numeric_limits<double>::infinity();
      for (Vec2 q : samples) ds = std::min(ds, dda::distance(g.at(i, j), q));
      worst_sample = std::max(worst_sample, std::fabs(kKn * ds / kH - g.phi[k]));
      ++checked;
    }
  Claim c{kSection, figure_tag("Fig. 5") + ": phi equals kn/H times the distance to the nearest boundary point",
          "'a point penetrated in a polygon will always be pushed out along the shortest path' (Sect. 3.2.2, Fig. 5)",
          "max |phi - kn/H * distance to " + std::to_string(samples.size()) + " boundary samples| at " +
              std::to_string(checked) + " interior points = " + format_short(worst_sample, 3) + " Pa",
          "<= kn/H * half the sample spacing = " + format_short(kKn * max_seg / (2 * kH), 3) + " Pa",
          checked > 0 && worst_sample <= kKn * max_seg / (2 * kH) * (1 + 1e-9)};
  c.control = std::string("repro_controls: ") + kControlNearest;
  return c;
}

// Fig. 5: Eqs. 13-14 applied blindly to pts give d_exit <= 0 at some interior
// grid point of g (so the shortest-distance evaluation is needed).
Claim concave_lines_row(const std::vector<Vec2>& pts, const Grid& g) {
  long fails = 0, interior = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      if (!g.inside[g.idx(i, j)]) continue;
      ++interior;
      if (edge_line_distance(pts, g.at(i, j)) <= 0.0) ++fails;
    }
  Claim c{kSection, figure_tag("Fig. 5") + ": Eqs. 13-14 (edge lines) alone do not give the concave potential",
          "'obtained by decomposing the concave polygon into six convex ones' (Sect. 3.2.2, Fig. 5): Eq. 13 is "
          "stated for convex polygons",
          std::to_string(fails) + " of " + std::to_string(interior) +
              " interior grid points get d_exit <= 0 from the edge-line formula",
          "> 0 points (the convex formula fails, so the shortest-distance evaluation is needed)", fails > 0};
  c.control = std::string("repro_controls: ") + kControlConcaveLines;
  return c;
}

}  // namespace potential_fields

