// What both simulations of the Python module share (_core.Simulation, Paper
// A's penalty model, and _core.CdemSimulation, Paper B's model): a model
// behind the stepping interface (dda::Stepper), stepped without the GIL,
// in chunks between which signals are checked and the callback is called,
// and refused to other threads while it steps; its state saved to bytes
// and restored (copy and pickle).
//
// Stepping releases the GIL. A long step(n) or run() goes in chunks of
// whole steps sized to take about kSignalCheckSeconds of wall time each;
// between chunks it takes the GIL back to check for signals (Ctrl-C raises
// KeyboardInterrupt there, after a whole step: the simulation stays
// usable) and to call the callback. The chunks do not change the result:
// n steps give the same bits whether run as one advance or as many.
//
// While a step runs without the GIL, another Python thread's call on the
// same simulation raises RuntimeError instead of reading a state in motion.
#pragma once
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "bindings.hpp"
#include "dda/io/run.hpp"
#include "dda/io/scene_file.hpp"
#include "dda/state_bytes.hpp"
#include "dda/stepper.hpp"

namespace dda::py_bindings {

// Wall time between two signal checks in a long run, s: Ctrl-C is seen
// within this plus one step (well inside the 0.1 s a user waits; a check costs a
// GIL round trip, ~1 us, so 2 ms keeps it below 0.1 % of the run).
constexpr double kSignalCheckSeconds = 0.002;
// Largest chunk, steps (a cap on the adaptive size; any value gives the same bits).
constexpr std::int64_t kMaxChunk = std::int64_t{1} << 20;

class PyStepped {
 public:
  static constexpr double kNoEnd = std::numeric_limits<double>::infinity();  // run_steps: no end time
  virtual ~PyStepped() = default;

  // The model for reading (RuntimeError while another thread steps it).
  const Stepper& stepper() const {
    check_idle();
    return *stepper_;
  }
  const io::SceneFile& file() const { return *file_; }
  std::shared_ptr<io::SceneFile> file_ptr() const { return file_; }

  void check_idle() const {
    if (busy_.load(std::memory_order_acquire)) throw std::runtime_error(kBusy);
  }

  // Up to `count` steps without the GIL (the caller holds it), stopping
  // before a step when time() + dt/2 >= until; returns the steps taken.
  // With until = +inf: exactly `count` steps, as one Stepper::advance.
  std::int64_t advance_released(std::int64_t count, double until = kNoEnd) {
    if (busy_.exchange(true, std::memory_order_acq_rel)) throw std::runtime_error(kBusy);
    struct Done {
      std::atomic<bool>& b;
      ~Done() { b.store(false, std::memory_order_release); }
    } done{busy_};
    py::gil_scoped_release release;
    try {
      if (until == kNoEnd) {
        stepper_->advance(count);
        return count;
      }
      const double half = 0.5 * stepper_->dt();
      std::int64_t k = 0;
      for (; k < count && stepper_->time() + half < until; ++k) stepper_->step();
      return k;
    } catch (const SceneError& e) {
      // A limit of the scene found only in a step (the CDEM model's at a
      // touch): the run stops there, as `dda run` reports it.
      throw SimulationError(e.what());
    }
  }

  // Up to `total` steps, and none once time() + dt/2 >= until, in chunks of
  // about kSignalCheckSeconds: signals checked between chunks;
  // callback(self) after each step whose count is a multiple of `every`
  // and after the last one. Returns the steps taken.
  std::int64_t run_steps(const py::object& self, std::int64_t total, double until, std::int64_t every,
                         const py::object& callback) {
    using Clock = std::chrono::steady_clock;
    std::int64_t done = 0, chunk = 1;
    const bool call = !callback.is_none();
    while (done < total) {
      std::int64_t m = std::min(chunk, total - done);
      if (call) m = std::min(m, every - stepper_->step_count() % every);
      const Clock::time_point t0 = Clock::now();
      const std::int64_t took = advance_released(m, until);
      const double el = std::chrono::duration<double>(Clock::now() - t0).count();
      done += took;
      const bool last = done == total || !(stepper_->time() + 0.5 * stepper_->dt() < until);
      if (call && took > 0 && (stepper_->step_count() % every == 0 || last)) callback(self);
      if (PyErr_CheckSignals() != 0) throw py::error_already_set();
      if (last) break;
      // The next chunk: about kSignalCheckSeconds at this chunk's pace.
      const double per_step = el / static_cast<double>(m);
      const double want = per_step > 0.0 ? kSignalCheckSeconds / per_step : static_cast<double>(kMaxChunk);
      chunk = std::max<std::int64_t>(1, std::min<std::int64_t>({kMaxChunk, 2 * m, static_cast<std::int64_t>(want)}));
    }
    return done;
  }

  // The model's full state as bytes (copy and pickle); TypeError where the
  // model cannot save it.
  py::bytes save_state() const {
    check_idle();
    ByteWriter out;
    save(out);
    return py::bytes(out.bytes());
  }
  // Restores what save_state gave, into a model built from the same scene
  // (ValueError naming what does not fit).
  void restore_state(const py::bytes& state) {
    check_idle();
    const std::string_view b = state;
    ByteReader in(b.data(), b.size(), "the simulation's saved state");
    try {
      restore(in);
      in.expect_end();
    } catch (const StateError& e) {
      throw py::value_error(e.what());
    }
  }

 protected:
  static constexpr const char* kBusy = "the simulation is stepping in another thread";

  explicit PyStepped(std::shared_ptr<io::SceneFile> file) : file_(std::move(file)) {}
  virtual void save(ByteWriter& out) const = 0;
  virtual void restore(ByteReader& in) = 0;

  std::shared_ptr<io::SceneFile> file_;
  std::unique_ptr<Stepper> stepper_;  // set by the derived class's constructor
  std::atomic<bool> busy_{false};
};

// The methods both simulation classes bind alike: step(n), the time-series
// row of `dda run`, the scene file, the state bytes of copy and pickle.
template <class T>
void bind_stepping(py::class_<T>& c) {
  c.def(
       "step",
       [](T& s, std::int64_t n) {
         if (n == 1) {
           s.advance_released(1);  // the short path: no clock, no chunks
           return;
         }
         if (n < 0) throw py::value_error("step: n must be >= 0");
         s.run_steps(py::none(), n, PyStepped::kNoEnd, 1, py::none());
       },
       py::arg("n") = 1,
       "Advances n steps (GIL released; Ctrl-C stops a long call between steps with KeyboardInterrupt).")
      .def(
          "timeseries_row",
          [](const T& s, const std::vector<int>& tracked) {
            const Stepper& st = s.stepper();
            for (int i : tracked)
              if (i < 0 || i >= st.block_count()) throw py::index_error("tracked block out of range");
            py::list row;
            for (const io::CsvValue& v : io::timeseries_row(st, tracked)) {
              if (v.is_integer) row.append(py::int_(v.integer));
              else row.append(py::float_(v.number));
            }
            return row;
          },
          py::arg("tracked"),
          "The row `dda run` writes to timeseries.csv for these scene blocks (see timeseries_header).")
      .def_property_readonly("outline_count", [](const T& s) { return s.stepper().outline_count(); },
                             "Outlines of `dda run`'s snapshots: the scene's blocks, then (penalty model) the\n"
                             "boundary polygons.")
      .def(
          "outline",
          [](const T& s, int i) {
            const Stepper& st = s.stepper();
            if (i < 0 || i >= st.outline_count()) throw py::index_error("outline index out of range");
            return vertices_array(st.outline(i));
          },
          py::arg("i"), "(m, 2) outline i's vertices now, counter-clockwise (copy): a row of `dda run`'s snapshots.")
      .def_property_readonly("scene_file", &T::file_ptr)
      // The full state (copy and pickle: dda/_simulation.py).
      .def("_save_state", &T::save_state, "The full state as bytes: what a copy or a pickle holds.")
      .def("_restore_state", &T::restore_state, py::arg("state"),
           "Restores _save_state's bytes into a simulation of the same scene (ValueError if they do not fit).");
}

}  // namespace dda::py_bindings
