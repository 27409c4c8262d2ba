// Is Paper A's segmentation exact? (Sect. 3.2.3, put to the test; beyond the paper.)
//
// Eq. 16 integrates (phi_CP - phi_TP) along each edge of the intersection
// polygon (IP) by the trapezoid rule between "demarcation points": the edge's
// ends and midpoint and its crossings with the angle-bisector rays of the CP
// and TP vertices and, for an edge shorter than a tolerance, of its virtual
// node (Sect. 3.2.3). The rule is exact only if those points include every
// kink of phi along the edge. For a convex polygon the kinks of
// phi = kn/H min_i d_i lie on its medial axis; the vertex bisector rays
// contain only the axis branches that end at vertices, not the inner ones
// (a rectangle's middle segment is the simplest). Two readings of the
// small-edge rule are measured, both by dda::normal_contact_force with
// PotentialSide::small_edge_rays (and in runs by ContactParams::small_edge_rays):
//   "paper" = dda::SmallEdgeRays::kVirtualAndVertex, the library default and
//     the paper's printed rule ("Both the real nodes and virtual nodes of CP
//     or TP are used in locating the demarcation points");
//   "replace" = kVirtualReplacesVertex, SPEC.md's reading (the virtual node
//     "replaces its two vertices as ray origins"), a library option.
// Each is compared with dda::Integration::kExactEnvelope (which splits each
// IP edge at the true breakpoints of the lower envelope):
//   1. per contact and step, along runs of Sects. 4.1, 4.2, 4.3 (phi 20 deg),
//      5.1 (4 runs), 5.2 and 5.3 (both cases), all run with the library
//      defaults (paper segmentation, paper small-edge rule); at each state
//      the force is evaluated under both readings: relative error of the
//      normal force |f_p - f_e| / |f_e| and of the loading point
//      |pg_p - pg_e| / diameter(IP);
//   2. on 20000 fuzzed convex polygon pairs (fixed seed; 3-10 vertices,
//      aspect ratio up to 6, 30 % with a corner cut by a 1e-3 to 5e-2 edge;
//      overlap thickness log-uniform from 1e-3 to 1 of the smaller inscribed
//      diameter), binned by that depth, under both readings;
//   3. the trajectories of 4.1, 4.3 (phi 0, 10, 20 deg), 5.1 (4 runs) and
//      5.3 (both cases) run three times: paper segmentation with each
//      reading, and exact integration; the energy error of each;
//   4. the textbook case: a square's corner pushed 0.7 m into a 2 m x 1 m
//      rectangle, across its medial axis's middle segment (no small edge:
//      both readings coincide).
// Expected (our prediction before the first run, when the library replaced
// the vertex rays): zero error wherever the IP stays near the boundary of
// both polygons (shallow contacts of Sects. 4-5), non-zero error for deep
// overlaps and near a small edge's virtual node.
//
// Output: data/segmentation/contacts.csv, summary.csv (1), fuzz.csv (2),
// trajectories.csv, trajectory_runs.csv (3); claims/5_5_segmentation.csv.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "dda/robustness_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/common/common.hpp"

namespace {
using dda::Integration;
using dda::NormalForce;
using dda::Polygon;
using dda::PotentialSide;
using dda::SmallEdgeRays;
using dda::Vec2;
using repro::format_short;

// The two readings of the small-edge rule, in the order of every table here.
constexpr std::array<SmallEdgeRays, 2> kModes = {SmallEdgeRays::kVirtualAndVertex,
                                                 SmallEdgeRays::kVirtualReplacesVertex};
constexpr std::array<const char*, 2> kModeKey = {"paper", "replace"};

// ---- comparing one configuration ---------------------------------------------

struct ModeError {
  double force = 0.0;  // |f_p - f_e| / |f_e|
  double point = 0.0;  // |pg_p - pg_e| / diameter(IP)
};

struct Errors {
  bool valid = false;
  std::array<ModeError, 2> mode{};  // indexed as kModes
  double depth_ratio = 0.0;         // overlap thickness / (2 min inscribed radius)
};

Errors compare(const Polygon& a, double kn_h_a, double small_a, const Polygon& b, double kn_h_b, double small_b) {
  Errors e;
  const double tol = dda::pair_tolerance(a, b);
  const Polygon ip = dda::intersection_polygon(a, b, tol);
  if (ip.count < 3) return e;
  PotentialSide sa{&a, kn_h_a, small_a}, sb{&b, kn_h_b, small_b};
  const NormalForce fe = dda::normal_contact_force(sa, sb, ip, Integration::kExactEnvelope, tol);
  const double fe_len = dda::length(fe.force), dia = dda::diameter(ip);
  if (!fe.valid || !(fe_len > 0.0)) return e;
  for (std::size_t m = 0; m < kModes.size(); ++m) {
    sa.small_edge_rays = sb.small_edge_rays = kModes[m];
    const NormalForce fp = dda::normal_contact_force(sa, sb, ip, Integration::kPaperBisector, tol);
    if (!fp.valid) return e;
    e.mode[m].force = dda::length(fp.force - fe.force) / fe_len;
    e.mode[m].point = dda::distance(fp.point, fe.point) / dia;
  }
  e.valid = true;
  const double r = std::min(dda::inscribed_circle(a).radius, dda::inscribed_circle(b).radius);
  e.depth_ratio = 2.0 * dda::inscribed_circle(ip).radius / (2.0 * r);
  return e;
}

// Error statistics of one reading over many configurations.
struct ModeStats {
  long n = 0, nonzero = 0;  // nonzero: relative force error > 1e-8 (above round-off)
  double max_force = 0.0, max_point = 0.0;
  std::vector<double> force_errors;
  void add(const ModeError& m) {
    ++n;
    nonzero += m.force > 1e-8 ? 1 : 0;
    max_force = std::max(max_force, m.force);
    max_point = std::max(max_point, m.point);
    force_errors.push_back(m.force);
  }
  double nonzero_percent() const { return n ? 100.0 * static_cast<double>(nonzero) / static_cast<double>(n) : 0.0; }
  double percentile(double q) const {
    if (force_errors.empty()) return 0.0;
    std::vector<double> v = force_errors;
    const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())));
    std::nth_element(v.begin(), v.begin() + static_cast<long>(k), v.end());
    return v[k];
  }
  bool same_as(const ModeStats& o) const { return force_errors == o.force_errors && max_point == o.max_point; }
  // "x % with a force error > 1e-8; max, median, 99th percentile; loading point max"
  std::string describe() const {
    return format_short(nonzero_percent(), 3) + " % with a force error > 1e-8 (above round-off); relative force error max " +
           format_short(max_force, 3) + ", median " + format_short(percentile(0.5), 3) + ", 99th percentile " +
           format_short(percentile(0.99), 3) + "; loading point error max " + format_short(max_point, 3) +
           " of the IP diameter";
  }
};

// ---- 1. contacts along the Sect. 4-5 runs -----------------------------------

struct SceneStats {
  std::string name;
  std::array<ModeStats, 2> mode;  // indexed as kModes
  double seconds = 0.0;
};

SceneStats scan(const std::string& name, const dda::Scene& scene, int every, int scene_id, repro::CsvWriter& csv) {
  const repro::Progress clock(name);
  SceneStats st;
  st.name = name;
  dda::Scene s = scene;  // the library defaults, made explicit
  s.contact.integration = Integration::kPaperBisector;
  s.contact.small_edge_rays = SmallEdgeRays::kVirtualAndVertex;
  dda::Simulation sim(s);
  const dda::ContactParams& c = s.contact;
  while (sim.time() < scene.duration - 0.5 * sim.dt()) {
    sim.step();
    if (sim.step_count() % every != 0) continue;
    for (const dda::ContactInfo& ci : sim.contacts()) {
      const double ha = sim.potential_length(ci.cp), hb = sim.potential_length(ci.tp);
      const Errors e = compare(sim.polygon(ci.cp), c.kn / ha, c.small_edge_fraction * ha, sim.polygon(ci.tp), c.kn / hb,
                               c.small_edge_fraction * hb);
      if (!e.valid) continue;
      for (std::size_t m = 0; m < kModes.size(); ++m) st.mode[m].add(e.mode[m]);
      csv.row({static_cast<double>(scene_id), sim.time(), e.mode[0].force, e.mode[0].point, e.mode[1].force,
               e.mode[1].point, e.depth_ratio});
    }
  }
  st.seconds = clock.elapsed_seconds();
  return st;
}

// ---- 2. fuzzed pairs -----------------------------------------------------------

std::vector<Vec2> random_polygon(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 3 + static_cast<int>(u(rng) * 8.0);  // 3..10 vertices
  std::vector<double> ang(static_cast<std::size_t>(n));
  for (double& a : ang) a = 2.0 * M_PI * u(rng);
  std::sort(ang.begin(), ang.end());
  const double aspect = std::exp(std::log(6.0) * u(rng));  // 1..6: elongated shapes have long medial segments
  const double rot = 2.0 * M_PI * u(rng);
  std::vector<Vec2> p;
  for (double a : ang) p.push_back(dda::rotate(Vec2{aspect * std::cos(a), std::sin(a)}, rot));
  // Sometimes cut one corner with a small edge (1e-3 to 5e-2 of the size).
  if (u(rng) < 0.3 && n >= 3) {
    const std::size_t i = static_cast<std::size_t>(u(rng) * n) % p.size();
    const Vec2 v = p[i], prev = p[(i + p.size() - 1) % p.size()], next = p[(i + 1) % p.size()];
    const double len = std::exp(std::log(1e-3) + (std::log(5e-2) - std::log(1e-3)) * u(rng));
    const Vec2 ua = dda::normalized(prev - v), ub = dda::normalized(next - v);
    const double t = len / dda::length(ua - ub);
    if (t < 0.3 * std::min(dda::distance(v, prev), dda::distance(v, next))) {
      p[i] = v + t * ub;
      p.insert(p.begin() + static_cast<long>(i), v + t * ua);
    }
  }
  return p;
}

}  // namespace

int main(int argc, char** argv) try {
  repro::check_command_line(argc, argv, "Beyond Paper A Sect. 3.2.3: is the segmentation of Eq. 16 exact?");
  const std::string out = repro::out_dir(argc, argv);
  const repro::Progress progress("5.5 segmentation");
  const std::string dir = out + "/data/segmentation";
  std::vector<repro::Claim> claims;
  const std::string sec = "5.5 (extra)";
  const std::string paper_rule = "paper's rule (library default: vertex and virtual-node rays)";
  const std::string replace_rule = "SPEC.md's reading (virtual node replaces the vertex rays)";

  // ---- 1. contacts of the Sect. 4-5 runs ----
  repro::CsvWriter contacts(
      dir + "/contacts.csv",
      {"scene", "time", "force_error_paper", "point_error_paper", "force_error_replace", "point_error_replace",
       "depth_ratio"},
      {"per contact and step of runs with the library defaults, paper's segmentation vs exact integration; "
       "force_error = |f_p - f_e|/|f_e|, point_error = |pg_p - pg_e|/diameter(IP); *_paper: small-edge rule "
       "kVirtualAndVertex (paper's printed rule, library default), *_replace: kVirtualReplacesVertex (SPEC.md's "
       "reading), both evaluated at the same states; depth_ratio = overlap thickness / (2 min inscribed radius)"});
  struct Named {
    std::string name;
    dda::Scene scene;
    int every;
  };
  std::vector<Named> scenes = {
      {"4.1 two squares", dda::paper::two_squares(), 1},
      {"4.2 symmetric stack", dda::paper::symmetric_stack().scene, 1},
      {"4.3 incline phi 20", dda::paper::incline(20.0).scene, 10},
      {"5.1 case 1 unified H", dda::paper::bouncing_block(0.1, dda::HRule::kMinMaxEdge).scene, 1},
      {"5.1 case 2 unified H", dda::paper::bouncing_block(1.0, dda::HRule::kMinMaxEdge).scene, 1},
      {"5.1 case 1 inscribed H", dda::paper::bouncing_block(0.1, dda::HRule::kInscribedRadius).scene, 1},
      {"5.1 case 2 inscribed H", dda::paper::bouncing_block(1.0, dda::HRule::kInscribedRadius).scene, 1},
      {"5.2 triangles 5 deg", dda::paper::small_angle_triangles(5.0).scene, 1},
      {"5.3 case 1 (on small edge)", dda::paper::small_edge_impact(dda::paper::SmallEdgeCase::kOnSmallEdge).scene, 1},
      {"5.3 case 2 (next to it)", dda::paper::small_edge_impact(dda::paper::SmallEdgeCase::kOnNeighbourEdge).scene, 1},
  };
  std::vector<std::string> summary_header = {"scene", "contacts"};
  for (const char* k : kModeKey)
    for (const char* col : {"nonzero_fraction", "max_force_error", "p50_force_error", "p99_force_error",
                            "max_point_error"})
      summary_header.push_back(std::string(col) + "_" + k);
  repro::CsvWriter summary(dir + "/summary.csv", summary_header,
                           {"paper: small-edge rule kVirtualAndVertex (library default); replace: "
                            "kVirtualReplacesVertex; both at the states of the default run"});
  std::array<double, 2> worst_scene = {0.0, 0.0};  // largest force error over every scene, per reading
  std::array<long, 2> nonzero_all = {0, 0};
  long contacts_all = 0;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const SceneStats st = scan(scenes[i].name, scenes[i].scene, scenes[i].every, static_cast<int>(i), contacts);
    std::vector<std::string> row = {st.name, std::to_string(st.mode[0].n)};
    for (const ModeStats& m : st.mode)
      for (double x : {m.nonzero_percent() / 100.0, m.max_force, m.percentile(0.5), m.percentile(0.99), m.max_point})
        row.push_back(repro::format_full(x));
    summary.row(row);
    for (std::size_t m = 0; m < kModes.size(); ++m) {
      worst_scene[m] = std::max(worst_scene[m], st.mode[m].max_force);
      nonzero_all[m] += st.mode[m].nonzero;
    }
    contacts_all += st.mode[0].n;
    progress(st.name + ": " + std::to_string(st.mode[0].n) + " contact evaluations, max force error " +
             format_short(st.mode[0].max_force, 3) + " (paper's rule) / " + format_short(st.mode[1].max_force, 3) +
             " (replacing), " + format_short(st.seconds, 3) + " s");
    claims.push_back({sec, "paper's segmentation vs exact integration, per contact and step: " + st.name,
                      "Sect. 3.2.3: 'the integral of potential on an edge can be computed accurately piece by piece'",
                      std::to_string(st.mode[0].n) + " contact evaluations of the run with the library defaults. " +
                          paper_rule + ": " + st.mode[0].describe() + ". " + replace_rule + ", same states: " +
                          (st.mode[1].same_as(st.mode[0]) ? std::string("the same errors, bit for bit")
                                                          : st.mode[1].describe()),
                      "information (exact would be 0)", false, repro::Kind::kMeasurement});
  }
  contacts.commit();
  summary.commit();
  claims.push_back({sec, "the library default (paper's printed small-edge rule) integrates every contact of the Sect. 4-5 runs exactly",
                    "Sect. 3.2.3: 'Both the real nodes and virtual nodes of CP or TP are used'",
                    std::to_string(contacts_all) + " contact evaluations in " + std::to_string(scenes.size()) +
                        " runs: largest relative force error " + paper_rule + " " + format_short(worst_scene[0], 3) +
                        " (" + std::to_string(nonzero_all[0]) + " above 1e-8); " + replace_rule + " at the same states " +
                        format_short(worst_scene[1], 3) + " (" + std::to_string(nonzero_all[1]) + " above 1e-8)",
                    "paper's rule: max relative force error < 1e-8", worst_scene[0] < 1e-8});

  // ---- 2. fuzzed pairs ----
  {
    const repro::Progress clock("fuzz");
    std::mt19937_64 rng(20240611);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    repro::CsvWriter fuzz(dir + "/fuzz.csv",
                          {"depth_ratio", "force_error_paper", "point_error_paper", "force_error_replace",
                           "point_error_replace", "has_small_edge"},
                          {"20000 random convex pairs (seed 20240611), overlap thickness log-uniform in [1e-3, 1] of the "
                           "smaller inscribed diameter, kn/H = 1/H with H the mean of the pair's "
                           "smallest and largest edge, small edges below 0.05 H get virtual nodes; *_paper: "
                           "kVirtualAndVertex (library default), *_replace: kVirtualReplacesVertex"});
    struct Bin {
      Bin(double l, double h) : lo(l), hi(h) {}
      double lo, hi;
      std::array<ModeStats, 2> mode;
      ModeStats small_paper, small_replace;  // the pairs with an edge below 0.05 H
    };
    std::vector<Bin> bins = {{0.0, 0.01}, {0.01, 0.1}, {0.1, 0.3}, {0.3, 1.01}};
    int accepted = 0, tries = 0;
    while (accepted < 20000 && tries < 1000000) {
      ++tries;
      const std::vector<Vec2> pa = random_polygon(rng), pb = random_polygon(rng);
      if (!dda::validate_polygon(pa.data(), static_cast<int>(pa.size())).ok() ||
          !dda::validate_polygon(pb.data(), static_cast<int>(pb.size())).ok())
        continue;
      Polygon a = dda::make_polygon(pa.data(), static_cast<int>(pa.size()));
      const Polygon b = dda::make_polygon(pb.data(), static_cast<int>(pb.size()));
      // Place A along a random direction from B's centroid at the distance
      // where the overlap thickness is a target fraction (log-uniform in
      // [1e-3, 1]) of the smaller inscribed diameter: found by bisection on
      // the distance (thickness falls as A moves out; 40 halvings).
      const double target = std::exp(std::log(1e-3) * u(rng)) * 2.0 *
                            std::min(dda::inscribed_circle(a).radius, dda::inscribed_circle(b).radius);
      const Vec2 dirn = dda::rotate(Vec2{1.0, 0.0}, 2.0 * M_PI * u(rng));
      a = dda::translated(a, dda::centroid(b) - dda::centroid(a));
      double lo = 0.0, hi = dda::diameter(a) + dda::diameter(b);
      for (int it = 0; it < 40; ++it) {
        const double mid = 0.5 * (lo + hi);
        (dda::paper::overlap_thickness(dda::translated(a, mid * dirn), b) > target ? lo : hi) = mid;
      }
      a = dda::translated(a, lo * dirn);
      const double lmin = std::min(dda::min_edge_length(a), dda::min_edge_length(b));
      const double lmax = std::max(dda::max_edge_length(a), dda::max_edge_length(b));
      const double h = 0.5 * (lmin + lmax);
      const Errors e = compare(a, 1.0 / h, 0.05 * h, b, 1.0 / h, 0.05 * h);
      if (!e.valid) continue;
      ++accepted;
      const bool small = lmin < 0.05 * h;
      fuzz.row({e.depth_ratio, e.mode[0].force, e.mode[0].point, e.mode[1].force, e.mode[1].point, small ? 1.0 : 0.0});
      for (Bin& bn : bins)
        if (e.depth_ratio >= bn.lo && e.depth_ratio < bn.hi) {
          for (std::size_t m = 0; m < kModes.size(); ++m) bn.mode[m].add(e.mode[m]);
          if (small) {
            bn.small_paper.add(e.mode[0]);
            bn.small_replace.add(e.mode[1]);
          }
        }
    }
    fuzz.commit();
    for (const Bin& bn : bins) {
      auto brief = [](const ModeStats& m) {
        return format_short(m.nonzero_percent(), 3) + " % with a force error > 1e-8, median " +
               format_short(m.percentile(0.5), 3) + ", max " + format_short(m.max_force, 3) +
               ", loading point error max " + format_short(m.max_point, 3) + " of the IP diameter";
      };
      claims.push_back(
          {sec,
           "fuzzed convex pairs, overlap depth " + format_short(bn.lo) + " to " + format_short(std::min(bn.hi, 1.0)) +
               " of the smaller inscribed diameter: paper's segmentation vs exact",
           "Sect. 3.2.3 (exactness implied)",
           std::to_string(bn.mode[0].n) + " pairs. " + paper_rule + ": " + brief(bn.mode[0]) + ". " + replace_rule +
               ": " + brief(bn.mode[1]) + ". Of these, the " + std::to_string(bn.small_paper.n) +
               " pairs with an edge below 0.05 H: paper's rule " + format_short(bn.small_paper.nonzero_percent(), 3) +
               " % nonzero (max " + format_short(bn.small_paper.max_force, 3) + "), replacing reading " +
               format_short(bn.small_replace.nonzero_percent(), 3) + " % (max " +
               format_short(bn.small_replace.max_force, 3) + ")",
           "information (exact would be 0)", false, repro::Kind::kMeasurement});
    }
    progress("fuzz: " + std::to_string(accepted) + " pairs in " + format_short(clock.elapsed_seconds(), 3) + " s");
  }

  // ---- 4. the rectangle's middle segment ----
  {
    const Vec2 r[4] = {{0, 0}, {2, 0}, {2, 1}, {0, 1}};
    const Polygon tp = dda::make_polygon(r, 4);
    const double s = 0.5 * std::sqrt(2.0), depth = 0.7;
    const Vec2 q[4] = {{1.0, 1.0 - depth}, {1.0 + s, 1.0 - depth + s}, {1.0, 1.0 - depth + 2 * s}, {1.0 - s, 1.0 - depth + s}};
    const Polygon cp = dda::make_polygon(q, 4);
    const Errors e = compare(cp, 1.0, 0.0, tp, 1.0, 0.0);  // no small edges: both readings are the same rays
    claims.push_back({sec, "a square's corner 0.7 m deep in a 2 m x 1 m rectangle (crossing the middle medial segment)",
                      "the rectangle's middle segment y = 0.5 carries no vertex bisector ray",
                      "relative force error " + format_short(e.mode[0].force, 3) + ", loading point error " +
                          format_short(e.mode[0].point, 3) + " of the IP diameter (no small edge: either reading)",
                      "> 1e-6 (the rule is not exact here)", e.valid && e.mode[0].force > 1e-6});
    progress("rectangle case: force error " + format_short(e.mode[0].force, 3));
  }

  // ---- 3. trajectories with each rule ----
  {
    repro::CsvWriter traj(dir + "/trajectories.csv", {"scene", "time", "difference_paper", "difference_replace"},
                          {"difference from the run with the exact integration of the runs with the paper's "
                           "segmentation, small-edge rule kVirtualAndVertex (paper, library default) and "
                           "kVirtualReplacesVertex (replace): 4.1 |dv_B| (m/s), 4.3 |d sliding distance| (m), "
                           "5.1 |d dy_A| (m), 5.3 |d vertex position| (m)"});
    repro::CsvWriter traj_runs(dir + "/trajectory_runs.csv",
                               {"scene", "name", "max_difference_paper", "max_difference_replace", "energy_error_paper",
                                "energy_error_replace", "energy_error_exact"});
    struct Traj {
      std::string name;
      dda::Scene scene;
      int every;
      std::function<double(const dda::Simulation&)> q;  // the watched quantity (scalar)
      std::function<Vec2(const dda::Simulation&)> q2;    // or a point
    };
    auto vb = [](const dda::Simulation& s) { return s.velocity(1)[0]; };
    std::vector<Traj> runs;
    runs.push_back({"4.1 two squares (v_B)", dda::paper::two_squares(), 10, vb, nullptr});
    for (double phi : {0.0, 10.0, 20.0}) {
      const dda::paper::Incline in = dda::paper::incline(phi);
      const Vec2 down = in.downhill;
      runs.push_back({"4.3 incline phi " + format_short(phi) + " (sliding distance)", in.scene, 500,
                      [down](const dda::Simulation& s) { return dda::dot(s.centroid(1), down); }, nullptr});
    }
    for (double h : {0.1, 1.0})
      for (dda::HRule rule : {dda::HRule::kMinMaxEdge, dda::HRule::kInscribedRadius})
        runs.push_back({"5.1 B " + format_short(h) + " m, " + (rule == dda::HRule::kMinMaxEdge ? "unified" : "inscribed") +
                            " H (dy_A)",
                        dda::paper::bouncing_block(h, rule).scene, 10,
                        [](const dda::Simulation& s) { return s.centroid(1).y; }, nullptr});
    for (auto which : {dda::paper::SmallEdgeCase::kOnSmallEdge, dda::paper::SmallEdgeCase::kOnNeighbourEdge})
      runs.push_back({std::string("5.3 case ") + (which == dda::paper::SmallEdgeCase::kOnSmallEdge ? "1" : "2") +
                          " (contacting vertex)",
                      dda::paper::small_edge_impact(which).scene, 5, nullptr,
                      [](const dda::Simulation& s) { return s.polygon(1).vertex(0); }});
    for (std::size_t k = 0; k < runs.size(); ++k) {
      const Traj& t = runs[k];
      const repro::Progress clock(t.name);
      // Runs 0, 1: paper segmentation with each small-edge reading; 2: exact.
      std::array<dda::Scene, 3> sc = {t.scene, t.scene, t.scene};
      for (std::size_t m = 0; m < kModes.size(); ++m) {
        sc[m].contact.integration = Integration::kPaperBisector;
        sc[m].contact.small_edge_rays = kModes[m];
      }
      sc[2].contact.integration = Integration::kExactEnvelope;
      dda::Simulation s0(sc[0]), s1(sc[1]), s2(sc[2]);
      std::array<dda::Simulation*, 3> sim = {&s0, &s1, &s2};
      dda::paper::RunMonitor m0(s0, 0, 1), m1(s1, 0, 1), m2(s2, 0, 1);
      std::array<dda::paper::RunMonitor*, 3> mon = {&m0, &m1, &m2};
      auto diff = [&](const dda::Simulation& a, const dda::Simulation& b) {
        return t.q ? std::fabs(t.q(a) - t.q(b)) : dda::distance(t.q2(a), t.q2(b));
      };
      std::array<double, 2> worst = {0.0, 0.0};
      double between = 0.0;  // largest difference between the two readings' runs
      while (s0.time() < sc[0].duration - 0.5 * s0.dt()) {
        for (int r = 0; r < 3; ++r) {
          sim[r]->step();
          mon[r]->sample();
        }
        const double d0 = diff(s0, s2), d1 = diff(s1, s2);
        worst = {std::max(worst[0], d0), std::max(worst[1], d1)};
        between = std::max(between, diff(s0, s1));
        if (s0.step_count() % t.every == 0) traj.row({static_cast<double>(k), s0.time(), d0, d1});
      }
      const double e0 = m0.stats().energy_error, e1 = m1.stats().energy_error, e2 = m2.stats().energy_error;
      const bool identical = between == 0.0 && e0 == e1;
      traj_runs.row(std::vector<std::string>{std::to_string(k), t.name, repro::format_full(worst[0]),
                                             repro::format_full(worst[1]), repro::format_full(e0),
                                             repro::format_full(e1), repro::format_full(e2)});
      const bool friction = t.scene.contact.friction() && t.scene.contact.friction_deg > 0.0;
      claims.push_back(
          {sec, "effect on the trajectory: " + t.name, "(not discussed in the paper)",
           "max difference from the exact integration: " + paper_rule + " " + format_short(worst[0], 3) + ", " +
               replace_rule + " " + format_short(worst[1], 3) + (identical ? " (the two readings' runs never differ)" : "") +
               (friction ? "; energy change (friction dissipates): paper's rule " : "; energy error: paper's rule ") +
               format_short(e0, 3) + ", replacing " + format_short(e1, 3) + ", exact " + format_short(e2, 3),
           "information", false, repro::Kind::kMeasurement});
      progress(t.name + ": max difference " + format_short(worst[0], 3) + " (paper's rule) / " +
               format_short(worst[1], 3) + " (replacing), energy error " + format_short(e0, 3) + " / " +
               format_short(e1, 3) + " / exact " + format_short(e2, 3) + ", " + format_short(clock.elapsed_seconds(), 3) +
               " s");
    }
    traj.commit();
    traj_runs.commit();
  }

  repro::write_claims(repro::claims_path(out, "5_5_segmentation"), claims);
  progress("done");
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "segmentation: error: %s\n", e.what());
  return 1;
}
