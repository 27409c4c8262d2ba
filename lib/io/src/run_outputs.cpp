#include "run_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "dda/io/block_table.hpp"
#include "dda/io/checkpoint.hpp"
#include "dda/io/run.hpp"
#include "dda/io/vtk_cdem.hpp"
#include "dda/io/vtk_dda.hpp"

namespace dda::io {

std::vector<std::string> timeseries_header(const std::vector<int>& tracked, bool rotation) {
  std::vector<std::string> h{"time", "step"};
  for (int i : tracked) {
    const std::string b = "b" + std::to_string(i) + "_";
    for (const char* c : {"x", "y", "vx", "vy"}) h.push_back(b + c);
    if (rotation)
      for (const char* c : {"rot", "spin"}) h.push_back(b + c);
  }
  // The energy budget (Energy::balance_error): E_total + E_dissipated - E_initial.
  for (const char* c : {"E_kinetic", "E_gravity", "E_strain", "E_contact", "E_friction_spring", "E_total",
                        "E_dissipated", "E_balance_error", "px", "py", "contacts"})
    h.emplace_back(c);
  return h;
}

std::vector<CsvValue> timeseries_row(const Stepper& model, const std::vector<int>& tracked) {
  std::vector<CsvValue> row{model.time(), static_cast<long long>(model.step_count())};
  const bool rotation = model.has_rotation();
  row.reserve(2 + 6 * tracked.size() + 11);
  for (int i : tracked) {
    const BlockMotion m = model.block_motion(i);
    for (double x : {m.position.x, m.position.y, m.velocity.x, m.velocity.y}) row.emplace_back(x);
    if (rotation)
      for (double x : {m.rotation, m.spin}) row.emplace_back(x);
  }
  const Energy e = model.energy();
  const Vec2 p = model.momentum();
  for (double x : {e.kinetic, e.gravity, e.strain, e.contact, e.friction_spring, e.total(), e.dissipated,
                   e.balance_error(), p.x, p.y})
    row.emplace_back(x);
  row.emplace_back(model.contact_count());
  return row;
}

std::vector<int> tracked_blocks(const SceneFile& file) {
  if (!file.output.tracked_blocks.empty()) return file.output.tracked_blocks;
  std::vector<int> all(file.scene.blocks.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  return all;
}

namespace detail {

namespace {

namespace fs = std::filesystem;

const char* const kTimeseries = "timeseries.csv";
const char* const kSnapshots = "snapshots.csv";
const char* const kBlockTable = "blocks.csv";
const std::vector<std::string> kSnapshotHeader = {"time", "step", "block", "vertex", "x", "y"};

std::string in_dir(const std::string& dir, const char* name) { return (fs::path(dir) / name).string(); }

void put_mark(ByteWriter& w, const char* name, const CsvMark& m) {
  w.text(name);
  w.u64(m.bytes);
  w.u64(m.rows);
  w.u64(m.hash);
}

CsvMark get_mark(ByteReader& r, const char* name) {
  if (r.text() != name) r.fail(std::string("the outputs are not recorded in order (expected ") + name + ")");
  CsvMark m;
  m.bytes = r.u64();
  m.rows = r.u64();
  m.hash = r.u64();
  return m;
}

std::vector<double> get_times(ByteReader& r) {
  std::vector<double> t;
  r.list(t, 8, [](ByteReader& in) { return in.f64(); });
  return t;
}

// The ParaView series' names: the penalty model's blocks, the cdem model's elements.
const char* mesh_series(const RunModel& m) { return m.penalty ? "blocks" : "elements"; }

// The CSV files a run writes, in the order save() records them.
std::vector<const char*> csv_files(const OutputSpec& output) {
  std::vector<const char*> f = {kTimeseries, kSnapshots};
  if (output.block_table) f.push_back(kBlockTable);
  return f;
}

}  // namespace

std::int64_t first_step_reaching(double t, double dt, std::int64_t after) {
  std::int64_t n = after + 1;
  const double estimate = std::floor((t - 0.5 * dt) / dt) - 2.0;
  if (estimate > static_cast<double>(n) && estimate < 9e18) n = static_cast<std::int64_t>(estimate);
  while (!(t <= static_cast<double>(n) * dt + 0.5 * dt)) ++n;
  return n;
}

RunOutputs::RunOutputs(const SceneFile& file, const OutputSpec& output, const RunModel& model, const std::string& dir)
    : model_(model),
      stepper_(*model.stepper),
      tracked_(tracked_blocks(file)),
      output_(output),
      timeseries_(in_dir(dir, kTimeseries), timeseries_header(tracked_, stepper_.has_rotation())),
      snapshots_(in_dir(dir, kSnapshots), kSnapshotHeader) {
  if (output_.block_table) table_.emplace(in_dir(dir, kBlockTable), block_table_header());
  if (output_.vtk) {
    const std::string vtk_dir = in_dir(dir, "vtk");
    vtk_.emplace(Vtk{VtkSeries(vtk_dir, mesh_series(model_)), VtkSeries(vtk_dir, "contacts")});
  }
}

RunOutputs::RunOutputs(const SceneFile& file, const OutputSpec& output, const RunModel& model, const std::string& dir,
                       ByteReader& saved)
    : model_(model),
      stepper_(*model.stepper),
      tracked_(tracked_blocks(file)),
      output_(output),
      next_snapshot_(static_cast<std::size_t>(saved.u64())),
      last_row_time_(saved.f64()),
      timeseries_(in_dir(dir, kTimeseries), timeseries_header(tracked_, stepper_.has_rotation()),
                  get_mark(saved, kTimeseries)),
      snapshots_(in_dir(dir, kSnapshots), kSnapshotHeader, get_mark(saved, kSnapshots)) {
  if (next_snapshot_ > output_.snapshot_times.size()) saved.fail("more snapshots written than the scene asks for");
  if (output_.block_table) table_.emplace(in_dir(dir, kBlockTable), block_table_header(), get_mark(saved, kBlockTable));
  if (output_.vtk) {
    const std::string vtk_dir = in_dir(dir, "vtk");
    const std::int64_t last = saved.i64();
    std::vector<double> mesh_times = get_times(saved), contact_times = get_times(saved);
    vtk_.emplace(Vtk{VtkSeries(vtk_dir, mesh_series(model_), std::move(mesh_times)),
                     VtkSeries(vtk_dir, "contacts", std::move(contact_times)), last});
  }
}

void RunOutputs::verify(const std::string& dir, const OutputSpec& output, const RunModel& model, ByteReader saved) {
  saved.u64();
  saved.f64();
  for (const char* name : csv_files(output)) {
    const CsvMark m = get_mark(saved, name);
    const std::string path = in_dir(dir, name);
    if (CsvFile::resume_source(path, m).empty())
      throw CheckpointError(path + ": does not hold the " + std::to_string(m.bytes) + " bytes (" +
                            std::to_string(m.rows) +
                            " rows) the checkpoint recorded: changed or removed since; nothing resumed");
  }
  if (!output.vtk) return;
  saved.i64();
  // The frames taken before the checkpoint stay as they are: each must be there.
  const std::string vtk_dir = in_dir(dir, "vtk");
  for (const char* name : {mesh_series(model), "contacts"}) {
    const std::size_t frames = get_times(saved).size();
    for (std::size_t k = 0; k < frames; ++k)
      if (!fs::exists(fs::path(vtk_dir) / VtkSeries::frame_file(name, k)))
        throw CheckpointError(vtk_dir + "/" + VtkSeries::frame_file(name, k) +
                              ": a ParaView frame the checkpoint recorded is missing; nothing resumed");
  }
}

void RunOutputs::write_row() {
  const std::vector<CsvValue> row = timeseries_row(stepper_, tracked_);
  if (table_) {
    // The time series' row is checked first: a NaN writes neither file.
    for (std::size_t i = 0; i < row.size(); ++i)
      if (!row[i].is_integer && !std::isfinite(row[i].number))
        throw NonFiniteValue(timeseries_.path() + ": row " + std::to_string(timeseries_.rows() + 1) + ", column " +
                             timeseries_.header()[i] + ": not finite (not written)");
    io::block_table_rows(*table_, model_.penalty->simulation());
  }
  timeseries_.row(row);
  last_row_time_ = stepper_.time();
}

void RunOutputs::write_due(bool first, bool last) {
  const std::int64_t step = stepper_.step_count();
  if (first || last || step % output_.every == 0) write_row();
  const double half = 0.5 * stepper_.dt();
  const std::vector<double>& times = output_.snapshot_times;
  while (next_snapshot_ < times.size() && times[next_snapshot_] <= stepper_.time() + half) {
    write_snapshot();
    if (output_.vtk_every == 0) vtk_frame();
    ++next_snapshot_;
  }
  if (output_.vtk_every > 0 && (first || last || step % output_.vtk_every == 0)) vtk_frame();
}

std::int64_t RunOutputs::next_due_step(std::int64_t step, double dt) const {
  std::int64_t next = (step / output_.every + 1) * output_.every;
  if (vtk_ && output_.vtk_every > 0) next = std::min(next, (step / output_.vtk_every + 1) * output_.vtk_every);
  if (next_snapshot_ < output_.snapshot_times.size())
    next = std::min(next, first_step_reaching(output_.snapshot_times[next_snapshot_], dt, step));
  return next;
}

void RunOutputs::write_snapshot() {
  // Every vertex is checked before any is written.
  const int n = stepper_.outline_count();
  std::vector<std::vector<Vec2>> outlines(static_cast<std::size_t>(n));
  for (int b = 0; b < n; ++b) {
    outlines[static_cast<std::size_t>(b)] = stepper_.outline(b);
    const std::vector<Vec2>& o = outlines[static_cast<std::size_t>(b)];
    for (std::size_t k = 0; k < o.size(); ++k)
      if (!is_finite(o[k]))
        throw NonFiniteValue(snapshots_.path() + ": snapshot at t = " + format_number(stepper_.time()) + " s: block " +
                             std::to_string(b) + " vertex " + std::to_string(k) + " is not finite (not written)");
  }
  for (int b = 0; b < n; ++b) {
    const std::vector<Vec2>& o = outlines[static_cast<std::size_t>(b)];
    for (std::size_t k = 0; k < o.size(); ++k)
      snapshots_.row({stepper_.time(), static_cast<long long>(stepper_.step_count()), b, k, o[k].x, o[k].y});
  }
}

void RunOutputs::vtk_frame() {
  // One frame per step at most (a snapshot time and vtk_every may meet).
  if (!vtk_ || stepper_.step_count() == vtk_->last_frame_step) return;
  const double t = stepper_.time();
  const VtkMesh mesh = model_.penalty ? block_mesh(model_.penalty->simulation()) : element_mesh(model_.cdem->model());
  const VtkMesh contacts =
      model_.penalty ? contact_mesh(model_.penalty->simulation()) : contact_mesh(model_.cdem->model());
  check_mesh(mesh, std::string("ParaView ") + mesh_series(model_) + " frame at t = " + format_number(t) + " s");
  check_mesh(contacts, "ParaView contacts frame at t = " + format_number(t) + " s");
  vtk_->blocks.add(t, mesh);
  vtk_->contacts.add(t, contacts);
  vtk_->last_frame_step = stepper_.step_count();
}

void RunOutputs::save(ByteWriter& out) {
  out.u64(next_snapshot_);
  out.f64(last_row_time_);
  put_mark(out, kTimeseries, timeseries_.mark());
  put_mark(out, kSnapshots, snapshots_.mark());
  if (table_) put_mark(out, kBlockTable, table_->mark());
  if (vtk_) {
    out.i64(vtk_->last_frame_step);
    for (const VtkSeries* s : {&vtk_->blocks, &vtk_->contacts})
      out.list(s->times(), [](ByteWriter& w, double t) { w.f64(t); });
  }
}

void RunOutputs::commit() {
  timeseries_.commit();
  snapshots_.commit();
  if (table_) table_->commit();
  // The frames are on disk as they were taken; the collections list them.
  if (vtk_) {
    vtk_->blocks.write_collection();
    vtk_->contacts.write_collection();
  }
}

}  // namespace detail

}  // namespace dda::io
