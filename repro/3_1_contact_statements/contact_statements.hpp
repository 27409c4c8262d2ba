// Paper A Sects. 3.1.2 and 3.2.1, two statements the contact model rests on,
// checked on random convex pairs against an independent computation:
//  - Sect. 3.1.2 (Table 2): A and B overlap if and only if A's reference
//    point a0 lies inside the entrance block E(A, B) = B - A + a0; the
//    reference is a separating-axis test on the edge normals of both
//    polygons (pairs within the geometric tolerance of touching are left
//    out: there the answer is "touching" by definition).
//  - Sect. 3.2.1, Eqs. 10-11: the normal force on CP is the negative
//    gradient of the contact energy (the integral of phi_CP + phi_TP over
//    the intersection polygon) with respect to CP's position; the reference
//    is a central difference of dda::contact_energy (exact, by cells), with
//    the force from dda::normal_contact_force under the paper's segmentation
//    (Sect. 3.2.3) and under the exact integration (not the paper's).
//  - Sect. 3.2.4, Eq. 20: the resultant acts on a line through the loading
//    point pg, so the contact's moment about pg vanishes; the reference is
//    the moment as the energy's derivative, -dE/dtheta for CP turned about
//    pg (central difference).
// Each row function takes a Variant: the negative controls of
// controls.cpp beside this file apply the same criterion to a deliberately
// wrong construction and must get FAIL.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "dda/contact.hpp"
#include "dda/overlap.hpp"
#include "dda/polygon.hpp"
#include "dda/potential.hpp"
#include "repro/common/claims.hpp"
#include "repro/common/common.hpp"

namespace contact_statements {

inline const char* const kKeyEntrance = "entrance-block-iff";
inline const char* const kKeyGradientExact = "force-is-energy-gradient-exact";
inline const char* const kKeyGradientPaper = "force-is-energy-gradient-paper";
inline const char* const kKeyMomentExact = "zero-moment-about-pg-exact";
inline const char* const kKeyMomentPaper = "zero-moment-about-pg-paper";

struct Pair {
  dda::Polygon a, b;  // a: the contact polygon CP, b: the target TP
};

// Random convex polygons: 3-8 vertices at random angles on a circle of
// radius 0.5-1.5 m (always convex), each pair placed so that the two
// overlap in about two cases of three. Polygons the library refuses (an
// edge below kMinEdgeRelative of the size) are drawn again.
inline std::vector<Pair> random_pairs(int count, std::uint64_t seed) {
  constexpr double kTwoPi = 6.283185307179586;
  std::mt19937_64 g(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto polygon = [&](dda::Vec2 c) {
    for (;;) {
      const int n = 3 + static_cast<int>(u(g) * 6.0);
      const double r = 0.5 + u(g);
      std::vector<double> angle(static_cast<std::size_t>(n));
      for (double& a : angle) a = kTwoPi * u(g);
      std::sort(angle.begin(), angle.end());
      std::vector<dda::Vec2> v;
      for (double a : angle) v.push_back(c + r * dda::Vec2{std::cos(a), std::sin(a)});
      if (dda::validate_polygon(v.data(), n).ok()) return dda::make_polygon(v.data(), n);
    }
  };
  std::vector<Pair> out;
  for (int k = 0; k < count; ++k) {
    const double d = 3.0 * u(g), t = kTwoPi * u(g);
    out.push_back({polygon({0.0, 0.0}), polygon(d * dda::Vec2{std::cos(t), std::sin(t)})});
  }
  return out;
}

// The negative controls' wrong constructions.
enum class Variant {
  kAsPublished,
  kEntranceWithoutReflection,  // E built as B + A + a0 (A not reflected)
  kForceWithoutTargetPotential,  // the force integrates phi_CP only (TP's kn / H set to 0 in the force)
  kMomentAboutCentroid,          // the moment taken about the IP centroid instead of pg
};

// Sect. 3.1.2: overlap iff a0 inside E(A, B).
inline repro::Claim entrance_row(const std::vector<Pair>& pairs, Variant variant = Variant::kAsPublished) {
  int decided = 0, overlapping = 0, banded = 0, disagree = 0;
  for (const Pair& p : pairs) {
    const double tol = dda::pair_tolerance(p.a, p.b);
    // Reference: the largest separation over the edge normals of both
    // polygons (> tol: apart, < -tol: interiors overlap).
    double sep = -1e300;
    for (const dda::Polygon* s : {&p.a, &p.b}) {
      const dda::Polygon& o = s == &p.a ? p.b : p.a;
      for (int i = 0; i < s->count; ++i) {
        double lo = 1e300;
        for (int j = 0; j < o.count; ++j) lo = std::min(lo, dot(s->normal(i), o.vertex(j) - s->vertex(i)));
        sep = std::max(sep, lo);
      }
    }
    if (std::fabs(sep) <= tol) {
      ++banded;
      continue;
    }
    const dda::Vec2 a0 = p.a.vertex(0);
    dda::Polygon a = p.a;
    if (variant == Variant::kEntranceWithoutReflection) {  // -A: entrance_block reflects it back to +A
      std::vector<dda::Vec2> v;
      for (int i = 0; i < a.count; ++i) v.push_back(-1.0 * a.vertex(i));
      a = dda::make_polygon(v.data(), a.count);
    }
    const dda::EntranceBlock e = dda::entrance_block(a, p.b, a0);
    const bool inside = dda::locate_point(e.poly, a0, tol) == dda::PointLocation::kInside;
    const bool reference = sep < -tol;
    ++decided;
    overlapping += reference;
    disagree += inside != reference;
  }
  return {"3.1.2", "A and B overlap if and only if A's reference point a0 lies inside the entrance block E(A, B)",
          "'If ao is in E(A,B), overlap occurs; if ao is out of E(A,B), two blocks are detached' (Sect. 3.1.2)",
          std::to_string(decided) + " random convex pairs (" + std::to_string(overlapping) + " overlapping; " +
              std::to_string(banded) + " within the tolerance of touching left out): " + std::to_string(disagree) +
              " verdicts differ from a separating-axis test on both polygons' edge normals",
          "0 differing verdicts, on at least 1000 decided pairs", decided >= 1000 && disagree == 0, repro::Kind::kCheck,
          kKeyEntrance};
}

// Eqs. 10-11: f_CP = -dE/dx_CP, against a central difference of the exact
// contact energy with step kStep (its error ~ kStep^2 E''' / 6, below 1e-8
// of f for these 1 m blocks; the energy is piecewise smooth).
// Shared by the energy-derivative rows: kn / H (Pa / m; the 4.1 material's
// order, the ratio is what matters) and the smallest overlap used.
inline constexpr double kKnOverH = 1e6;  // Pa / m
inline constexpr double kMinIpArea = 1e-3;  // m^2: overlaps shallower than this are left out (FD resolution)

// The overlap of a pair, or none if it is shallower than kMinIpArea.
struct Overlap {
  double tol = 0.0;
  dda::Polygon ip;
  bool used = false;
};
inline Overlap overlap_of(const Pair& p) {
  Overlap o;
  o.tol = dda::pair_tolerance(p.a, p.b);
  o.ip = dda::intersection_polygon(p.a, p.b, o.tol);
  o.used = o.ip.count >= 3 && dda::area(o.ip) >= kMinIpArea;
  return o;
}
// The exact contact energy (dda::contact_energy) with CP moved to `a`.
inline double energy_with(const dda::Polygon& a, const dda::Polygon& b, double tol) {
  const dda::PotentialSide side{a, kKnOverH, 0.0}, target{b, kKnOverH, 0.0};
  return dda::contact_energy(side, target, dda::intersection_polygon(a, b, tol), tol);
}

struct GradientSample {
  double ip_area = 0.0;   // m^2
  double depth = 0.0;     // m: the IP's inscribed diameter (how deep the overlap is)
  double error = 0.0;     // |f + grad E| / |grad E|
};

// A row of a statement checked under integration `rule`: the claim names the
// integration, the key is the exact or the paper row's.
inline repro::Claim integration_row(const char* section, const std::string& statement, dda::Integration rule,
                                    std::string paper, std::string measured, std::string tolerance, bool pass,
                                    const char* key_exact, const char* key_paper) {
  const bool exact = rule == dda::Integration::kExactEnvelope;
  const char* how = exact ? "exact integration (not the paper's)" : "the paper's segmentation (Sect. 3.2.3)";
  return {section, statement + how, std::move(paper), std::move(measured), std::move(tolerance), pass,
          repro::Kind::kCheck, exact ? key_exact : key_paper};
}

inline repro::Claim gradient_row(const std::vector<Pair>& pairs, dda::Integration rule,
                                 Variant variant = Variant::kAsPublished, std::vector<GradientSample>* samples = nullptr) {
  constexpr double kStep = 1e-5;           // m, central-difference step
  constexpr double kTolerance = 1e-6;      // relative: 100 x the difference's error, far below a model error
  int used = 0, beyond = 0;
  double worst = 0.0;
  for (const Pair& p : pairs) {
    const Overlap o = overlap_of(p);
    if (!o.used) continue;
    const double tol = o.tol;
    const dda::Polygon& ip = o.ip;
    dda::Vec2 gradient{};
    for (int axis = 0; axis < 2; ++axis) {
      const dda::Vec2 d = axis == 0 ? dda::Vec2{kStep, 0.0} : dda::Vec2{0.0, kStep};
      (axis == 0 ? gradient.x : gradient.y) =
          (energy_with(dda::translated(p.a, d), p.b, tol) - energy_with(dda::translated(p.a, -1.0 * d), p.b, tol)) /
          (2.0 * kStep);
    }
    const dda::PotentialSide cp{p.a, kKnOverH, 0.0};
    const dda::PotentialSide tp_force{p.b, variant == Variant::kForceWithoutTargetPotential ? 0.0 : kKnOverH, 0.0};
    const dda::NormalForce f = dda::normal_contact_force(cp, tp_force, ip, rule, tol);
    const double e = dda::length(f.force + gradient) / dda::length(gradient);
    worst = std::max(worst, e);
    if (samples) samples->push_back({dda::area(ip), 2.0 * dda::inscribed_circle(ip).radius, e});
    beyond += e > kTolerance;
    ++used;
  }
  return integration_row(
      "3.2.1", "the normal force on CP is the negative gradient of the contact energy (Eqs. 10-11), ", rule,
      "'the integral of potential on an edge can be computed accurately piece by piece' (Sect. 3.2.3), for the "
      "force of Eqs. 10-11",
      std::to_string(used) + " random overlapping convex pairs (IP area >= 1e-3 m^2): largest |f + grad E| / "
          "|grad E| " + repro::format_short(worst, 3) + ", " + std::to_string(beyond) + " pairs beyond 1e-6 "
          "(grad E: central difference of the exact contact energy, step 1e-5 m)",
      "|f + grad E| / |grad E| < 1e-6 on every pair, at least 300 pairs", used >= 300 && beyond == 0,
      kKeyGradientExact, kKeyGradientPaper);
}

// Eq. 20: the moment about pg, -dE/dtheta for CP turned about pg by a
// central difference (step kTurn), relative to |f| sqrt(IP area).
inline repro::Claim moment_row(const std::vector<Pair>& pairs, dda::Integration rule,
                               Variant variant = Variant::kAsPublished) {
  constexpr double kTurn = 1e-6;         // rad, central-difference step
  constexpr double kTolerance = 1e-6;    // relative: measured 2e-8 for the exact integration
  int used = 0, beyond = 0;
  double worst = 0.0;
  for (const Pair& p : pairs) {
    const Overlap o = overlap_of(p);
    if (!o.used) continue;
    const dda::PotentialSide cp{p.a, kKnOverH, 0.0}, tp{p.b, kKnOverH, 0.0};
    const dda::NormalForce f = dda::normal_contact_force(cp, tp, o.ip, rule, o.tol);
    if (!f.valid) continue;
    const dda::Vec2 about = variant == Variant::kMomentAboutCentroid ? f.ip_centroid : f.point;
    auto energy_turned = [&](double t) {
      std::vector<dda::Vec2> v;
      for (int i = 0; i < p.a.count; ++i) v.push_back(about + dda::rotate(p.a.vertex(i) - about, t));
      return energy_with(dda::make_polygon(v.data(), p.a.count), p.b, o.tol);
    };
    const double moment = -(energy_turned(kTurn) - energy_turned(-kTurn)) / (2.0 * kTurn);
    const double e = std::fabs(moment) / (dda::length(f.force) * std::sqrt(dda::area(o.ip)));
    worst = std::max(worst, e);
    beyond += e > kTolerance;
    ++used;
  }
  return integration_row(
      "3.2.4", "the contact force acts on a line through pg: its moment about pg vanishes (Eq. 20), ", rule,
      "'the acting line lng along which the moment of total normal contact force is zero' (Sect. 3.2.4, Eq. 20); "
      "pg lies on it",
      std::to_string(used) + " random overlapping convex pairs: largest |M_pg| / (|f| sqrt(IP area)) " +
          repro::format_short(worst, 3) + ", " + std::to_string(beyond) + " pairs beyond 1e-6 (M_pg = -dE/dtheta "
          "for CP turned about pg, central difference of the exact contact energy, step 1e-6 rad)",
      "|M_pg| / (|f| sqrt(IP area)) < 1e-6 on every pair, at least 300 pairs", used >= 300 && beyond == 0,
      kKeyMomentExact, kKeyMomentPaper);
}

}  // namespace contact_statements
