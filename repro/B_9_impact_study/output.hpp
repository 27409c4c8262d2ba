// The impact study's data file: cells.csv, one row per cell (outcome,
// penetration, separation, energy, loss vs Eq. 5, restitution, impulses and
// the law's prediction, the per-criterion verdicts).
#pragma once
#include <string>

#include "repro/B_9_impact_study/impact_study.hpp"
#include "repro/common/common.hpp"

namespace impact {

class CellsCsv {
 public:
  CellsCsv(const std::string& path, double dt);
  void row(const CellResult& r);
  void commit() { csv_.commit(); }

 private:
  repro::CsvWriter csv_;
};

}  // namespace impact
