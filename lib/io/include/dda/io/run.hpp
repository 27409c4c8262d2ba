// Runs a scene file to its duration and writes the run's output:
//   <out>/timeseries.csv  one row at t = 0, every `output.every` steps, and at the end
//   <out>/snapshots.csv   the vertices of every polygon at each snapshot time
//   <out>/blocks.csv      (output.block_table) one row per block at each time-series row
//   <out>/vtk/            (output.vtk) ParaView series blocks.pvd and contacts.pvd
//   <out>/run.json        status, counts, wall time, block names and masses
// Columns are documented in lib/io/SCHEMA.md. Every file is written
// through "<file>.tmp" and renamed into place when complete. A run stopped by
// dda::SimulationError (or a non-finite output value) still commits the rows
// written up to that point, and run.json says "simulation_error". An
// interrupted run commits no CSV file and no run.json; the ParaView frames
// taken before the interrupt stay, with their .pvd collections.
#pragma once
#include <csignal>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "dda/io/csv.hpp"
#include "dda/io/scene_file.hpp"
#include "dda/simulation.hpp"

namespace dda::io {

struct RunOptions {
  std::string out_dir;               // created if missing
  std::string scene_label;           // recorded in run.json
  std::ostream* progress = nullptr;  // progress lines (at most ~1 per second after the first second); null: none
  const volatile std::sig_atomic_t* interrupt = nullptr;  // polled every step; non-zero stops the run
};

enum class RunStatus { kCompleted, kSimulationError, kInterrupted };

struct RunResult {
  RunStatus status = RunStatus::kCompleted;
  std::string message;  // the SimulationError text, if any
  std::int64_t steps = 0;
  double time = 0.0;          // simulated time reached, s
  double last_row_time = 0.0; // time of the last time-series row written, s
  double wall_seconds = 0.0;
  std::size_t timeseries_rows = 0, snapshot_rows = 0;
  std::size_t block_table_rows = 0;  // DIR/blocks.csv (output.block_table)
  std::size_t vtk_frames = 0;        // frames of each ParaView series (output.vtk)
};

// Column names of the time series for `tracked` scene blocks (see SCHEMA.md).
std::vector<std::string> timeseries_header(const std::vector<int>& tracked);
// The time-series row of the current state, matching timeseries_header.
std::vector<CsvValue> timeseries_row(const Simulation& sim, const std::vector<int>& tracked);

// Throws OutputError if the output cannot be written; SceneFileError (before
// anything is written) if the run would take more than file.max_steps steps
// (check_step_count with the simulation's dt); dda::SceneError cannot happen
// for a SceneFile from parse_scene.
RunResult run_scene(const SceneFile& file, const RunOptions& options);

}  // namespace dda::io
