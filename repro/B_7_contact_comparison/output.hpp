// Paper A against Paper B on the same collisions: the data files under
// <out>/data/B_7_contact_comparison/.
#pragma once
#include <map>
#include <string>
#include <vector>

#include "repro/B_7_contact_comparison/contact_comparison.hpp"

namespace compare {

// sweep.csv, history.csv and energy_history.csv into `dir`.
void write_data(const std::string& dir, const std::vector<Result>& results,
                const std::map<std::string, History>& histories);

}  // namespace compare
