// S3 extreme cases: the criteria of the rows and the guard row's scene
// (extreme_cases.hpp), shared with the negative controls.
#include "dda/paper_scenes.hpp"
#include "repro/S3_extreme_cases/extreme_cases.hpp"
#include "repro/common/shapes.hpp"

namespace s3 {
using repro::rect;

std::pair<bool, std::string> row_verdict(const Extreme& e, const Outcome& o) {
  bool pass = false;
  std::string tolerance;
  const bool deep_case = e.name == "deep penetration" || e.parameter == "100 m/s";
  if (deep_case) {
    tolerance = "stopped by the penetration guard before the blocks cross";
    pass = o.penetration_stop;
  } else if (o.ratio0 > 1.0) {
    tolerance = "dt above dt_crit: the solver stops with a message";
    pass = !o.message.empty() && o.message.find("dt/dt_crit") != std::string::npos;
  } else {
    tolerance = "stable and |v - v_expected| < 5 % of the impact speed";
    pass = o.cls == RunClass::kStable && o.velocity_error < 0.05;
  }
  return {pass && o.t_swap < 0.0, tolerance + "; the blocks never cross"};
}

dda::Scene guard_scene(double dt_fraction) {
  dda::Scene s = dda::paper::two_squares();
  s.blocks[0].vertices = rect(-1.001, -0.5, 1.0, 1.0);
  s.contact.kn = 1e10;
  s.dt_fraction = dt_fraction;
  s.duration = 0.2;
  s.guards.energy_check_every = 1;
  return s;
}

bool guard_stop_complete(const std::string& message, long rows_kept) {
  bool names_all = !message.empty();
  for (const char* word : {"step ", "(t = ", " s)", "block ", "pair (", "dt/dt_crit = "})
    names_all = names_all && message.find(word) != std::string::npos;
  names_all = names_all && (message.find("more than") != std::string::npos ||
                            message.find("non-finite") != std::string::npos ||
                            message.find("collapsed") != std::string::npos);
  return names_all && rows_kept >= 1;
}

}  // namespace s3
