// Beyond Paper A Sect. 3.2.3 (segmentation.cpp says what it measures): the
// comparison of the paper's segmentation with the exact integration, the
// scans, the fuzzed pairs, the rectangle case and the criteria of the check
// rows, here so that the negative controls (controls.cpp beside it)
// apply the same criteria to a deliberately wrong configuration.
#pragma once
#include <array>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "dda/contact.hpp"
#include "dda/polygon.hpp"
#include "dda/simulation.hpp"
#include "repro/common/claims.hpp"
#include "repro/common/table.hpp"

namespace segmentation {

// The two readings of the small-edge rule, in the order of every table here.
constexpr std::array<dda::SmallEdgeRays, 2> kModes = {dda::SmallEdgeRays::kVirtualAndVertex,
                                                      dda::SmallEdgeRays::kVirtualReplacesVertex};
constexpr std::array<const char*, 2> kModeKey = {"paper", "replace"};
constexpr std::size_t kPaperRule = 0, kReplaceRule = 1;  // indices into kModes
inline const char* const kSection = "5.5 (extra)";
inline const char* const kPaperRuleName = "paper's rule (library default: vertex and virtual-node rays)";
inline const char* const kReplaceRuleName = "the replacing reading (virtual node replaces the vertex rays)";

constexpr double kExactTolerance = 1e-8;    // a relative force error above this is not round-off
constexpr double kInexactThreshold = 1e-6;  // the rectangle case must exceed this
constexpr double kRectangleDepth = 0.7;     // m: the square's corner below the rectangle's top

// The negative controls of the check rows (test names in repro_controls).
inline const char* const kControlExact =
    "5.5 segmentation exact on the Sect. 4-5 runs: FAIL with SPEC.md's reading on the 5.3 impact";
inline const char* const kControlRectangle =
    "5.5 rectangle: FAIL when the corner stays above the middle medial segment";

// ---- comparing one configuration ----------------------------------------------

struct ModeError {
  double force = 0.0;  // |f_p - f_e| / |f_e|
  double point = 0.0;  // |pg_p - pg_e| / diameter(IP)
};

struct Errors {
  bool valid = false;
  std::array<ModeError, 2> mode{};  // indexed as kModes
  double depth_ratio = 0.0;         // overlap thickness / (2 min inscribed radius)
};

// Paper's segmentation under both readings vs the exact integration, for one
// pair (kn/H and the small-edge length of each side).
Errors compare(const dda::Polygon& a, double kn_h_a, double small_a, const dda::Polygon& b, double kn_h_b,
               double small_b);

// Error statistics of one reading over many configurations.
struct ModeStats {
  long n = 0, nonzero = 0;  // nonzero: relative force error > kExactTolerance (above round-off)
  double max_force = 0.0, max_point = 0.0;
  std::vector<double> force_errors;
  void add(const ModeError& m);
  double nonzero_percent() const;
  double percentile(double q) const;
  bool same_as(const ModeStats& o) const;
  // "x % with a force error > 1e-8; max, median, 99th percentile; loading point max"
  std::string describe() const;
  // "x % with a force error > 1e-8, median, max, loading point error max"
  std::string brief() const;
};

// ---- 1. contacts along a run ----------------------------------------------------

struct SceneStats {
  std::string name;
  std::array<ModeStats, 2> mode;  // indexed as kModes
  double seconds = 0.0;
};

// One compared contact of a scan (contacts.csv) or of the fuzz (fuzz.csv).
struct Compared {
  int scene;  // the scan's scene number (contacts.csv)
  double time;
  Errors e;
  bool small_edge;  // the pair has an edge below 0.05 H (fuzz.csv)
};
std::vector<repro::Column<Compared>> contact_columns();
std::vector<repro::Column<Compared>> fuzz_columns();

// Runs `scene` with the library defaults (paper segmentation, paper small-edge
// rule) and compares every contact every `every` steps under both readings;
// each to `table` if given.
SceneStats scan(const std::string& name, const dda::Scene& scene, int every, int scene_id,
                repro::TableWriter<Compared>* table);

// The check "the library default integrates every contact of the Sect. 4-5
// runs exactly": the largest relative force error of reading `tested` over
// every scan below kExactTolerance (the driver tests kPaperRule).
repro::Claim exact_row(const std::vector<SceneStats>& scans, std::size_t tested = kPaperRule);

// ---- 2. fuzzed pairs ---------------------------------------------------------------

std::vector<dda::Vec2> random_polygon(std::mt19937_64& rng);

// Runs the fuzz (20000 pairs, seed 20240611), writes <dir>/fuzz.csv and adds
// one measurement row per depth bin; returns the number of pairs.
int fuzz(const std::string& dir, std::vector<repro::Claim>& claims);

// ---- 3. trajectories ------------------------------------------------------------

struct Traj {
  std::string name;
  dda::Scene scene;
  int every;
  std::function<double(const dda::Simulation&)> q;  // the watched quantity (scalar)
  std::function<dda::Vec2(const dda::Simulation&)> q2;  // or a point
};

struct TrajResult {
  std::array<double, 2> worst = {0.0, 0.0};  // max difference from the exact run, per reading
  std::array<double, 3> energy = {0.0, 0.0, 0.0};  // energy error: paper, replace, exact
  bool identical = false;  // the two readings' runs never differ
};

// One moment of trajectories.csv: the difference of each reading's run from
// the exact one.
struct TrajSample {
  std::size_t scene;
  double time, difference_paper, difference_replace;
};
std::vector<repro::Column<TrajSample>> trajectory_columns();

// Runs t three times (paper segmentation with each reading, exact) side by
// side; every t.every steps a TrajSample of scene k to traj.
TrajResult run_trajectory(const Traj& t, std::size_t k, repro::TableWriter<TrajSample>& traj);

// ---- 4. the rectangle's middle segment ------------------------------------------

// A 1 m square turned 45 deg, its corner pushed `depth` m down into a 2 m x
// 1 m rectangle at x = 1 (kn/H = 1, no small edges): deeper than 0.5 m its IP
// crosses the middle medial segment y = 0.5, which carries no vertex ray.
Errors rectangle_case(double depth);

// The check: the rule is not exact there (force error > kInexactThreshold).
repro::Claim rectangle_row(double depth, const Errors& e);

}  // namespace segmentation
