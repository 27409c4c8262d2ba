// Shared by the B-6 negative controls (controls.cpp, controls_energy.cpp):
// the option sets of the runs they compare, and a row of prisms::rows that
// must be a check naming its control test.
#pragma once
#include <catch2/catch.hpp>

#include <string>

#include "dda/cdem/scenes.hpp"
#include "repro/B_6_two_prisms/two_prisms.hpp"
#include "repro/common/claims.hpp"
#include "repro/common/controls.hpp"

namespace controls_b6 {

// The row `claim` of prisms::rows(r, coarse) must be a check naming `test`.
inline void names_test(const prisms::Result& r, const prisms::Result& coarse, const std::string& claim,
                       const char* test) {
  controls::row_names_test(prisms::rows(r, coarse), [&claim](const repro::Claim& c) { return c.claim == claim; },
                           test, "B-6 '" + claim + "'");
}

// The default flipped to the sub-model: the row `claim` of
// prisms::flipped_rows(sub, inplace, coarse) and the in-place option's row
// beside it (the sub-model's row fails) both name `test`.
inline void names_test_both(const prisms::Result& sub, const prisms::Result& inplace, const prisms::Result& coarse,
                            const std::string& claim, const char* test) {
  int found = 0;
  for (const repro::Claim& c : prisms::flipped_rows(sub, inplace, coarse))
    if (c.claim == claim || c.claim == prisms::kInPlacePrefix + claim) {
      CHECK(c.kind == repro::Kind::kCheck);
      CHECK(c.control == repro::control_test(test));
      ++found;
    }
  CHECK(found == 2);
}
// The in-place option (Sect. 5 as an in-place refinement).
inline dda::cdem::CdemOptions in_place() {
  dda::cdem::CdemOptions o;
  o.subdivision_mode = dda::cdem::SubdivisionMode::kInPlace;
  return o;
}
// No subdivision: the coarse run beside the paper's.
inline dda::cdem::CdemOptions no_subdivision() {
  dda::cdem::CdemOptions o;
  o.subdivision = false;
  return o;
}

}  // namespace controls_b6
