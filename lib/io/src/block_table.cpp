#include "dda/io/block_table.hpp"

#include <cmath>

namespace dda::io {

std::vector<std::string> block_table_header() {
  return {"time", "step", "block", "x", "y", "vx", "vy", "rot", "spin", "sxx", "syy", "sxy"};
}

namespace {

std::vector<CsvValue> row_of(const Simulation& sim, int i) {
  const Vec2 c = sim.centroid(i);
  const Vec6& v = sim.velocity(i);
  const Vec3& s = sim.stress(i);
  return {sim.time(), static_cast<long long>(sim.step_count()), i, c.x, c.y, v[0], v[1], sim.displacement(i)[2], v[2],
          s[0], s[1], s[2]};
}

}  // namespace

void block_table_rows(CsvFile& table, const Simulation& sim) {
  const int n = sim.scene_block_count();
  // Every value of this time first: a block's NaN writes none of its rows.
  for (int i = 0; i < n; ++i)
    for (const CsvValue& x : row_of(sim, i))
      if (!x.is_integer && !std::isfinite(x.number))
        throw NonFiniteValue(table.path() + ": t = " + format_number(sim.time()) + " s: block " + std::to_string(i) +
                             " has a non-finite value (not written)");
  for (int i = 0; i < n; ++i) table.row(row_of(sim, i));
}

}  // namespace dda::io
