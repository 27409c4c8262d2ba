// Runs a scene file to its duration, with either contact model, and writes
// the run's output:
//   <out>/timeseries.csv  one row at t = 0, every `output.every` steps, and at the end
//   <out>/snapshots.csv   the vertices of every outline at each snapshot time
//   <out>/blocks.csv      (output.block_table) one row per block at each time-series row
//   <out>/vtk/            (output.vtk) ParaView series: penalty model blocks.pvd,
//                         cdem model elements.pvd; both contacts.pvd
//   <out>/run.json        status, counts, wall time, block names and masses
//   <out>/checkpoint.dda  while a run can be resumed (either model; checkpoint.hpp)
// Columns are documented in lib/io/SCHEMA.md. Every file is written through
// "<file>.tmp" and renamed into place: the CSV files and run.json when the
// run ends, completed, stopped by dda::SimulationError (or a non-finite
// output value: the rows written up to that point, run.json says
// "simulation_error"), or interrupted (the rows so far, a checkpoint,
// run.json says "interrupted"); each ParaView frame as it is taken, the
// .pvd collections when the run ends. A run resumed from its checkpoint ends
// with the same files, byte for byte, as one never stopped (run.json's
// wall-clock fields aside).
#pragma once
#include <csignal>
#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

#include "dda/io/checkpoint.hpp"
#include "dda/io/csv.hpp"
#include "dda/io/scene_file.hpp"
#include "dda/stepper.hpp"

namespace dda::io {

struct RunOptions {
  std::string out_dir;               // created if missing
  std::string scene_label;           // recorded in run.json
  std::ostream* progress = nullptr;  // progress lines (at most ~1 per second after the first second); null: none
  // Polled after every step (or group of steps); non-zero: the run stops
  // there, writes a checkpoint and the output so far.
  const volatile std::sig_atomic_t* interrupt = nullptr;
  int threads = 0;             // > 0: the penalty solver's threads (overrides the file's "threads"; default 1)
  CheckpointSpec checkpoint;   // a field > 0 overrides the file's "checkpoint"
  // Continue the run of this checkpoint (read from out_dir), which must be
  // of this scene file (SceneFile::text_hash) and find out_dir's outputs as
  // it recorded them; else CheckpointError before anything is written.
  const Checkpoint* resume = nullptr;
  std::string scene_path;      // recorded in checkpoints (absolute); default: scene_label made absolute
};

enum class RunStatus { kCompleted, kSimulationError, kInterrupted };

struct RunResult {
  RunStatus status = RunStatus::kCompleted;
  std::string message;  // the SimulationError text, if any
  std::int64_t steps = 0;
  double time = 0.0;          // simulated time reached, s
  double last_row_time = 0.0; // time of the last time-series row written, s
  double wall_seconds = 0.0;  // of this run and the runs it resumed
  std::size_t timeseries_rows = 0, snapshot_rows = 0;
  std::size_t block_table_rows = 0;  // DIR/blocks.csv (output.block_table)
  std::size_t vtk_frames = 0;        // frames of each ParaView series (output.vtk)
  int threads = 1;
  std::int64_t checkpoints = 0;       // written by this run
  std::string checkpoint_path;        // the last one written ("" if none)
  std::int64_t resumed_from_step = -1;  // >= 0: this run resumed a checkpoint at that step
};

// Column names of the time series for `tracked` scene blocks (see
// SCHEMA.md); rotation: with each block's rotation and spin (the penalty
// model's 6-DOF blocks).
std::vector<std::string> timeseries_header(const std::vector<int>& tracked, bool rotation = true);
// The time-series row of the model's current state, matching timeseries_header.
std::vector<CsvValue> timeseries_row(const Stepper& model, const std::vector<int>& tracked);
// The scene blocks in the time series: output.tracked_blocks, or all.
std::vector<int> tracked_blocks(const SceneFile& file);

// Throws OutputError if the output cannot be written; SceneFileError (before
// anything is written) if the run would take more than file.max_steps steps
// (check_step_count with the model's dt); CheckpointError (before anything is written) if
// options.resume does not fit this scene or out_dir's outputs.
RunResult run_scene(const SceneFile& file, const RunOptions& options);

}  // namespace dda::io
