// Claims: one row per checkable statement of a paper, with what the driver
// measured and whether it is within tolerance. Every driver writes
// <out>/claims/<driver>.csv; figures/report.py merges them into report.md.
#pragma once
#include <string>
#include <vector>

namespace repro {

struct Claim {
  std::string section;    // paper section, e.g. "3.2.2"
  std::string claim;      // the statement checked, in words
  std::string paper;      // what the paper says or shows (value or quote)
  std::string measured;   // what this run measured (computed, never typed in)
  std::string tolerance;  // the acceptance criterion, in words/numbers
  bool pass = false;      // computed by the driver from `measured`
};

// Writes CSV "section,claim,paper,measured,tolerance,status" (status PASS or
// FAIL), fields quoted as needed, atomically (tmp + rename).
void write_claims(const std::string& path, const std::vector<Claim>& claims);

// "<out>/claims/<driver>.csv"
std::string claims_path(const std::string& out, const std::string& driver);

}  // namespace repro
