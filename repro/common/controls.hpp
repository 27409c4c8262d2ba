// Shared helpers of the negative-control tests (each driver folder's
// controls*.cpp, built into repro_controls_tests): finding a driver's row or
// case by name, checking that a row is a check naming its control test (so
// that the report's count of controlled checks names real tests), and the
// scene edits several controls make. Includes no driver header.
#pragma once
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "repro/common/claims.hpp"

namespace controls {

// The first element of `items` that `match` picks; fails the test if there
// is none (`what` names the element wanted).
template <class Items, class Match>
auto find(const Items& items, Match match, const std::string& what) -> typename Items::value_type {
  for (const auto& x : items)
    if (match(x)) return x;
  FAIL("no " << what);
  return {};
}

// The element of `items` whose member `name` is `name`.
template <class Items>
auto named(const Items& items, const std::string& name, const std::string& what) -> typename Items::value_type {
  return find(items, [&name](const auto& x) { return x.name == name; }, what + " " + name);
}

// The row with key `key`; fails the test if there is none or it is not a check.
inline const repro::Claim& row(const std::vector<repro::Claim>& rows, const std::string& key) {
  for (const repro::Claim& c : rows)
    if (c.key == key) {
      REQUIRE(c.kind == repro::Kind::kCheck);
      return c;
    }
  FAIL("no row with key " << key);
  return rows.front();
}

// The control named in the row must be this test case.
inline void names_control(const repro::Claim& c, const std::string& test) {
  CHECK(c.control == repro::control_test(test));
}

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

// Block 1 (block j of the two-body scenes) of a DDA or CDEM scene made
// `factor` times as dense, through a material of its own.
template <class SceneT>
void make_j_denser(SceneT& s, double factor) {
  s.materials.push_back(s.materials[static_cast<std::size_t>(s.blocks[1].material)]);
  s.materials.back().density *= factor;
  s.blocks[1].material = static_cast<int>(s.materials.size()) - 1;
}

}  // namespace controls
