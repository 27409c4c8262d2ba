// Negative controls of the Sect. 5.1 bouncing-block rows: the H comparison
// with the H rules swapped and the sane-run criterion with mass damping
// must both FAIL.
#include <catch2/catch.hpp>

#include <string>

#include "dda/scene.hpp"
#include "repro/5_1_bouncing_block/bouncing_block.hpp"
#include "repro/common/claims.hpp"

TEST_CASE("5.1 H comparison: FAIL with the H rules swapped", "[controls][5.1]") {
  // The wrong H rule: the runs judged as 'unified H' use the inscribed radius
  // and the other way round.
  using dda::HRule;
  const double diff_inscribed = bouncing_block::max_difference(bouncing_block::run(0.1, HRule::kInscribedRadius, "c1"),
                                                               bouncing_block::run(1.0, HRule::kInscribedRadius, "c2"));
  const double diff_unified = bouncing_block::max_difference(bouncing_block::run(0.1, HRule::kMinMaxEdge, "c1"),
                                                             bouncing_block::run(1.0, HRule::kMinMaxEdge, "c2"));
  const repro::Claim swapped = bouncing_block::comparison_row(diff_inscribed, diff_unified);
  CHECK_FALSE(swapped.pass);
  CHECK(swapped.control == "repro_controls: 5.1 H comparison: FAIL with the H rules swapped");
}

TEST_CASE("5.1 sane run: FAIL with mass damping", "[controls][5.1]") {
  // 1/s: A loses energy in its fall and bounce, so the undamped run's energy
  // criterion must fail (the criterion also checks flip-through and symmetry).
  const bouncing_block::Run r = bouncing_block::run(0.1, dda::HRule::kMinMaxEdge, "damped",
                                                    [](dda::Scene& s) { s.damping.mass = 1.0; });
  const repro::Claim c = bouncing_block::sane_row(r);
  CHECK_FALSE(c.pass);
  CHECK(c.control == std::string("repro_controls: ") + bouncing_block::kControlSane);
}
