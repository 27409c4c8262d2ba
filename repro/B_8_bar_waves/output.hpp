// Two elastic bars head on: the data files under <out>/data/B_8_bar_waves/.
#pragma once
#include <string>

#include "repro/B_8_bar_waves/bar_waves.hpp"

namespace bars {

// runs.csv (one row per run, with the wall time; a stopped run has its error
// and no values) and traces.csv (one run of each model) into `dir`.
void write_runs(const std::string& dir, const Setup& s, const Study& study);

}  // namespace bars
