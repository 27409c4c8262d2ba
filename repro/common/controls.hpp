// Shared by the negative-control files (controls_*.cpp): a driver's row must
// be a check that names its control test, so that the report's count of
// controlled checks names real tests.
#pragma once
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "repro/common/claims.hpp"

namespace controls {

// The first row of `rows` that `match` picks must be a check naming `test`;
// `what` describes the row wanted, for the failure message.
template <class Match>
void row_names_test(const std::vector<repro::Claim>& rows, Match match, const char* test, const std::string& what) {
  for (const repro::Claim& c : rows)
    if (match(c)) {
      CHECK(c.kind == repro::Kind::kCheck);
      CHECK(c.control == repro::control_test(test));
      return;
    }
  FAIL("no row " << what);
}

// The same for the row with key `key`.
inline void key_names_test(const std::vector<repro::Claim>& rows, const std::string& key, const char* test) {
  row_names_test(rows, [&key](const repro::Claim& c) { return c.key == key; }, test, "with key " + key);
}

}  // namespace controls
