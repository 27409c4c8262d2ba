#include "run_outputs.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "dda/io/checkpoint.hpp"
#include "dda/io/run.hpp"

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

}  // namespace

std::int64_t first_step_reaching(double t, double dt, std::int64_t after) {
  std::int64_t n = after + 1;
  const double estimate = std::floor((t - 0.5 * dt) / dt) - 2.0;
  if (estimate > static_cast<double>(n) && estimate < 9e18) n = static_cast<std::int64_t>(estimate);
  while (!(t <= static_cast<double>(n) * dt + 0.5 * dt)) ++n;
  return n;
}

RunOutputs::RunOutputs(const SceneFile& file, const Stepper& model, const std::string& dir)
    : tracked_(tracked_blocks(file)),
      every_(file.output.every),
      snapshot_times_(file.output.snapshot_times),
      timeseries_(in_dir(dir, kTimeseries), timeseries_header(tracked_, model.has_rotation())),
      snapshots_(in_dir(dir, kSnapshots), kSnapshotHeader) {}

RunOutputs::RunOutputs(const SceneFile& file, const Stepper& model, const std::string& dir, ByteReader& saved)
    : tracked_(tracked_blocks(file)),
      every_(file.output.every),
      snapshot_times_(file.output.snapshot_times),
      next_snapshot_(static_cast<std::size_t>(saved.u64())),
      last_row_time_(saved.f64()),
      timeseries_(in_dir(dir, kTimeseries), timeseries_header(tracked_, model.has_rotation()),
                  get_mark(saved, kTimeseries)),
      snapshots_(in_dir(dir, kSnapshots), kSnapshotHeader, get_mark(saved, kSnapshots)) {
  if (next_snapshot_ > snapshot_times_.size()) saved.fail("more snapshots written than the scene asks for");
}

void RunOutputs::verify(const std::string& dir, ByteReader saved) {
  saved.u64();
  saved.f64();
  for (const char* name : {kTimeseries, kSnapshots}) {
    const CsvMark m = get_mark(saved, name);
    const std::string path = in_dir(dir, name);
    if (CsvFile::resume_source(path, m).empty())
      throw CheckpointError(path + ": does not hold the " + std::to_string(m.bytes) + " bytes (" +
                            std::to_string(m.rows) +
                            " rows) the checkpoint recorded: changed or removed since; nothing resumed");
  }
}

void RunOutputs::write_due(const Stepper& model, bool first, bool last) {
  if (first || last || model.step_count() % every_ == 0) {
    timeseries_.row(timeseries_row(model, tracked_));
    last_row_time_ = model.time();
  }
  const double half = 0.5 * model.dt();
  while (next_snapshot_ < snapshot_times_.size() && snapshot_times_[next_snapshot_] <= model.time() + half) {
    write_snapshot(model);
    ++next_snapshot_;
  }
}

std::int64_t RunOutputs::next_due_step(std::int64_t step, double dt) const {
  std::int64_t next = (step / every_ + 1) * every_;
  if (next_snapshot_ < snapshot_times_.size())
    next = std::min(next, first_step_reaching(snapshot_times_[next_snapshot_], dt, step));
  return next;
}

void RunOutputs::write_snapshot(const Stepper& model) {
  // Every vertex is checked before any is written.
  const int n = model.outline_count();
  std::vector<std::vector<Vec2>> outlines(static_cast<std::size_t>(n));
  for (int b = 0; b < n; ++b) {
    outlines[static_cast<std::size_t>(b)] = model.outline(b);
    const std::vector<Vec2>& o = outlines[static_cast<std::size_t>(b)];
    for (std::size_t k = 0; k < o.size(); ++k)
      if (!is_finite(o[k]))
        throw NonFiniteValue(snapshots_.path() + ": snapshot at t = " + format_number(model.time()) + " s: block " +
                             std::to_string(b) + " vertex " + std::to_string(k) + " is not finite (not written)");
  }
  for (int b = 0; b < n; ++b) {
    const std::vector<Vec2>& o = outlines[static_cast<std::size_t>(b)];
    for (std::size_t k = 0; k < o.size(); ++k)
      snapshots_.row({model.time(), static_cast<long long>(model.step_count()), b, k, o[k].x, o[k].y});
  }
}

void RunOutputs::save(ByteWriter& out) {
  out.u64(next_snapshot_);
  out.f64(last_row_time_);
  put_mark(out, kTimeseries, timeseries_.mark());
  put_mark(out, kSnapshots, snapshots_.mark());
}

void RunOutputs::commit() {
  timeseries_.commit();
  snapshots_.commit();
}

}  // namespace detail

}  // namespace dda::io
