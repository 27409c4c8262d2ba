// What `dda run` writes while it runs, in one place: the time series and the
// snapshots of either model (lib/io/SCHEMA.md, "Run output"). An output
// added beside them opens its files in the constructors, writes what is due
// in write_due (the run loop's one output step), tells the loop when it is
// next due (next_due_step), records how far it got in save and continues
// from there in the resuming constructor (after verify accepted it), and
// renames its files into place in commit. Internal to dda_io.
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "dda/io/csv.hpp"
#include "dda/io/scene_file.hpp"
#include "dda/state_bytes.hpp"
#include "dda/stepper.hpp"

namespace dda::io::detail {

class RunOutputs {
 public:
  // New files in `dir` (which exists).
  RunOutputs(const SceneFile& file, const Stepper& model, const std::string& dir);
  // Continues the files of a stopped run from what save() recorded.
  RunOutputs(const SceneFile& file, const Stepper& model, const std::string& dir, ByteReader& saved);

  // Throws CheckpointError, naming the file, unless every output in `dir`
  // still holds what save() recorded (reads `saved` to its end). Writes
  // nothing.
  static void verify(const std::string& dir, ByteReader saved);

  // The output step, after t = 0 (first) and after every advance of the
  // model: a time-series row at t = 0, every output.every steps and at the
  // last step; each snapshot whose time has come (the first step with
  // time >= t - dt/2). NonFiniteValue if a value is not finite (nothing of
  // that row or snapshot written).
  void write_due(const Stepper& model, bool first, bool last);
  // The first step after `step` at which something is due, for a model
  // whose time is steps * dt (the penalty model).
  std::int64_t next_due_step(std::int64_t step, double dt) const;

  // Flushes; records how far each file is written.
  void save(ByteWriter& out);
  void commit();

  std::size_t timeseries_rows() const { return timeseries_.rows(); }
  std::size_t snapshot_rows() const { return snapshots_.rows(); }
  double last_row_time() const { return last_row_time_; }

 private:
  void write_snapshot(const Stepper& model);

  std::vector<int> tracked_;
  int every_ = 1;
  std::vector<double> snapshot_times_;
  std::size_t next_snapshot_ = 0;
  double last_row_time_ = 0.0;
  CsvFile timeseries_, snapshots_;
};

// The first step n > after whose time n * dt satisfies t <= n dt + dt/2 (the
// run loop's and the snapshots' "time has come"), as the penalty model
// computes its time.
std::int64_t first_step_reaching(double t, double dt, std::int64_t after);

}  // namespace dda::io::detail
