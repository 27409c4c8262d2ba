#include "repro/common/claims.hpp"

#include "repro/common/csv.hpp"

namespace repro {

void write_claims(const std::string& path, const std::vector<Claim>& claims) {
  CsvWriter w(path, {"section", "claim", "paper", "measured", "tolerance", "status"});
  for (const Claim& c : claims)
    w.row(std::vector<std::string>{c.section, c.claim, c.paper, c.measured, c.tolerance, c.pass ? "PASS" : "FAIL"});
  w.commit();
}

std::string claims_path(const std::string& out, const std::string& driver) {
  return out + "/claims/" + driver + ".csv";
}

}  // namespace repro
