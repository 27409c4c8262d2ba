// Claims: one row per statement, with what the driver measured. Every driver
// writes <out>/claims/<driver>.csv; figures/report.py merges them into
// report.md and claims.json, repro/common/verdicts.py compares the verdicts
// with repro/expected_verdicts.csv (make verdicts).
//
// Every row has a scope (what it is a test of):
//  - paper: a statement the paper makes, quoted with where it stands;
//  - extension: a test beyond the paper (its geometry, speeds or theory);
//  - option: our option beside a row of the paper's method;
//  - suite: the suite's own guards, integrator orders, work-precision and
//    stability maps.
// write_claims refuses a row without one.
//
// Three kinds of row:
//  - a check has a criterion computed from the run (`pass`) that can come
//    out PASS and FAIL on physically possible runs; a failing check names a
//    root cause (Root, which fixes its Cause) and a text;
//  - a fitted check (`fitted`): a check on a scene whose geometry or
//    parameter was chosen to match the number it checks; its verdict is
//    shown, never counted as reproduced;
//  - a measurement reports a number with no verdict; it is never shown or
//    counted as PASS.
// A check whose criterion has a negative control in `make test` (a ctest that
// applies the same criterion function to a deliberately wrong configuration
// and asserts FAIL) names that test in `control`; the report lists a check
// without one among the measurements.
#pragma once
#include <string>
#include <vector>

namespace repro {

enum class Kind { kCheck, kMeasurement };

enum class Scope { kNone, kPaper, kExtension, kOption, kSuite };

// The category of a failing check's cause.
enum class Cause {
  kNone,            // not given: a FAIL without a cause is reported as a problem
  kPaperMethod,     // the paper's method as published (an option beyond it passes, or an analytic argument)
  kMissingData,     // data the paper does not give (reconstructed geometry or set-up) or gives inconsistently
  kOurReading,      // our reading of a section the paper leaves incomplete (another reading is an option)
  kImplementation,  // our implementation: a defect not yet explained
};

// Why a check fails: one root cause per failing row; the report explains each
// once (figures/report.py ROOTS, by root_name) with the rows it explains.
enum class Root {
  kNone,
  kFrictionStartUp,    // paper method: the finite tangential spring loaded suddenly at the start
  kFrictionUpdate,     // paper method: Eq. 26 restarts a sliding pair's spring from zero shear (creep)
  kSegmentation,       // paper method: the segmentation of Sect. 3.2.3 is not the energy's gradient
  kThinBlock,          // paper method: a thin block is pierced under the paper's kn and dt
  kSmallGeometryStep,  // paper method: the paper's fixed dt above the critical step of smaller geometry
  kStiffBounce,        // paper method: a stiff penalty bounce amplifies a round-off tilt
  kCloneImpact,        // paper method: the clone's inelastic impact takes the whole tangential velocity
  kNodalPeak,          // paper method: a nodal value of the paper's coarse mesh read as j's velocity
  kMeshDispersion,     // paper method: a coarse CST mesh disperses the elastic wave
  kSubModelReading,    // our reading: Paper B Sect. 5's sub-model, steps (1)-(5)
  kUnstatedSetup,      // missing data: geometry or set-up the paper does not give
  kPrintedNumbers,     // missing data: the paper's own printed numbers disagree
  kCornerNormal,       // implementation: our contact normal at a corner-to-corner touch
  kUnexplained,        // implementation: not explained yet
};
// The category of a root cause.
Cause root_cause(Root root);

struct Claim {
  std::string section;    // paper section, e.g. "3.2.2"
  std::string claim;      // the statement checked, in words (no measured numbers: it names the row)
  std::string paper;      // what the paper says or shows (value or quote)
  std::string measured;   // what this run measured (computed, never typed in)
  std::string tolerance;  // the acceptance criterion, in words/numbers
  bool pass = false;      // computed by the driver from `measured` (checks only)
  Kind kind = Kind::kCheck;
  std::string key{};       // short stable key of the row within its section; empty: derived from `claim`
  Cause cause = Cause::kNone;  // for a failing check: the category of its root cause
  std::string cause_text{};    // for a failing check: the argument, with the run's numbers
  std::string control{};       // name of the ctest that is this check's negative control, if any
  Root root = Root::kNone;     // for a failing check: the root cause (sets `cause`)
  Scope scope = Scope::kNone;  // every row: what it is a test of (write_claims refuses kNone)
  bool fitted = false;         // a check on a scene fitted to the number it checks (kind "fitted")
};

// The `control` of a check whose negative control is the repro_controls test
// case `test_case` (its exact name).
inline std::string control_test(const std::string& test_case) { return "repro_controls: " + test_case; }

// A measurement row: a number with no verdict; `note` says what it shows.
Claim measurement(std::string section, std::string claim, std::string paper, std::string measured,
                  std::string note);

// Sets the root cause (and with it the cause) and the text of a failing
// check (no-op when the check passes, so that the call can stay in the
// driver whatever the verdict is).
Claim& explain_fail(Claim& c, Root root, std::string text);

// Appends `c` to `claims` with its negative control (`control`, as in
// Claim::control) and its scope; returns the appended row, so that
// explain_fail can follow: explain_fail(add_claim(claims, c, ctl, scope), ...).
Claim& add_claim(std::vector<Claim>& claims, Claim c, std::string control, Scope scope);

// Sets the scope of every row of `claims` that has none (a driver whose rows
// are all of one scope says so once).
void default_scope(std::vector<Claim>& claims, Scope scope);

// "check" / "fitted" / "measurement"; "" / "paper_method" / "missing_data" /
// "our_reading" / "implementation"; "paper" / "extension" / "option" /
// "suite"; the root cause's key (e.g. "friction_start_up").
std::string kind_name(const Claim& c);
std::string cause_name(Cause cause);
std::string scope_name(Scope scope);
std::string root_name(Root root);

// The row id: "<section>:<key>" with the key, or a slug of the claim text
// (lower-case letters, digits and '-', at most kMaxSlug characters) when the
// key is empty.
std::string claim_id(const Claim& c);

// Writes CSV "id,section,scope,kind,claim,paper,measured,tolerance,status,
// cause,root_cause,cause_text,control,run_time_s": status PASS or FAIL for a
// check, empty for a measurement; run_time_s is the driver's wall time from
// program start to this call (the report's "run time"). Ids are made unique
// within the file by a suffix "-2", "-3", ... in row order. Throws
// std::invalid_argument naming the row if a row has no scope (a failing
// check without a root cause is written, and flagged by verdicts.py and the
// report). Written atomically (tmp + rename).
void write_claims(const std::string& path, const std::vector<Claim>& claims);

// "<out>/claims/<driver>.csv"
std::string claims_path(const std::string& out, const std::string& driver);

}  // namespace repro
