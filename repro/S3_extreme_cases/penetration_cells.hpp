// S3 penetration map (penetration_map.cpp says what it shows): the cells,
// one run of a cell and the rows' criteria, here so that the negative
// controls (controls.cpp beside it) apply the same ones.
#pragma once
#include <string>
#include <vector>

#include "dda/scene.hpp"

namespace s3map {

inline constexpr double kGap = 0.02;                    // A's face to B's at t = 0, m
inline constexpr double kOffset = 0.2;                  // B's centre above A's, m: not a symmetric hit
inline constexpr double kOblique = 0.5235987755982988;  // 30 deg off the face normal, rad
inline constexpr double kPaperDt = 1e-4;                // Sect. 4.1's time step, s
inline constexpr double kSoftKn = 1e5;                  // Pa: the v-dt map's penalty, 1 % of Sect. 4.1's
inline const std::vector<double> kSpeeds{0.5, 1, 2, 4, 8, 16, 32, 64};  // m/s
inline const std::vector<double> kKns{1e4, 1e5, 1e6, 1e7, 1e8};         // Pa
inline const std::vector<double> kDts{1e-5, 3e-5, 1e-4, 3e-4, 1e-3};    // s

enum class Cell { kBounced, kGuardStop, kOtherStop, kPassed, kStuck, kMissed };
const char* name(Cell c);

struct Setup {
  std::string map;
  bool oblique = false;
  double speed = 0.0, kn = 0.0, dt = 0.0;
};

// The cell's scene; guarded false: the penetration guard off.
dda::Scene scene(const Setup& c, bool guarded);

struct Result {
  Cell cls = Cell::kBounced;
  double ratio = 0.0;  // dt / predicted dt_crit at the start
  std::string message;
  std::vector<double> final_state;  // vertex coordinates at the end (bounces only)
};

// One run of the scene s (scene(c, guarded), possibly altered), classified.
Result run(const dda::Scene& s);

// The guard's message names what a user needs to act on: where (step,
// time, pair), the bound (a depth bound, or the energy the pair can store),
// dt/dt_crit and what to change (kn).
bool actionable(const std::string& message);

// Row "the guard does not touch a bounce": every cell that bounces with the
// guard on ends bit for bit as without it, and there is at least one.
inline bool bounces_untouched(int bounces, int identical) { return bounces > 0 && identical == bounces; }
inline constexpr const char* kControlUntouched = "S3 map bounces: FAIL against a run with kn changed by 1e-9";
// Row "every penetration-guard stop names ...": all stop messages
// actionable, and there is at least one stop.
inline bool stops_actionable(int stops, int actionable_count) { return stops > 0 && actionable_count == stops; }
inline constexpr const char* kControlActionable =
    "S3 map messages: FAIL on a map without stops and on another guard's message";

}  // namespace s3map
