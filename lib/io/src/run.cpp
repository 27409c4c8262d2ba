// The run loop of `dda run`: either model behind dda::Stepper, the outputs
// written at one place (run_outputs.hpp), checkpoints, the interrupt.
#include "dda/io/run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <ostream>

#include <nlohmann/json.hpp>

#include "dda/io/models.hpp"
#include "dda/state_bytes.hpp"
#include "run_outputs.hpp"

namespace dda::io {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using detail::first_step_reaching;
using detail::RunOutputs;

const char* const kRunSection = "run";
const char* const kPenaltySection = "penalty.simulation";
const char* const kCdemSection = "cdem.model";

// The penalty model runs its steps in groups (one thread team per group,
// Simulation::advance) that end where an output, a checkpoint or the end is
// due, and last about this long (s of wall-clock time) so that the interrupt
// flag, the progress line and a wall-clock checkpoint are looked at that
// often. The grouping changes the time a run takes, never its bits.
constexpr double kGroupSeconds = 0.05;
constexpr std::int64_t kMaxGroup = 1000;  // steps

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::string short_number(double x, int digits = 3) {
  char buf[48];
  std::snprintf(buf, sizeof buf, "%.*g", digits, x);
  return buf;
}

// Every outline's index, kind, name, mass and area at t = 0 (run.json).
nlohmann::ordered_json block_table(const SceneFile& file, const RunModel& m) {
  nlohmann::ordered_json blocks = nlohmann::ordered_json::array();
  const Scene& scene = file.scene;
  if (m.penalty) {
    const Simulation& sim = m.penalty->simulation();
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
    return blocks;
  }
  const cdem::Model& model = m.cdem->model();
  for (int i = 0; i < model.block_count(); ++i) {
    const BlockSpec& spec = scene.blocks[static_cast<std::size_t>(i)];
    const std::vector<Vec2> o = model.block_outline(i);
    nlohmann::ordered_json b;
    b["index"] = i;
    b["kind"] = "block";
    b["name"] = spec.name;
    b["fixed"] = spec.fixed;
    b["mass"] = spec.fixed ? 0.0 : model.block_mass(i);
    b["area"] = area(make_polygon(o.data(), static_cast<int>(o.size())));
    blocks.push_back(b);
  }
  return blocks;
}

const char* status_name(RunStatus s) {
  switch (s) {
    case RunStatus::kCompleted: return "completed";
    case RunStatus::kSimulationError: return "simulation_error";
    case RunStatus::kInterrupted: return "interrupted";
  }
  return "completed";
}

std::string run_json(const SceneFile& file, const std::string& label, const RunResult& res, double dt,
                     const nlohmann::ordered_json& blocks) {
  nlohmann::ordered_json j;
  j["status"] = status_name(res.status);
  j["message"] = res.message;
  j["scene"] = label;
  j["name"] = file.scene.name;
  j["model"] = model_name(file.model);
  j["threads"] = res.threads;
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
  if (res.status == RunStatus::kInterrupted) j["checkpoint"] = res.checkpoint_path;
  return j.dump(2) + "\n";
}

// The checkpoint schedule and where it stands.
struct Schedule {
  CheckpointSpec spec;
  std::int64_t next_index = 1;  // the next simulated-time checkpoint is at next_index * spec.every
};

}  // namespace

RunResult run_scene(const SceneFile& file, const RunOptions& opt) {
  const fs::path out(opt.out_dir.empty() ? "." : opt.out_dir);
  const bool penalty = file.model == ContactModel::kPenalty;
  Schedule schedule{file.checkpoint};
  if (opt.checkpoint.every > 0.0) schedule.spec.every = opt.checkpoint.every;
  if (opt.checkpoint.every_wall > 0.0) schedule.spec.every_wall = opt.checkpoint.every_wall;
  if (!penalty && opt.threads > 1)
    throw SceneFileError(opt.scene_label + ": threads: the cdem model steps on one thread");
  const int threads = opt.threads > 0 ? opt.threads : file.threads > 0 ? file.threads : 1;
  const std::string ckpt_path = (out / kCheckpointFileName).string();
  // The output section with the command line's additions (the flags of
  // dda run; a resumed run takes those it started with).
  OutputSpec output = file.output;
  if (!penalty && output.block_table)
    throw SceneFileError(opt.scene_label + ": output.block_table: the per-block table of 6-DOF blocks (rotation, "
                                           "spin, stress) is the penalty model's");

  // The model first: the step count is known once its dt is (with
  // dt_fraction > 0); a run that would be too long writes nothing. The block
  // table is of t = 0, before a resumed state replaces it.
  RunModel m = build_model(file, threads);
  Stepper& model = *m.stepper;
  check_step_count(file, model.dt(), opt.scene_label);
  const nlohmann::ordered_json blocks = block_table(file, m);

  // A resumed run: everything checked, and the model restored, before
  // anything is written.
  double wall_before = 0.0;
  std::string label = opt.scene_label;  // a resumed run keeps the label it started with
  ByteReader run_state(nullptr, 0, ckpt_path);
  if (opt.resume) {
    const Checkpoint& c = *opt.resume;
    if (c.scene_hash != file.text_hash)
      throw CheckpointError(ckpt_path + ": written for another scene (" + c.scene_path +
                            " as it was then); this scene file's text differs; nothing resumed");
    if (c.model != model_name(file.model))
      throw CheckpointError(ckpt_path + ": holds a \"" + c.model + "\" model, the scene's is \"" +
                            model_name(file.model) + "\"");
    const CheckpointSection* run = c.find(kRunSection);
    const char* const model_section = penalty ? kPenaltySection : kCdemSection;
    const CheckpointSection* sim = c.find(model_section);
    if (!run || !sim) throw CheckpointError(ckpt_path + ": corrupted: a section is missing");
    try {
      ByteReader state(sim->bytes.data(), sim->bytes.size(), ckpt_path + ": " + model_section);
      if (penalty)
        m.penalty->simulation().restore_state(state);
      else
        m.cdem->model().restore_state(state);
      state.expect_end();
      run_state = ByteReader(run->bytes.data(), run->bytes.size(), ckpt_path + ": " + kRunSection);
      if (run_state.i64() != model.step_count()) run_state.fail("the run and the model stopped at different steps");
      wall_before = run_state.f64();
      run_state.i32();  // the threads of the run that stopped (any count gives the same bits)
      const double every = run_state.f64(), every_wall = run_state.f64();
      schedule.next_index = run_state.i64();
      label = run_state.text();
      output.vtk = run_state.boolean();
      output.vtk_every = run_state.i32();
      output.block_table = run_state.boolean();
      if (!(opt.checkpoint.every > 0.0)) schedule.spec.every = every;
      if (!(opt.checkpoint.every_wall > 0.0)) schedule.spec.every_wall = every_wall;
      RunOutputs::verify(out.string(), output, m, run_state);
    } catch (const StateError& e) {
      throw CheckpointError(std::string(e.what()) + "; nothing resumed");
    }
  }

  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw OutputError("cannot create directory " + out.string() + ": " + ec.message());
  std::optional<RunOutputs> open_outputs;
  if (opt.resume) open_outputs.emplace(file, output, m, out.string(), run_state);
  else open_outputs.emplace(file, output, m, out.string());
  RunOutputs& outputs = *open_outputs;

  RunResult res;
  res.threads = threads;
  res.resumed_from_step = opt.resume ? model.step_count() : -1;
  if (opt.resume && opt.progress)
    *opt.progress << "dda: resuming " << label << " from step " << model.step_count() << " (t = "
                  << format_number(model.time()) << " s) on " << threads << (threads == 1 ? " thread" : " threads")
                  << std::endl;
  const Clock::time_point start = Clock::now();
  Clock::time_point last_print = start, last_checkpoint = start;
  const std::string scene_path =
      !opt.scene_path.empty() ? opt.scene_path : fs::absolute(opt.scene_label, ec).lexically_normal().string();
  auto write_checkpoint_now = [&] {
    ByteWriter run;
    run.i64(model.step_count());
    run.f64(wall_before + seconds_since(start));
    run.i32(threads);
    run.f64(schedule.spec.every);
    run.f64(schedule.spec.every_wall);
    run.i64(schedule.next_index);
    run.text(label);
    run.boolean(output.vtk);
    run.i32(output.vtk_every);
    run.boolean(output.block_table);
    outputs.save(run);  // flushed to the disk before the checkpoint names them
    ByteWriter state;
    if (penalty)
      m.penalty->simulation().save_state(state);
    else
      m.cdem->model().save_state(state);
    Checkpoint c;
    c.scene_path = scene_path;
    c.scene_hash = file.text_hash;
    c.model = model_name(file.model);
    c.sections = {{kRunSection, run.take()}, {penalty ? kPenaltySection : kCdemSection, state.take()}};
    write_checkpoint(out.string(), c);
    res.checkpoint_path = ckpt_path;
    ++res.checkpoints;
    last_checkpoint = Clock::now();
  };

  const double dt = model.dt(), duration = model.duration();
  auto finished = [&] { return !(model.time() + 0.5 * dt < duration); };
  const double total_steps = std::max(1.0, std::round(duration / dt));
  const std::int64_t first_step = model.step_count();
  std::int64_t group = 1;
  try {
    if (!opt.resume) outputs.write_due(true, false);
    while (!finished()) {
      if (opt.interrupt && *opt.interrupt) {
        res.status = RunStatus::kInterrupted;
        break;
      }
      std::int64_t count = 1;
      if (penalty) {
        // Up to the next step at which anything is due (time = steps * dt).
        const std::int64_t s = model.step_count();
        std::int64_t next = std::min(outputs.next_due_step(s, dt), first_step_reaching(duration, dt, s));
        if (schedule.spec.every > 0.0)
          next = std::min(next, first_step_reaching(static_cast<double>(schedule.next_index) * schedule.spec.every, dt, s));
        count = std::clamp<std::int64_t>(next - s, 1, group);
      }
      const Clock::time_point t0 = Clock::now();
      model.advance(count);
      const double took = seconds_since(t0);
      group = took > 0.0 ? std::clamp<std::int64_t>(static_cast<std::int64_t>(kGroupSeconds * static_cast<double>(count) / took), 1, kMaxGroup)
                         : kMaxGroup;
      const bool last = finished();
      outputs.write_due(false, last);
      if (!last) {
        bool due = false;
        if (schedule.spec.every > 0.0)
          while (static_cast<double>(schedule.next_index) * schedule.spec.every <= model.time() + 0.5 * dt) {
            due = true;
            ++schedule.next_index;
          }
        if (schedule.spec.every_wall > 0.0 && seconds_since(last_checkpoint) >= schedule.spec.every_wall) due = true;
        if (due) write_checkpoint_now();
      }
      if (opt.progress && !last) {
        const Clock::time_point now = Clock::now();
        if (now - last_print >= std::chrono::seconds(1)) {
          last_print = now;
          const double el = std::chrono::duration<double>(now - start).count();
          const double steps = static_cast<double>(model.step_count());
          const double rate = static_cast<double>(model.step_count() - first_step) / el;
          *opt.progress << "dda: " << short_number(100.0 * steps / total_steps) << "%  t = "
                        << short_number(model.time(), 6) << " of " << short_number(duration, 6) << " s, step "
                        << model.step_count() << ", " << short_number(rate) << " steps/s, about "
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
  } catch (const SceneError& e) {  // the CDEM model finds some limits only at a touch
    res.status = RunStatus::kSimulationError;
    res.message = e.what();
  }
  res.steps = model.step_count();
  res.time = model.time();
  res.timeseries_rows = outputs.timeseries_rows();
  res.snapshot_rows = outputs.snapshot_rows();
  res.last_row_time = outputs.last_row_time();
  res.block_table_rows = outputs.block_table_rows();
  res.vtk_frames = outputs.vtk_frames();
  if (res.status == RunStatus::kInterrupted) {
    res.message = "interrupted at step " + std::to_string(res.steps) + " (t = " + format_number(res.time) + " s)";
    write_checkpoint_now();
  }
  res.wall_seconds = wall_before + seconds_since(start);
  outputs.commit();
  // A run that ended has nothing to resume.
  if (res.status != RunStatus::kInterrupted) fs::remove(ckpt_path, ec);
  write_file_atomic((out / "run.json").string(), run_json(file, label, res, dt, blocks));
  return res;
}

}  // namespace dda::io
