// The long-format per-block table of `dda run` (DIR/blocks.csv): one row per
// scene block per output time, so that its width does not grow with the
// number of blocks (the wide time series, timeseries.csv, has six columns per
// tracked block). Columns (SCHEMA.md):
//   time, step, block, x, y, vx, vy, rot, spin, sxx, syy, sxy
#pragma once
#include <string>
#include <vector>

#include "dda/io/csv.hpp"
#include "dda/simulation.hpp"

namespace dda::io {

std::vector<std::string> block_table_header();

// Appends one row per scene block (boundary polygons excluded) of the
// current state. A non-finite value throws NonFiniteValue before any row of
// this time is written.
void block_table_rows(CsvFile& table, const Simulation& sim);

}  // namespace dda::io
