// Paper A Sects. 3.1.2, 3.2.1 and 3.2.4: the overlap criterion of the
// entrance block, the normal force as the negative gradient of the contact
// energy, and the zero moment about the loading point pg (Eq. 20), checked
// on 4000 random convex pairs against independent computations (see
// contact_statements.hpp).
//
// Expected: the entrance-block criterion agrees with a separating-axis test
// on every pair outside the touching band; the force of the exact
// integration is the energy gradient to the central difference's error
// (measured 2e-8); the paper's segmentation misses kinks of the potential
// on some pairs (Sect. 3.2.3 is exact only if the bisector crossings are
// all the kinks; 5.5 measures the effect on the paper's scenes), so its row
// is expected to FAIL with the exact integration passing beside it; the
// same for the moment about pg (exact: measured 2e-8).
//
// Output: data/contact_statements/gradient.csv (per pair: overlap depth and
// the force's error under both integrations), claims/3_1_contact_statements.csv.
#include <cstdint>
#include <string>
#include <vector>

#include "repro/3_1_contact_statements/contact_statements.hpp"
#include "repro/common/common.hpp"

using contact_statements::GradientSample;
using repro::add_claim;
using repro::explain_fail;
using repro::Root;
using repro::Scope;

// The driver: its name in errors, its progress lines' prefix and its usage line.
const repro::DriverInfo kInfo = {
    "contact_statements", "3.1-3.2 contact statements",
    "Paper A Sects. 3.1.2 and 3.2.1: the entrance-block criterion and the force as the energy gradient, on "
    "random convex pairs."};

namespace {

constexpr int kPairs = 4000;
constexpr std::uint64_t kSeed = 20261125;
const char* const kControlGradient =
    "repro_controls: 3.2.1 energy gradient: FAIL when the force leaves out TP's potential";
const char* const kControlMoment = "repro_controls: 3.2.4 moment about pg: FAIL about the IP centroid";

// The gradient and moment rows, each under the exact integration (beyond the
// paper) and the paper's segmentation; the force errors per pair to
// `exact` and `paper`.
void force_rows(const std::vector<contact_statements::Pair>& pairs, std::vector<repro::Claim>& claims,
                std::vector<GradientSample>& exact, std::vector<GradientSample>& paper) {
  using contact_statements::Variant;
  using dda::Integration;
  explain_fail(add_claim(claims,
                         contact_statements::gradient_row(pairs, Integration::kExactEnvelope, Variant::kAsPublished,
                                                          &exact),
                         kControlGradient, Scope::kOption),
               Root::kUnexplained, "the exact integration should be the energy's gradient; not explained");
  explain_fail(add_claim(claims,
                         contact_statements::gradient_row(pairs, Integration::kPaperBisector, Variant::kAsPublished,
                                                          &paper),
                         kControlGradient, Scope::kPaper),
               Root::kSegmentation,
               "the segmentation of Sect. 3.2.3 (IP edges split at the bisector crossings and midpoints, "
               "Eq. 16's trapezoid rule) is exact only where those are all the kinks of phi along an edge; "
               "on the others the force is off the energy's gradient; the exact integration beyond the paper "
               "(row above) passes");
  explain_fail(add_claim(claims, contact_statements::moment_row(pairs, Integration::kExactEnvelope), kControlMoment,
                         Scope::kOption),
               Root::kUnexplained, "with the exact force the line through pg should carry no moment; not explained");
  explain_fail(add_claim(claims, contact_statements::moment_row(pairs, Integration::kPaperBisector), kControlMoment,
                         Scope::kPaper),
               Root::kSegmentation,
               "the segment forces of Sect. 3.2.3 are off the energy's derivatives (the gradient row "
               "above), so the moment they give, and pg with it, is off too; the exact integration beyond "
               "the paper (row above) passes");
}

// gradient.csv: per pair, the overlap and the force's error under both
// integrations.
void write_gradient(const std::string& path, const std::vector<GradientSample>& exact,
                    const std::vector<GradientSample>& paper) {
  std::vector<std::size_t> pairs(exact.size());
  for (std::size_t k = 0; k < pairs.size(); ++k) pairs[k] = k;
  repro::write_table<std::size_t>(path,
                                  {{"pair", [](std::size_t k) { return k; }},
                                   {"ip_area", [&](std::size_t k) { return exact[k].ip_area; }},
                                   {"depth", [&](std::size_t k) { return exact[k].depth; }},
                                   {"error_exact", [&](std::size_t k) { return exact[k].error; }},
                                   {"error_paper", [&](std::size_t k) { return paper[k].error; }}},
                                  pairs,
                                  {"Paper A Eqs. 10-11: |f + grad E| / |grad E| per random overlapping convex pair; "
                                   "depth: the intersection polygon's inscribed diameter, m"});
}

// The run: what main's driver_main calls once the command line is checked.
int reproduce(const repro::Driver& d) {
  const std::vector<contact_statements::Pair> pairs = contact_statements::random_pairs(kPairs, kSeed);
  std::vector<repro::Claim> claims;
  add_claim(claims, contact_statements::entrance_row(pairs),
            "repro_controls: 3.1.2 entrance block: FAIL when A is not reflected", Scope::kPaper);
  std::vector<GradientSample> exact, paper;
  force_rows(pairs, claims, exact, paper);
  write_gradient(d.out + "/data/contact_statements/gradient.csv", exact, paper);
  for (const repro::Claim& c : claims)
    d.progress(c.claim + ": " + (c.pass ? "PASS" : "FAIL") + " (" + c.measured + ")");
  repro::write_claims(repro::claims_path(d.out, "3_1_contact_statements"), claims);
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return repro::driver_main(argc, argv, kInfo, {}, reproduce); }
