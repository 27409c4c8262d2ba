// Negative control of the Sect. 4.2 symmetric-stack row: the symmetry
// criterion on a run whose impactor drifts sideways must FAIL.
#include <catch2/catch.hpp>

#include <string>

#include "dda/paper_scenes.hpp"
#include "repro/4_2_symmetric_stack/symmetric_stack.hpp"
#include "repro/common/claims.hpp"

TEST_CASE("4.2 symmetry: FAIL when the impactor drifts sideways", "[controls][4.2]") {
  dda::paper::SymmetricStack st = dda::paper::symmetric_stack();
  // Symmetric at t = 0, but the impactor drifts sideways at 2.5 % of its
  // 2 m/s fall: the asymmetry must come from the motion, not the start.
  constexpr double kSideSpeed = 0.05;  // m/s
  st.scene.blocks.back().velocity.x = kSideSpeed;
  const repro::Claim c = symmetric_stack::row(symmetric_stack::run(st, nullptr, nullptr));
  CHECK_FALSE(c.pass);
  CHECK(c.control == "repro_controls: 4.2 symmetry: FAIL when the impactor drifts sideways");
}
