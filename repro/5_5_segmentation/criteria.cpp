// The 5.5 driver's check rows (segmentation.hpp): the criteria the negative
// controls apply to a deliberately wrong configuration.
#include <algorithm>
#include <cmath>

#include "repro/5_5_segmentation/segmentation.hpp"
#include "repro/common/common.hpp"

namespace segmentation {

using repro::format_short;

repro::Claim exact_row(const std::vector<SceneStats>& scans, std::size_t tested) {
  std::array<double, 2> worst = {0.0, 0.0};  // largest force error over every scene, per reading
  std::array<long, 2> nonzero = {0, 0};
  long contacts = 0;
  for (const SceneStats& st : scans) {
    for (std::size_t m = 0; m < kModes.size(); ++m) {
      worst[m] = std::max(worst[m], st.mode[m].max_force);
      nonzero[m] += st.mode[m].nonzero;
    }
    contacts += st.mode[0].n;
  }
  repro::Claim c{kSection,
                 "the library default (paper's printed small-edge rule) integrates every contact of the Sect. 4-5 runs exactly",
                 "Sect. 3.2.3: 'Both the real nodes and virtual nodes of CP or TP are used'",
                 std::to_string(contacts) + " contact evaluations in " + std::to_string(scans.size()) +
                     " runs: largest relative force error " + kPaperRuleName + " " + format_short(worst[0], 3) + " (" +
                     std::to_string(nonzero[0]) + " above 1e-8); " + kReplaceRuleName + " at the same states " +
                     format_short(worst[1], 3) + " (" + std::to_string(nonzero[1]) + " above 1e-8)",
                 "paper's rule: max relative force error < 1e-8", worst[tested] < kExactTolerance};
  c.control = std::string("repro_controls: ") + kControlExact;
  return c;
}

repro::Claim rectangle_row(double depth, const Errors& e) {
  repro::Claim c{kSection,
                 "a square's corner " + format_short(depth) +
                     " m deep in a 2 m x 1 m rectangle (crossing the middle medial segment)",
                 "the rectangle's middle segment y = 0.5 carries no vertex bisector ray",
                 "relative force error " + format_short(e.mode[0].force, 3) + ", loading point error " +
                     format_short(e.mode[0].point, 3) + " of the IP diameter (no small edge: either reading)",
                 "> 1e-6 (the rule is not exact here)", e.valid && e.mode[0].force > kInexactThreshold};
  c.control = std::string("repro_controls: ") + kControlRectangle;
  return c;
}

}  // namespace segmentation
