// Output helpers for drivers that run a dda::Simulation (header only; the
// repro_common library itself does not depend on dda).
#pragma once
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "dda/simulation.hpp"
#include "repro/common/csv.hpp"
#include "repro/common/table.hpp"

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

// One vertex of one block's polygon at a moment: a row of a snapshot table
// (columns "time,block,vertex,x,y", snapshot_columns()).
struct VertexRow {
  double time;
  int block, vertex;
  dda::Vec2 p;
};
inline std::vector<Column<VertexRow>> snapshot_columns() {
  return {{"time", [](const VertexRow& v) { return v.time; }},
          {"block", [](const VertexRow& v) { return v.block; }},
          {"vertex", [](const VertexRow& v) { return v.vertex; }},
          {"x", [](const VertexRow& v) { return v.p.x; }},
          {"y", [](const VertexRow& v) { return v.p.y; }}};
}

// Every scene block's polygon (boundary polygons too) at sim.time(), as rows.
inline std::vector<VertexRow> snapshot_rows(const dda::Simulation& sim) {
  std::vector<VertexRow> rows;
  for (int i = 0; i < sim.block_count(); ++i) {
    const dda::Polygon& p = sim.polygon(i);
    for (int k = 0; k < p.count; ++k) rows.push_back({sim.time(), i, k, p.vertex(k)});
  }
  return rows;
}

// Appends snapshot_rows(sim) to a snapshot table.
inline void write_snapshot(TableWriter<VertexRow>& table, const dda::Simulation& sim) {
  table.rows(snapshot_rows(sim));
}

// When a driver writes output during a run of `steps` steps: at every
// multiple of each period, at each listed step and at the last step. The
// steps between two outputs run as one Simulation::advance (one thread team).
class OutputSchedule {
 public:
  OutputSchedule(long long steps, std::vector<long long> periods, std::vector<long long> listed = {})
      : steps_(steps), periods_(std::move(periods)), listed_(std::move(listed)) {}
  // The first output step after s (at most the last step).
  long long next(long long s) const {
    long long n = steps_;
    for (long long p : periods_) n = std::min(n, (s / p + 1) * p);
    for (long long v : listed_)
      if (v > s) n = std::min(n, v);
    return n;
  }
  // Whether step s is an output of the given period (or the last step).
  bool at(long long s, long long period) const { return s % period == 0 || s == steps_; }
  bool listed(long long s) const { return std::find(listed_.begin(), listed_.end(), s) != listed_.end(); }

 private:
  long long steps_;
  std::vector<long long> periods_, listed_;
};

}  // namespace repro
