// Negative controls of the Sects. 3.1.2 and 3.2.1 contact-statement rows:
// the entrance block, the energy gradient and the moment about pg, each on
// random pairs with the driver's own criterion, which must PASS on the
// statement as written and FAIL on a deliberately wrong variant.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "repro/3_1_contact_statements/contact_statements.hpp"
#include "repro/common/claims.hpp"

namespace {
namespace cs = contact_statements;
constexpr dda::Integration kExact = dda::Integration::kExactEnvelope;

// A row as published must PASS, the same row on the wrong variant FAIL,
// under the key `key`.
void fails_on_variant(const repro::Claim& published, const repro::Claim& wrong, const std::string& key) {
  CHECK(published.pass);
  CHECK_FALSE(wrong.pass);
  CHECK(wrong.key == key);
}
}  // namespace

TEST_CASE("3.1.2 entrance block: FAIL when A is not reflected", "[controls][3.1]") {
  // E built as B + A + a0: a0 inside it says nothing about the overlap.
  const std::vector<cs::Pair> pairs = cs::random_pairs(1500, 1);
  fails_on_variant(cs::entrance_row(pairs), cs::entrance_row(pairs, cs::Variant::kEntranceWithoutReflection),
                   cs::kKeyEntrance);
}

TEST_CASE("3.2.1 energy gradient: FAIL when the force leaves out TP's potential", "[controls][3.2]") {
  // The force integrates phi_CP alone (TP's kn / H = 0 in the force, not in
  // the energy): no longer the gradient of the energy.
  const std::vector<cs::Pair> pairs = cs::random_pairs(1000, 2);
  fails_on_variant(cs::gradient_row(pairs, kExact),
                   cs::gradient_row(pairs, kExact, cs::Variant::kForceWithoutTargetPotential), cs::kKeyGradientExact);
}

TEST_CASE("3.2.4 moment about pg: FAIL about the IP centroid", "[controls][3.2]") {
  // The same energy derivative taken about the IP centroid: the force's
  // line misses it, so the moment there is not zero.
  const std::vector<cs::Pair> pairs = cs::random_pairs(1000, 3);
  fails_on_variant(cs::moment_row(pairs, kExact), cs::moment_row(pairs, kExact, cs::Variant::kMomentAboutCentroid),
                   cs::kKeyMomentExact);
}
