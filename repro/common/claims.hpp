// Claims: one row per statement of a paper, with what the driver measured.
// Every driver writes <out>/claims/<driver>.csv; figures/report.py merges them
// into report.md and claims.json, repro/common/verdicts.py compares the
// verdicts with repro/expected_verdicts.csv (make verdicts).
//
// Two kinds of row (issue 21, item 1):
//  - a *check* has a criterion computed from the run (`pass`) that can come
//    out FAIL; a failing check carries a Cause and a text (item 4);
//  - a *measurement* reports a number with no verdict; it is never shown or
//    counted as PASS.
// A check whose criterion has a negative control in `make test` (a ctest that
// applies the same criterion function to a deliberately wrong configuration
// and asserts FAIL, item 2) names that test in `control`; the report lists a
// check without one among the measurements.
#pragma once
#include <string>
#include <vector>

namespace repro {

enum class Kind { kCheck, kMeasurement };

// Why a check fails (issue 21, item 4).
enum class Cause {
  kNone,            // not given: a FAIL without a cause is reported as a problem
  kPaperMethod,     // the paper's method as published (an option beyond it passes, or an analytic argument)
  kMissingData,     // data missing from the paper (reconstructed geometry or parameters)
  kImplementation,  // our implementation: a bug, with an issue note
};

struct Claim {
  std::string section;    // paper section, e.g. "3.2.2"
  std::string claim;      // the statement checked, in words (no measured numbers: it names the row)
  std::string paper;      // what the paper says or shows (value or quote)
  std::string measured;   // what this run measured (computed, never typed in)
  std::string tolerance;  // the acceptance criterion, in words/numbers
  bool pass = false;      // computed by the driver from `measured` (checks only)
  Kind kind = Kind::kCheck;
  std::string key{};       // short stable key of the row within its section; empty: derived from `claim`
  Cause cause = Cause::kNone;  // for a failing check: why (see Cause)
  std::string cause_text{};    // for a failing check: the argument or the issue note
  std::string control{};       // name of the ctest that is this check's negative control, if any
};

// The `control` of a check whose negative control is the repro_controls test
// case `test_case` (its exact name).
inline std::string control_test(const std::string& test_case) { return "repro_controls: " + test_case; }

// A measurement row: a number with no verdict; `note` says what it shows.
Claim measurement(std::string section, std::string claim, std::string paper, std::string measured,
                  std::string note);

// Sets the cause of a failing check (no-op when the check passes, so that the
// call can stay in the driver whatever the verdict is).
Claim& explain_fail(Claim& c, Cause cause, std::string text);

// "check" / "measurement"; "" / "paper_method" / "missing_data" / "implementation".
std::string kind_name(Kind kind);
std::string cause_name(Cause cause);

// The row id: "<section>:<key>" with the key, or a slug of the claim text
// (lower-case letters, digits and '-', at most kMaxSlug characters) when the
// key is empty.
std::string claim_id(const Claim& c);

// Writes CSV "id,section,kind,claim,paper,measured,tolerance,status,cause,
// cause_text,control,run_time_s": status PASS or FAIL for a check, empty for a
// measurement; run_time_s is the driver's wall time from program start to this
// call (the report's "run time"). Ids are made unique within the file by a
// suffix "-2", "-3", ... in row order. Written atomically (tmp + rename).
void write_claims(const std::string& path, const std::vector<Claim>& claims);

// "<out>/claims/<driver>.csv"
std::string claims_path(const std::string& out, const std::string& driver);

}  // namespace repro
