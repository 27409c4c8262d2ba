// Negative control of the Sect. 5.4 "clean" criterion: a damped, an
// asymmetric and a pierced run, each differing from a clean paper-size case
// in one thing the criterion must see, must not count as clean.
#include <catch2/catch.hpp>

#include <string>

#include "repro/5_4_extreme_geometry/extreme_geometry.hpp"
#include "repro/common/controls.hpp"

namespace {
extreme::Case extreme_case(const std::string& label) {
  return controls::find(
      extreme::make_cases(), [&label](const extreme::Case& c) { return c.label == label; }, "5.4 case " + label);
}
}  // namespace

TEST_CASE("5.4 clean: FAIL on a damped, an asymmetric and a pierced run", "[controls][5.4]") {
  // Each run below differs from a clean paper-size case in one thing the
  // criterion must see.
  const extreme::Case bounce = extreme_case("bouncing block, B height 0.1 m, unified H");
  const extreme::Outcome ok = extreme::attempt(bounce, bounce.scene.dt, true);
  CHECK(ok.clean);
  // Energy: mass damping (1 1/s) takes energy out; the run is otherwise clean.
  extreme::Case damped = bounce;
  damped.scene.damping.mass = 1.0;
  const extreme::Outcome d = extreme::attempt(damped, damped.scene.dt, true);
  INFO(d.verdict);
  CHECK_FALSE(d.clean);
  CHECK(d.energy_bad);
  // Symmetry: the upper 5 deg triangle drifts sideways at 1 cm/s.
  extreme::Case tri = extreme_case("triangles, apex angle 5 deg");
  CHECK(extreme::attempt(tri, tri.scene.dt, true).clean);
  tri.scene.blocks[static_cast<std::size_t>(tri.pushed)].velocity.x += 0.01;
  const extreme::Outcome a = extreme::attempt(tri, tri.scene.dt, true);
  INFO(a.verdict);
  CHECK_FALSE(a.clean);
  CHECK(a.asymmetric);
  // Flip-through: the 1 mm thin B with every guard off: A goes through.
  extreme::Case thin = extreme_case("bouncing block, B height 0.001 m, unified H");
  thin.scene.guards.max_penetration = 0.0;
  thin.scene.guards.max_approach_energy = 0.0;
  const extreme::Outcome f = extreme::attempt(thin, thin.scene.dt, false);
  INFO(f.verdict);
  CHECK_FALSE(f.clean);
  CHECK((f.flip || f.pierced));
}
