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
//   "replace" = kVirtualReplacesVertex, the replacing reading (the virtual node
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
// The comparison, the scans and the criteria of the check rows are in
// segmentation.hpp: compare.cpp, runs.cpp and criteria.cpp (shared with the
// negative controls).
//
// Output: data/segmentation/contacts.csv, summary.csv (1), fuzz.csv (2),
// trajectories.csv, trajectory_runs.csv (3); claims/5_5_segmentation.csv.
#include <array>
#include <iterator>
#include <string>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "dda/robustness_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/5_5_segmentation/segmentation.hpp"
#include "repro/common/common.hpp"

using namespace segmentation;
using dda::Vec2;
using repro::format_short;

// The driver: its name in errors, its progress lines' prefix and its usage line.
const repro::DriverInfo kInfo = {"segmentation", "5.5 segmentation",
                                 "Beyond Paper A Sect. 3.2.3: is the segmentation of Eq. 16 exact?"};

namespace {

using Claims = std::vector<repro::Claim>;

// 1. The contacts of the Sect. 4-5 runs: contacts.csv, summary.csv, a
// measurement row per scene and the exactness check.
void contact_scans(const repro::Driver& d, const std::string& dir, Claims& claims) {
  const std::string paper_rule = kPaperRuleName, replace_rule = kReplaceRuleName;
  repro::TableWriter<Compared> contacts(
      dir + "/contacts.csv", contact_columns(),
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
  std::vector<repro::Column<SceneStats>> summary_columns = {
      {"scene", [](const SceneStats& st) { return st.name; }},
      {"contacts", [](const SceneStats& st) { return std::to_string(st.mode[0].n); }}};
  const std::vector<repro::Column<ModeStats>> stats = {
      {"nonzero_fraction", [](const ModeStats& m) { return m.nonzero_percent() / 100.0; }},
      {"max_force_error", [](const ModeStats& m) { return m.max_force; }},
      {"p50_force_error", [](const ModeStats& m) { return m.percentile(0.5); }},
      {"p99_force_error", [](const ModeStats& m) { return m.percentile(0.99); }},
      {"max_point_error", [](const ModeStats& m) { return m.max_point; }}};
  for (std::size_t k = 0; k < std::size(kModeKey); ++k)
    for (const repro::Column<ModeStats>& c : stats)
      summary_columns.push_back(
          {c.name + "_" + kModeKey[k], [k, cell = c.cell](const SceneStats& st) { return cell(st.mode[k]); }});
  std::vector<SceneStats> scans;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    const SceneStats st = scan(scenes[i].name, scenes[i].scene, scenes[i].every, static_cast<int>(i), &contacts);
    scans.push_back(st);
    d.progress(st.name + ": " + std::to_string(st.mode[0].n) + " contact evaluations, max force error " +
               format_short(st.mode[0].max_force, 3) + " (paper's rule) / " + format_short(st.mode[1].max_force, 3) +
               " (replacing), " + format_short(st.seconds, 3) + " s");
    claims.push_back(
        {kSection, "paper's segmentation vs exact integration, per contact and step: " + st.name,
         "Sect. 3.2.3: 'the integral of potential on an edge can be computed accurately piece by piece'",
         std::to_string(st.mode[0].n) + " contact evaluations of the run with the library defaults. " + paper_rule +
             ": " + st.mode[0].describe() + ". " + replace_rule + ", same states: " +
             (st.mode[1].same_as(st.mode[0]) ? std::string("the same errors, bit for bit") : st.mode[1].describe()),
         "information (exact would be 0)", false, repro::Kind::kMeasurement});
  }
  contacts.commit();
  repro::write_table(dir + "/summary.csv", summary_columns, scans,
                     {"paper: small-edge rule kVirtualAndVertex (library default); replace: "
                      "kVirtualReplacesVertex; both at the states of the default run"});
  claims.push_back(exact_row(scans));
}

// The runs of the trajectory study: what each watches and how often.
std::vector<Traj> trajectories() {
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
      runs.push_back({"5.1 B " + format_short(h) + " m, " +
                          (rule == dda::HRule::kMinMaxEdge ? "unified" : "inscribed") + " H (dy_A)",
                      dda::paper::bouncing_block(h, rule).scene, 10,
                      [](const dda::Simulation& s) { return s.centroid(1).y; }, nullptr});
  for (auto which : {dda::paper::SmallEdgeCase::kOnSmallEdge, dda::paper::SmallEdgeCase::kOnNeighbourEdge})
    runs.push_back({std::string("5.3 case ") + (which == dda::paper::SmallEdgeCase::kOnSmallEdge ? "1" : "2") +
                        " (contacting vertex)",
                    dda::paper::small_edge_impact(which).scene, 5, nullptr,
                    [](const dda::Simulation& s) { return s.polygon(1).vertex(0); }});
  return runs;
}

// 3. Each trajectory run with each rule: trajectories.csv,
// trajectory_runs.csv and a measurement row per run.
void trajectory_rows(const repro::Driver& d, const std::string& dir, Claims& claims) {
  const std::string paper_rule = kPaperRuleName, replace_rule = kReplaceRuleName;
  repro::TableWriter<TrajSample> traj(dir + "/trajectories.csv", trajectory_columns(),
                                      {"difference from the run with the exact integration of the runs with the "
                                       "paper's segmentation, small-edge rule kVirtualAndVertex (paper, library "
                                       "default) and kVirtualReplacesVertex (replace): 4.1 |dv_B| (m/s), 4.3 |d "
                                       "sliding distance| (m), 5.1 |d dy_A| (m), 5.3 |d vertex position| (m)"});
  struct Row {
    std::size_t k;
    std::string name;
    TrajResult r;
  };
  std::vector<Row> rows;
  const std::vector<Traj> runs = trajectories();
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const Traj& t = runs[k];
    const repro::Progress clock(t.name);
    const TrajResult r = run_trajectory(t, k, traj);
    const double e0 = r.energy[0], e1 = r.energy[1], e2 = r.energy[2];
    rows.push_back({k, t.name, r});
    const bool friction = t.scene.contact.friction() && t.scene.contact.friction_deg > 0.0;
    claims.push_back(
        {kSection, "effect on the trajectory: " + t.name, "(not discussed in the paper)",
         "max difference from the exact integration: " + paper_rule + " " + format_short(r.worst[0], 3) + ", " +
             replace_rule + " " + format_short(r.worst[1], 3) +
             (r.identical ? " (the two readings' runs never differ)" : "") +
             (friction ? "; energy change (friction dissipates): paper's rule " : "; energy error: paper's rule ") +
             format_short(e0, 3) + ", replacing " + format_short(e1, 3) + ", exact " + format_short(e2, 3),
         "information", false, repro::Kind::kMeasurement});
    d.progress(t.name + ": max difference " + format_short(r.worst[0], 3) + " (paper's rule) / " +
               format_short(r.worst[1], 3) + " (replacing), energy error " + format_short(e0, 3) + " / " +
               format_short(e1, 3) + " / exact " + format_short(e2, 3) + ", " +
               format_short(clock.elapsed_seconds(), 3) + " s");
  }
  traj.commit();
  repro::write_table<Row>(dir + "/trajectory_runs.csv",
                          {{"scene", [](const Row& w) { return std::to_string(w.k); }},
                           {"name", [](const Row& w) { return w.name; }},
                           {"max_difference_paper", [](const Row& w) { return w.r.worst[0]; }},
                           {"max_difference_replace", [](const Row& w) { return w.r.worst[1]; }},
                           {"energy_error_paper", [](const Row& w) { return w.r.energy[0]; }},
                           {"energy_error_replace", [](const Row& w) { return w.r.energy[1]; }},
                           {"energy_error_exact", [](const Row& w) { return w.r.energy[2]; }}},
                          rows);
}

// The run: what main's driver_main calls once the command line is checked.
int reproduce(const repro::Driver& d) {
  const std::string dir = d.out + "/data/segmentation";
  Claims claims;
  contact_scans(d, dir, claims);  // 1. contacts of the Sect. 4-5 runs
  {                               // 2. fuzzed pairs
    const repro::Progress clock("fuzz");
    const int accepted = fuzz(dir, claims);
    d.progress("fuzz: " + std::to_string(accepted) + " pairs in " + format_short(clock.elapsed_seconds(), 3) + " s");
  }
  // 4. the rectangle's middle segment
  const Errors rect = rectangle_case(kRectangleDepth);
  claims.push_back(rectangle_row(kRectangleDepth, rect));
  d.progress("rectangle case: force error " + format_short(rect.mode[0].force, 3));
  trajectory_rows(d, dir, claims);                         // 3. trajectories with each rule
  repro::default_scope(claims, repro::Scope::kExtension);  // a study beyond the paper, every row
  repro::write_claims(repro::claims_path(d.out, "5_5_segmentation"), claims);
  d.progress("done");
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return repro::driver_main(argc, argv, kInfo, {}, reproduce); }
