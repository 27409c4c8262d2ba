// Paper A Sect. 3.1.3: "the intersection polygon" of two overlapping convex
// blocks, the domain of the contact integrals (Eqs. 10-11), as a report row:
// our intersection polygon against CGAL's exact intersection (exact.hpp) on
// random convex pairs, at the origin and far from it, with the bounds that
// overlap.hpp states (every vertex within kIpVertexReach tol of both inputs;
// the area within kIpAreaBound (n + m) tol D of the exact one). The property
// tests check the same and more with generated families (make fuzz runs
// 10^6 cases); this program puts the statement in the report.
// It lives here because only property_tests/ may link CGAL.
//
// Expected: every pair within both bounds. The negative control (ctest
// geometry_claims_control) computes the IP of A with B moved by 100 tol and
// must FAIL.
//
// Output: claims/3_1_exact_geometry.csv.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "dda/overlap.hpp"
#include "exact.hpp"
#include "repro/3_1_contact_statements/contact_statements.hpp"
#include "repro/common/common.hpp"
#include "support.hpp"

namespace {
using prop::Points;
using prop::Vec2;

struct Result {
  int pairs = 0, beyond = 0;
  double worst_reach = 0.0, worst_area = 0.0;  // in units of their bounds
};

// shift_tols: B moved by this many tolerances along x before our IP is
// computed (the control: a wrong intersection); 0 for the claim.
Result measure(int count, std::uint64_t seed, double offset, double shift_tols) {
  // The random convex pairs of the Sect. 3.1-3.2 rows, moved by `offset`.
  const Vec2 base{offset, offset * 0.5};
  Result r;
  for (const contact_statements::Pair& pair : contact_statements::random_pairs(count, seed)) {
    const Points a = prop::points_of(dda::translated(pair.a, base)), b = prop::points_of(dda::translated(pair.b, base));
    const prop::exact::PairTruth truth = prop::exact::pair_truth(a, b);
    if (truth.contact != prop::exact::Contact::kOverlapping) continue;
    ++r.pairs;
    const dda::Polygon pa = prop::to_polygon(a), pb = prop::to_polygon(b);
    const double tol = dda::pair_tolerance(pa, pb);
    const dda::Polygon pb_used = shift_tols != 0.0 ? dda::translated(pb, {shift_tols * tol, 0.0}) : pb;
    const Points ip = prop::points_of(dda::intersection_polygon(pa, pb_used));
    const double diam = std::min(prop::diameter_of(a), prop::diameter_of(b));
    const double area_bound = dda::kIpAreaBound * static_cast<double>(a.size() + b.size()) * tol * diam;
    const double area = ip.size() >= 3 ? dda::area(prop::to_polygon(ip)) : 0.0;
    const double area_err = std::fabs(area - truth.area) / area_bound;
    double reach = 0.0;
    for (const Vec2& q : ip)
      reach = std::max(reach, std::max(prop::region_distance(q, a), prop::region_distance(q, b)) /
                                  (dda::kIpVertexReach * tol));
    r.worst_area = std::max(r.worst_area, area_err);
    r.worst_reach = std::max(r.worst_reach, reach);
    r.beyond += area_err > 1.0 || reach > 1.0;
  }
  return r;
}

repro::Claim row(const Result& near, const Result& far, double far_offset) {
  auto text = [](const Result& r) {
    return std::to_string(r.pairs) + " exactly overlapping pairs: largest vertex distance " +
           repro::format_short(r.worst_reach, 3) + " of the bound, largest area error " +
           repro::format_short(r.worst_area, 3) + " of the bound, " + std::to_string(r.beyond) + " beyond";
  };
  repro::Claim c{"3.1.3",
                 "the intersection polygon is the exact intersection of the two blocks, within the round-off bounds "
                 "the library states (an exact-arithmetic reference)",
                 "'After the cycling of each CP edges, the remaining polygon is IP' (Sect. 3.1.3)",
                 "at the origin: " + text(near) + "; offset by " + repro::format_short(far_offset) + " m: " + text(far),
                 "every vertex within " + repro::format_short(dda::kIpVertexReach) + " tol of both blocks and |area - "
                 "exact area| <= " + repro::format_short(dda::kIpAreaBound) + " (n + m) tol D on every pair, at least "
                 "500 pairs each",
                 near.pairs >= 500 && far.pairs >= 500 && near.beyond == 0 && far.beyond == 0};
  c.key = "intersection-polygon-exact";
  c.control = "geometry_claims_control";
  c.scope = repro::Scope::kPaper;
  return c;
}

}  // namespace

int main(int argc, char** argv) try {
  // --control: the negative control (B moved by 100 tol before clipping):
  // prints the row's verdict and exits 0 only if it is FAIL.
  const bool control = argc > 1 && std::strcmp(argv[1], "--control") == 0;
  if (!control)
    repro::check_command_line(argc, argv,
                              "Paper A Sect. 3.1.3: the intersection polygon against CGAL's exact intersection.");
  constexpr int kPairs = 2000;  // random pairs per placement; about half overlap
  constexpr double kFarOffset = 1e6;  // m: blocks of 1 m a million metres from the origin
  const double shift = control ? 100.0 : 0.0;
  const Result near = measure(kPairs, 11, 0.0, shift), far = measure(kPairs, 12, kFarOffset, shift);
  repro::Claim c = row(near, far, kFarOffset);
  if (control) {
    std::printf("geometry_claims --control: %s (%s)\n", c.pass ? "PASS: the criterion did not catch it" : "FAIL as it must",
                c.measured.c_str());
    return c.pass ? 1 : 0;
  }
  repro::explain_fail(c, repro::Root::kUnexplained, "the clipper must meet the bounds the library states; not explained");
  const std::string out = repro::out_dir(argc, argv);
  repro::write_claims(repro::claims_path(out, "3_1_exact_geometry"), {c});
  std::fprintf(stderr, "[3.1.3 exact geometry] %s: %s\n", c.pass ? "PASS" : "FAIL", c.measured.c_str());
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "geometry_claims: error: %s\n", e.what());
  return 1;
}
