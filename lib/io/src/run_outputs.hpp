// What `dda run` writes while it runs, in one place: the time series, the
// snapshots, the long per-block table and the ParaView series, of either
// model (lib/io/SCHEMA.md, "Run output"). An output added beside them opens
// its files in the constructors, writes what is due in write_due (the run
// loop's one output step), tells the loop when it is next due
// (next_due_step), records how far it got in save and continues from there
// in the resuming constructor (after verify accepted it), and closes in
// commit. Internal to dda_io.
#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "dda/io/csv.hpp"
#include "dda/io/models.hpp"
#include "dda/io/scene_file.hpp"
#include "dda/io/vtk_series.hpp"
#include "dda/state_bytes.hpp"

namespace dda::io::detail {

class RunOutputs {
 public:
  // New files in `dir` (which exists); `output`: the file's output section
  // with the command line's additions.
  RunOutputs(const SceneFile& file, const OutputSpec& output, const RunModel& model, const std::string& dir);
  // Continues the files of a stopped run from what save() recorded.
  RunOutputs(const SceneFile& file, const OutputSpec& output, const RunModel& model, const std::string& dir,
             ByteReader& saved);

  // Throws CheckpointError, naming the file, unless every output in `dir`
  // still holds what save() recorded (reads a copy of `saved`). Writes
  // nothing.
  static void verify(const std::string& dir, const OutputSpec& output, const RunModel& model, ByteReader saved);

  // The output step, after t = 0 (first) and after every advance of the
  // model: a time-series row (and the block table's rows) at t = 0, every
  // output.every steps and at the last step; each snapshot whose time has
  // come (the first step with time >= t - dt/2), with its ParaView frame;
  // or the frames every output.vtk_every steps, at t = 0 and at the last
  // step. NonFiniteValue if a value is not finite (nothing of that row,
  // snapshot or frame written).
  void write_due(bool first, bool last);
  // The first step after `step` at which something is due, for a model
  // whose time is steps * dt (the penalty model).
  std::int64_t next_due_step(std::int64_t step, double dt) const;

  // Flushes; records how far each file is written.
  void save(ByteWriter& out);
  // Renames the CSV files into place and writes the ParaView collections.
  void commit();

  std::size_t timeseries_rows() const { return timeseries_.rows(); }
  std::size_t snapshot_rows() const { return snapshots_.rows(); }
  std::size_t block_table_rows() const { return table_ ? table_->rows() : 0; }
  std::size_t vtk_frames() const { return vtk_ ? vtk_->blocks.frames() : 0; }
  double last_row_time() const { return last_row_time_; }

 private:
  struct Vtk {
    VtkSeries blocks, contacts;  // penalty: blocks; cdem: elements
    std::int64_t last_frame_step = -1;
  };
  void write_row();
  void write_snapshot();
  void vtk_frame();

  const RunModel& model_;
  const Stepper& stepper_;
  std::vector<int> tracked_;
  OutputSpec output_;
  std::size_t next_snapshot_ = 0;
  double last_row_time_ = 0.0;
  CsvFile timeseries_, snapshots_;
  std::optional<CsvFile> table_;
  std::optional<Vtk> vtk_;
};

// The first step n > after whose time n * dt satisfies t <= n dt + dt/2 (the
// run loop's and the snapshots' "time has come"), as the penalty model
// computes its time.
std::int64_t first_step_reaching(double t, double dt, std::int64_t after);

}  // namespace dda::io::detail
