// Output helpers for drivers that run a dda::Simulation (header only; the
// repro_common library itself does not depend on dda).
#pragma once
#include <string>
#include <vector>

#include "dda/simulation.hpp"
#include "repro/common/csv.hpp"

namespace repro {

// Columns "time,block,vertex,x,y" for snapshots of block polygons.
inline std::vector<std::string> snapshot_header() { return {"time", "block", "vertex", "x", "y"}; }

// Appends every scene block's polygon (boundary polygons too) at sim.time().
inline void write_snapshot(CsvWriter& csv, const dda::Simulation& sim) {
  for (int i = 0; i < sim.block_count(); ++i) {
    const dda::Polygon& p = sim.polygon(i);
    for (int k = 0; k < p.count; ++k)
      csv.row({sim.time(), static_cast<double>(i), static_cast<double>(k), p.vertex(k).x, p.vertex(k).y});
  }
}

}  // namespace repro
