#include "dda/io/run.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <ostream>

#include <nlohmann/json.hpp>

#include "dda/io/block_table.hpp"
#include "dda/io/csv.hpp"
#include "dda/io/vtk_dda.hpp"
#include "dda/io/vtk_series.hpp"

namespace dda::io {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string short_number(double x, int digits = 3) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

std::vector<int> tracked_blocks(const SceneFile& file) {
  if (!file.output.tracked_blocks.empty()) return file.output.tracked_blocks;
  std::vector<int> all(file.scene.blocks.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  return all;
}

// All vertices of every polygon, or NonFiniteValue before anything is written.
void write_snapshot(CsvFile& csv, const Simulation& sim) {
  for (int b = 0; b < sim.block_count(); ++b) {
    const Polygon& p = sim.polygon(b);
    for (int k = 0; k < p.count; ++k)
      if (!is_finite(p.vertex(k)))
        throw NonFiniteValue(csv.path() + ": snapshot at t = " + format_number(sim.time()) + " s: block " +
                             std::to_string(b) + " vertex " + std::to_string(k) + " is not finite (not written)");
  }
  for (int b = 0; b < sim.block_count(); ++b) {
    const Polygon& p = sim.polygon(b);
    for (int k = 0; k < p.count; ++k)
      csv.row({sim.time(), static_cast<long long>(sim.step_count()), b, k, p.vertex(k).x, p.vertex(k).y});
  }
}

// `dt`: the step used (Simulation::dt(), which differs from scene.dt when
// scene.dt_fraction > 0).
std::string run_json(const SceneFile& file, const RunOptions& opt, const RunResult& res, double dt,
                     const nlohmann::ordered_json& blocks) {
  nlohmann::ordered_json j;
  j["status"] = res.status == RunStatus::kCompleted ? "completed" : "simulation_error";
  j["message"] = res.message;
  j["scene"] = opt.scene_label;
  j["name"] = file.scene.name;
  j["dt"] = dt;
  j["duration"] = file.scene.duration;
  j["steps"] = res.steps;
  j["time"] = res.time;
  j["last_row_time"] = res.last_row_time;
  j["wall_seconds"] = res.wall_seconds;
  j["steps_per_second"] = res.wall_seconds > 0.0 ? static_cast<double>(res.steps) / res.wall_seconds : 0.0;
  j["timeseries_rows"] = res.timeseries_rows;
  j["snapshot_rows"] = res.snapshot_rows;
  j["block_table_rows"] = res.block_table_rows;
  j["vtk_frames"] = res.vtk_frames;
  j["tracked_blocks"] = tracked_blocks(file);
  j["blocks"] = blocks;
  return j.dump(2) + "\n";
}

}  // namespace

std::vector<std::string> timeseries_header(const std::vector<int>& tracked) {
  std::vector<std::string> h{"time", "step"};
  for (int i : tracked) {
    const std::string b = "b" + std::to_string(i) + "_";
    for (const char* c : {"x", "y", "vx", "vy", "rot", "spin"}) h.push_back(b + c);
  }
  // The energy budget (Energy::balance_error): E_total + E_dissipated - E_initial.
  for (const char* c : {"E_kinetic", "E_gravity", "E_strain", "E_contact", "E_friction_spring", "E_total",
                        "E_dissipated", "E_balance_error", "px", "py", "contacts"})
    h.emplace_back(c);
  return h;
}

std::vector<CsvValue> timeseries_row(const Simulation& sim, const std::vector<int>& tracked) {
  std::vector<CsvValue> row{sim.time(), static_cast<long long>(sim.step_count())};
  row.reserve(2 + 6 * tracked.size() + 11);
  for (int i : tracked) {
    const Vec2 c = sim.centroid(i);
    const Vec6& v = sim.velocity(i);
    for (double x : {c.x, c.y, v[0], v[1], sim.displacement(i)[2], v[2]}) row.emplace_back(x);
  }
  const Energy e = sim.energy();
  const Vec2 p = sim.momentum();
  for (double x : {e.kinetic, e.gravity, e.strain, e.contact, e.friction_spring, e.total(), e.dissipated,
                   e.balance_error(), p.x, p.y})
    row.emplace_back(x);
  row.emplace_back(sim.contacts().size());
  return row;
}

RunResult run_scene(const SceneFile& file, const RunOptions& opt) {
  const Scene& scene = file.scene;
  const std::vector<int> tracked = tracked_blocks(file);
  const fs::path out(opt.out_dir.empty() ? "." : opt.out_dir);
  // The simulation first: the step count is known once its dt is (with
  // dt_fraction > 0); a run that would be too long writes nothing.
  Simulation sim(scene);
  check_step_count(file, sim.dt(), opt.scene_label);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw OutputError("cannot create directory " + out.string() + ": " + ec.message());

  nlohmann::ordered_json blocks = nlohmann::ordered_json::array();
  for (int i = 0; i < sim.block_count(); ++i) {
    const bool boundary = i >= sim.scene_block_count();
    nlohmann::ordered_json b;
    b["index"] = i;
    b["kind"] = boundary ? "boundary" : "block";
    b["name"] = boundary ? "boundaries[" + std::to_string(i - sim.scene_block_count()) + "]"
                         : scene.blocks[static_cast<std::size_t>(i)].name;
    b["fixed"] = sim.fixed(i);
    b["mass"] = boundary || sim.fixed(i) ? 0.0 : sim.mass(i);
    b["area"] = sim.area(i);
    b["potential_length"] = sim.potential_length(i);
    blocks.push_back(b);
  }

  CsvFile ts((out / "timeseries.csv").string(), timeseries_header(tracked));
  CsvFile snap((out / "snapshots.csv").string(), {"time", "step", "block", "vertex", "x", "y"});
  std::optional<CsvFile> table;
  if (file.output.block_table) table.emplace((out / "blocks.csv").string(), block_table_header());
  // ParaView series: DIR/vtk/blocks.pvd and contacts.pvd, a frame at each
  // snapshot time or every output.vtk_every steps (one per step at most).
  std::optional<VtkSeries> vtk_blocks, vtk_contacts;
  if (file.output.vtk) {
    vtk_blocks.emplace((out / "vtk").string(), "blocks");
    vtk_contacts.emplace((out / "vtk").string(), "contacts");
  }
  std::int64_t last_frame_step = -1;
  auto vtk_frame = [&] {
    if (!vtk_blocks || sim.step_count() == last_frame_step) return;
    const VtkMesh blocks_mesh = block_mesh(sim), contacts_mesh = contact_mesh(sim);
    check_mesh(blocks_mesh, "ParaView blocks frame at t = " + format_number(sim.time()) + " s");
    check_mesh(contacts_mesh, "ParaView contacts frame at t = " + format_number(sim.time()) + " s");
    vtk_blocks->add(sim.time(), blocks_mesh);
    vtk_contacts->add(sim.time(), contacts_mesh);
    last_frame_step = sim.step_count();
  };

  const double dt = sim.dt();
  const std::vector<double>& times = file.output.snapshot_times;
  std::size_t next_snap = 0;
  auto snapshots_due = [&] {
    while (next_snap < times.size() && times[next_snap] <= sim.time() + 0.5 * dt) {
      write_snapshot(snap, sim);
      if (file.output.vtk_every == 0) vtk_frame();
      ++next_snap;
    }
  };
  const double total_steps = std::max(1.0, std::round(scene.duration / dt));
  const Clock::time_point start = Clock::now();
  Clock::time_point last_print = start;

  RunResult res;
  auto write_row = [&] {
    const std::vector<CsvValue> row = timeseries_row(sim, tracked);
    if (table) {
      for (const CsvValue& x : row)
        if (!x.is_integer && !std::isfinite(x.number)) ts.row(row);  // throws NonFiniteValue, nothing written
      block_table_rows(*table, sim);
    }
    ts.row(row);
    res.last_row_time = sim.time();
  };
  try {
    write_row();
    snapshots_due();
    if (file.output.vtk_every > 0) vtk_frame();
    while (sim.time() + 0.5 * dt < scene.duration) {
      if (opt.interrupt && *opt.interrupt) {
        res.status = RunStatus::kInterrupted;
        break;
      }
      sim.step();
      const bool last = !(sim.time() + 0.5 * dt < scene.duration);
      if (last || sim.step_count() % file.output.every == 0) write_row();
      snapshots_due();
      if (file.output.vtk_every > 0 && (last || sim.step_count() % file.output.vtk_every == 0)) vtk_frame();
      if (opt.progress && !last) {
        const Clock::time_point now = Clock::now();
        if (now - last_print >= std::chrono::seconds(1)) {
          last_print = now;
          const double el = std::chrono::duration<double>(now - start).count();
          const double steps = static_cast<double>(sim.step_count());
          const double rate = steps / el;
          *opt.progress << "dda: " << short_number(100.0 * steps / total_steps) << "%  t = " << short_number(sim.time(), 6)
                        << " of " << short_number(scene.duration, 6) << " s, step " << sim.step_count() << ", "
                        << short_number(rate) << " steps/s, about "
                        << short_number(std::max(0.0, (total_steps - steps) / rate), 2) << " s left" << std::endl;
        }
      }
    }
  } catch (const SimulationError& e) {
    res.status = RunStatus::kSimulationError;
    res.message = e.what();
  } catch (const NonFiniteValue& e) {
    res.status = RunStatus::kSimulationError;
    res.message = std::string("non-finite output: ") + e.what();
  }
  res.steps = sim.step_count();
  res.time = sim.time();
  res.wall_seconds = seconds_since(start);
  res.timeseries_rows = ts.rows();
  res.snapshot_rows = snap.rows();
  res.block_table_rows = table ? table->rows() : 0;
  res.vtk_frames = vtk_blocks ? vtk_blocks->frames() : 0;
  // The frames are on disk as they were taken; the collections list them
  // (also after an interrupt: each frame is complete).
  if (vtk_blocks) {
    vtk_blocks->write_collection();
    vtk_contacts->write_collection();
  }
  if (res.status == RunStatus::kInterrupted) {
    ts.discard();
    snap.discard();
    if (table) table->discard();
    return res;
  }
  ts.commit();
  snap.commit();
  if (table) table->commit();
  write_file_atomic((out / "run.json").string(), run_json(file, opt, res, dt, blocks));
  return res;
}

}  // namespace dda::io
