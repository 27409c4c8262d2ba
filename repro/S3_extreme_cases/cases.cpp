// S3 extreme cases: the impacts and what the rigid 1D elastic exchange
// says they end with (extreme_cases.hpp).
#include <string>
#include <utility>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "repro/S3_extreme_cases/extreme_cases.hpp"
#include "repro/common/shapes.hpp"

namespace s3 {
namespace {
using repro::rect;

// Out of line: GCC 12 warns (falsely, -Wmaybe-uninitialized) about Scene's
// default member initialisers when the constructor is inlined into cases().
[[gnu::noinline]] Extreme new_case() { return Extreme{}; }

dda::BlockSpec block(std::vector<Vec2> v, Vec2 vel, int material = 0) {
  dda::BlockSpec b;
  b.vertices = std::move(v);
  b.velocity = vel;
  b.material = material;
  return b;
}

// The 4.1 two squares' material and contact with blocks a (moving at v0
// along x) and b (at rest), run for `duration`; the expected velocities of
// the rigid 1D elastic exchange between masses ma and mb.
Extreme impact(const std::string& name, const std::string& parameter, const std::vector<Vec2>& a,
               const std::vector<Vec2>& b, double duration, double ma, double mb, double v0 = 1.0) {
  Extreme e = new_case();
  e.name = name;
  e.parameter = parameter;
  e.scene = dda::paper::two_squares();
  e.scene.blocks = {block(a, {v0, 0.0}), block(b, {})};
  e.duration = duration;
  e.v0 = v0;
  e.va_expected = (ma - mb) / (ma + mb) * e.v0;
  e.vb_expected = 2.0 * ma / (ma + mb) * e.v0;
  return e;
}

}  // namespace

std::vector<Extreme> cases() {
  std::vector<Extreme> out;
  const std::vector<Vec2> unit = rect(0.0, -0.5, 1.0, 1.0), unit_left = rect(-1.001, -0.5, 1.0, 1.0);
  for (double ratio : {1e4, 1e-4}) {
    Extreme e = impact("mass ratio", "m_A / m_B = " + format_short(ratio), rect(-1.1, -0.5, 1.0, 1.0), unit, 0.4,
                       ratio, 1.0);
    e.scene.materials = {{2000.0, 1e9, 0.25}, {2000.0 * ratio, 1e9, 0.25}};
    e.scene.blocks[0].material = 1;
    out.push_back(e);
  }
  for (double v : {1.0, 10.0, 100.0})
    out.push_back(impact("impact speed", format_short(v) + " m/s", unit_left, unit, 0.1, 1.0, 1.0, v));
  // Masses in proportion to the areas, 1e-4 and 100 m^2.
  out.push_back(impact("size ratio", "0.01 m square hits a 10 m square (1000 x)", rect(-0.0101, -0.005, 0.01, 0.01),
                       rect(0.0, -5.0, 10.0, 10.0), 0.02, 1e-4, 100.0));
  out.push_back(impact("sliver 100:1", "1 m square hits the long side of a 0.01 m x 1 m sliver", unit_left,
                       rect(0.0, -0.5, 0.01, 1.0), 0.05, 1.0, 0.01));
  out.push_back(impact("sliver 100:1", "1 m x 0.01 m sliver flies end-on into a 1 m square",
                       rect(-1.001, -0.005, 1.0, 0.01), unit, 0.3, 0.01, 1.0));
  Extreme deep = impact("deep penetration", "two squares at 1 m/s, kn = 1e3 Pa (overlap to stop: 0.71 m)", unit_left,
                        unit, 3.0, 1.0, 1.0);
  deep.scene.contact.kn = 1e3;
  out.push_back(deep);
  return out;
}

}  // namespace s3
