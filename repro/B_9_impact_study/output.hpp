// The impact study's data file: cells.csv, one row per cell (outcome,
// penetration, separation, energy, loss vs Eq. 5, restitution, impulses and
// the law's prediction, the per-criterion verdicts).
#pragma once
#include <string>

#include "repro/B_9_impact_study/impact_study.hpp"
#include "repro/common/common.hpp"
#include "repro/common/table.hpp"

namespace impact {

class CellsCsv {
 public:
  CellsCsv(const std::string& path, double dt);
  void row(const CellResult& r) { table_.row(r); }
  void commit() { table_.commit(); }

 private:
  repro::TableWriter<CellResult> table_;
};

}  // namespace impact
