#include "repro/common/claims.hpp"

#include <chrono>
#include <map>
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

Claim& explain_fail(Claim& c, Cause cause, std::string text) {
  if (c.kind == Kind::kCheck && !c.pass) {
    c.cause = cause;
    c.cause_text = std::move(text);
  }
  return c;
}

std::string kind_name(Kind kind) { return kind == Kind::kCheck ? "check" : "measurement"; }

std::string cause_name(Cause cause) {
  switch (cause) {
    case Cause::kPaperMethod: return "paper_method";
    case Cause::kMissingData: return "missing_data";
    case Cause::kImplementation: return "implementation";
    case Cause::kNone: break;
  }
  return "";
}

std::string claim_id(const Claim& c) { return c.section + ":" + (c.key.empty() ? slug(c.claim) : c.key); }

void write_claims(const std::string& path, const std::vector<Claim>& claims) {
  const double run_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - g_start).count();
  CsvWriter w(path, {"id", "section", "kind", "claim", "paper", "measured", "tolerance", "status", "cause",
                     "cause_text", "control", "run_time_s"});
  std::map<std::string, int> seen;
  for (const Claim& c : claims) {
    std::string id = claim_id(c);
    const int n = ++seen[id];
    if (n > 1) id += "-" + std::to_string(n);
    const bool check = c.kind == Kind::kCheck;
    w.row(std::vector<std::string>{id, c.section, kind_name(c.kind), c.claim, c.paper, c.measured, c.tolerance,
                                   check ? (c.pass ? "PASS" : "FAIL") : "",
                                   check && !c.pass ? cause_name(c.cause) : "",
                                   check && !c.pass ? c.cause_text : "", check ? c.control : "",
                                   format_short(run_time_s, 3)});
  }
  w.commit();
}

std::string claims_path(const std::string& out, const std::string& driver) {
  return out + "/claims/" + driver + ".csv";
}

}  // namespace repro
