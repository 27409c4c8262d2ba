#include "repro/common/claims.hpp"

#include <chrono>
#include <map>
#include <stdexcept>
#include <utility>

#include "repro/common/csv.hpp"

namespace repro {
namespace {

// Longest slug derived from a claim text: long enough to keep the rows of one
// driver apart, short enough for a readable id in expected_verdicts.csv.
constexpr std::size_t kMaxSlug = 72;

// Program start as seen by this library: dynamic initialisation of a
// namespace-scope object runs before main(), so write_claims() measures the
// driver's whole run (the report's "run time" column).
const std::chrono::steady_clock::time_point g_start = std::chrono::steady_clock::now();

std::string slug(const std::string& text) {
  std::string s;
  bool dash = false;
  for (char ch : text) {
    const unsigned char u = static_cast<unsigned char>(ch);
    const bool alnum = (u >= '0' && u <= '9') || (u >= 'a' && u <= 'z') || (u >= 'A' && u <= 'Z');
    if (alnum || ch == '.') {
      if (dash && !s.empty()) s += '-';
      s += static_cast<char>(u >= 'A' && u <= 'Z' ? u - 'A' + 'a' : u);
      dash = false;
    } else {
      dash = true;
    }
    if (s.size() >= kMaxSlug) break;
  }
  return s.substr(0, kMaxSlug);
}

}  // namespace

Claim measurement(std::string section, std::string claim, std::string paper, std::string measured,
                  std::string note) {
  Claim c{std::move(section), std::move(claim), std::move(paper), std::move(measured), std::move(note)};
  c.kind = Kind::kMeasurement;
  return c;
}

Cause root_cause(Root root) {
  switch (root) {
    case Root::kFrictionStartUp:
    case Root::kFrictionUpdate:
    case Root::kSegmentation:
    case Root::kThinBlock:
    case Root::kSmallGeometryStep:
    case Root::kStiffBounce:
    case Root::kCloneImpact:
    case Root::kNodalPeak:
    case Root::kMeshDispersion: return Cause::kPaperMethod;
    case Root::kSubModelReading: return Cause::kOurReading;
    case Root::kUnstatedSetup:
    case Root::kPrintedNumbers: return Cause::kMissingData;
    case Root::kCornerNormal:
    case Root::kUnexplained: return Cause::kImplementation;
    case Root::kNone: break;
  }
  return Cause::kNone;
}

Claim& add_claim(std::vector<Claim>& claims, Claim c, std::string control, Scope scope) {
  c.control = std::move(control);
  c.scope = scope;
  claims.push_back(std::move(c));
  return claims.back();
}

Claim& explain_fail(Claim& c, Root root, std::string text) {
  if (c.kind == Kind::kCheck && !c.pass) {
    c.root = root;
    c.cause = root_cause(root);
    c.cause_text = std::move(text);
  }
  return c;
}

void default_scope(std::vector<Claim>& claims, Scope scope) {
  for (Claim& c : claims)
    if (c.scope == Scope::kNone) c.scope = scope;
}

std::string kind_name(const Claim& c) {
  if (c.kind == Kind::kMeasurement) return "measurement";
  return c.fitted ? "fitted" : "check";
}

std::string cause_name(Cause cause) {
  switch (cause) {
    case Cause::kPaperMethod: return "paper_method";
    case Cause::kMissingData: return "missing_data";
    case Cause::kOurReading: return "our_reading";
    case Cause::kImplementation: return "implementation";
    case Cause::kNone: break;
  }
  return "";
}

std::string scope_name(Scope scope) {
  switch (scope) {
    case Scope::kPaper: return "paper";
    case Scope::kExtension: return "extension";
    case Scope::kOption: return "option";
    case Scope::kSuite: return "suite";
    case Scope::kNone: break;
  }
  return "";
}

std::string root_name(Root root) {
  switch (root) {
    case Root::kFrictionStartUp: return "friction_start_up";
    case Root::kFrictionUpdate: return "friction_update";
    case Root::kSegmentation: return "segmentation";
    case Root::kThinBlock: return "thin_block";
    case Root::kSmallGeometryStep: return "small_geometry_step";
    case Root::kStiffBounce: return "stiff_bounce";
    case Root::kCloneImpact: return "clone_impact";
    case Root::kNodalPeak: return "nodal_peak";
    case Root::kMeshDispersion: return "mesh_dispersion";
    case Root::kSubModelReading: return "sub_model_reading";
    case Root::kUnstatedSetup: return "unstated_setup";
    case Root::kPrintedNumbers: return "printed_numbers";
    case Root::kCornerNormal: return "corner_normal";
    case Root::kUnexplained: return "unexplained";
    case Root::kNone: break;
  }
  return "";
}

std::string claim_id(const Claim& c) { return c.section + ":" + (c.key.empty() ? slug(c.claim) : c.key); }

void write_claims(const std::string& path, const std::vector<Claim>& claims) {
  const double run_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - g_start).count();
  std::map<std::string, int> seen;
  std::vector<std::string> ids;
  for (const Claim& c : claims) {
    std::string id = claim_id(c);
    const int n = ++seen[id];
    if (n > 1) id += "-" + std::to_string(n);
    if (c.scope == Scope::kNone)
      throw std::invalid_argument("claims " + path + ": row " + id + " has no scope (paper, extension, option, suite)");
    ids.push_back(id);
  }
  CsvWriter w(path, {"id", "section", "scope", "kind", "claim", "paper", "measured", "tolerance", "status", "cause",
                     "root_cause", "cause_text", "control", "run_time_s"});
  for (std::size_t i = 0; i < claims.size(); ++i) {
    const Claim& c = claims[i];
    const bool check = c.kind == Kind::kCheck;
    const bool failed = check && !c.pass;
    w.row(std::vector<std::string>{ids[i], c.section, scope_name(c.scope), kind_name(c), c.claim, c.paper, c.measured,
                                   c.tolerance, check ? (c.pass ? "PASS" : "FAIL") : "",
                                   failed ? cause_name(c.cause) : "", failed ? root_name(c.root) : "",
                                   failed ? c.cause_text : "", check ? c.control : "", format_short(run_time_s, 3)});
  }
  w.commit();
}

std::string claims_path(const std::string& out, const std::string& driver) {
  return out + "/claims/" + driver + ".csv";
}

}  // namespace repro
