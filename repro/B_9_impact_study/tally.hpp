// The impact study's rows over many cells: the per-cell criteria counted
// ("n of N" with the failing cells named) and summarised (min, median, max).
// Private to the rows (rows.cpp, submodel_rows.cpp).
#pragma once
#include <algorithm>
#include <string>
#include <vector>

#include "repro/B_9_impact_study/impact_study.hpp"

namespace impact {

// Cells failing `ok`, as "n of N" and a list (the first `shown`, with a
// detail per cell).
struct Tally {
  int pass = 0, total = 0;
  std::string failing;
};
template <class Pred, class Detail>
Tally tally(const std::vector<CellResult>& cells, Pred ok, Detail detail, int shown = 8) {
  Tally t;
  int listed = 0;
  for (const CellResult& r : cells) {
    ++t.total;
    if (ok(r)) {
      ++t.pass;
      continue;
    }
    if (listed < shown) t.failing += (listed ? "; " : "") + cell_name(r.cell) + " " + detail(r);
    ++listed;
  }
  if (listed > shown) t.failing += "; and " + std::to_string(listed - shown) + " more";
  return t;
}
std::string count_text(const Tally& t);
std::string stopped_or(const CellResult& r, const std::string& text);

// Minimum, median and maximum of f over the cells that finished and pass `keep`.
template <class F, class Keep>
std::string stats(const std::vector<CellResult>& cells, F f, Keep keep) {
  std::vector<double> v;
  for (const CellResult& r : cells)
    if (r.ok && keep(r)) v.push_back(f(r));
  if (v.empty()) return "no cell";
  std::sort(v.begin(), v.end());
  return "min " + repro::format_short(v.front(), 3) + ", median " + repro::format_short(v[v.size() / 2], 3) +
         ", max " + repro::format_short(v.back(), 3) + " (" + std::to_string(v.size()) + " cells)";
}

// A check row of the study: passes when every cell passes (and there is
// one); `key` and the negative control's test case `test` set.
repro::Claim tally_row(const std::string& key, const std::string& claim, const std::string& paper,
                       const std::string& measured, const std::string& tol, const Tally& t, const char* test);

}  // namespace impact
