// _core.Simulation: Paper A's model (dda::Simulation) stepped from Python,
// its state as numpy arrays. dda.Simulation (dda/_simulation.py) derives
// from it. Stepping, the GIL and other threads: stepping.hpp.
#include <pybind11/functional.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "bindings.hpp"
#include "dda/io/run.hpp"
#include "dda/io/scene_file.hpp"
#include "dda/simulation.hpp"
#include "dda/stepper.hpp"
#include "stepping.hpp"

namespace dda::py_bindings {

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// Steps from the simulation's current count until time() + dt/2 >= until:
// the loop of `dda run` (lib/io/src/run.cpp), with time() = steps * dt.
std::int64_t steps_until(const Simulation& s, double until) {
  if (!std::isfinite(until)) throw py::value_error("until: must be a finite time, s");
  const double dt = s.dt();
  const std::int64_t now = s.step_count();
  auto reached = [&](std::int64_t k) { return !(static_cast<double>(k) * dt + 0.5 * dt < until); };
  if (reached(now)) return 0;
  const double guess = std::ceil((until - 0.5 * dt) / dt);
  if (guess > 9.0e18) throw py::value_error("until: too many steps");
  std::int64_t k = std::max(now + 1, static_cast<std::int64_t>(guess));
  while (k > now + 1 && reached(k - 1)) --k;
  while (!reached(k)) ++k;
  return k - now;
}

class PySimulation final : public PyStepped {
 public:
  PySimulation(std::shared_ptr<io::SceneFile> file, int threads, const std::string& label) : PyStepped(std::move(file)) {
    if (threads < 1) throw py::value_error("threads: must be >= 1");
    if (file_->model != io::ContactModel::kPenalty)
      throw py::value_error(label + ": model: \"" + io::model_name(file_->model) +
                            "\": Paper B's model runs in dda.CdemSimulation (dda.Simulation makes one for such a scene)");
    {
      py::gil_scoped_release release;  // a settle (damping.settle_time) may take long
      auto s = std::make_unique<SimulationStepper>(Simulation(file_->scene));
      sim_ = &s->simulation();
      stepper_ = std::move(s);
    }
    // As `dda run`: with dt_fraction > 0 the step count is known only now.
    io::check_step_count(*file_, sim_->dt(), label);
    sim_->set_threads(threads);
  }

  // The simulation for reading (RuntimeError while another thread steps it).
  const Simulation& read() const {
    check_idle();
    return *sim_;
  }
  Simulation& write() {
    check_idle();
    return *sim_;
  }

 private:
  // The full state (Simulation::save_state): blocks, near pairs with their
  // contact and friction history, the guards' and budget's accumulators, the clock.
  void save(ByteWriter& out) const override { sim_->save_state(out); }
  void restore(ByteReader& in) override { sim_->restore_state(in); }

  Simulation* sim_ = nullptr;  // stepper_'s simulation
};

// The live state as a read-only (n, cols) view: `first` points at block 0's
// row, rows `stride` doubles apart; the view keeps `owner` alive.
py::array read_only_view(const double* first, py::ssize_t n, py::ssize_t cols, py::ssize_t stride,
                         const py::handle& owner) {
  py::array a(py::dtype::of<double>(), {n, cols},
              {static_cast<py::ssize_t>(stride * sizeof(double)), static_cast<py::ssize_t>(sizeof(double))}, first,
              owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

// A read-only (n, Cols) view of the per-block rows row(sim, i) points at,
// which the simulation keeps one after another (a std::vector per state).
template <int Cols, class Row>
py::array state_view(const py::object& self, Row row) {
  const Simulation& sim = self.cast<const PySimulation&>().read();
  const int n = sim.block_count();
  if (n > 1 && row(sim, n - 1) != row(sim, 0) + Cols * (n - 1))
    throw std::logic_error("the state is not stored as one array: no view");
  return read_only_view(n > 0 ? row(sim, 0) : nullptr, n, Cols, Cols, self);
}

// A property getter: the per-block rows f(sim, i) of the simulation, (n, Cols)
// (a copy).
template <int Cols, class F>
auto per_block(F f) {
  return [f](const PySimulation& s) {
    const Simulation& sim = s.read();
    const int n = sim.block_count();
    py::array_t<double> a = new_array(n, Cols);
    auto w = a.mutable_unchecked<2>();
    for (int i = 0; i < n; ++i) {
      const auto row = f(sim, i);
      for (int c = 0; c < Cols; ++c) w(i, c) = row[c];
    }
    return a;
  };
}

// A property getter: the per-block values f(sim, i), (n,) (a copy).
template <class F>
auto per_block_scalar(F f) {
  return [f](const PySimulation& s) {
    const Simulation& sim = s.read();
    const int n = sim.block_count();
    py::array_t<double> a(n);
    auto w = a.mutable_unchecked<1>();
    for (int i = 0; i < n; ++i) w(i) = f(sim, i);
    return a;
  };
}

// The contacts of the last force evaluation as arrays (one row a contact).
struct Contacts {
  py::array_t<int> pairs;            // (k, 2): contact polygon, target polygon
  py::array_t<double> normal_forces;  // (k, 2) on the contact polygon, N/m
  py::array_t<double> shear_forces;   // (k, 2) friction force on the contact polygon, N/m
  py::array_t<double> points;         // (k, 2) loading points pg, m
  py::array_t<double> couples;        // (k,) pure moments on the contact polygon, N m/m
  py::array_t<double> ip_areas;       // (k,) m^2
  py::array_t<double> ip_lengths;     // (k,) contact lengths (half the IP perimeter), m
  py::array_t<bool> sliding;          // (k,)
  py::array_t<double> ip_vertices;    // (V, 2) the intersection polygons, one after another
  py::array_t<long> ip_offsets;       // (k + 1,): contact j's are ip_vertices[ip_offsets[j]:ip_offsets[j + 1]]
};

Contacts make_contacts(const Simulation& s) {
  const std::vector<ContactInfo>& info = s.contacts();
  const auto k = static_cast<py::ssize_t>(info.size());
  Contacts c;
  c.pairs = py::array_t<int>(std::vector<py::ssize_t>{k, 2});
  c.normal_forces = new_array(k, 2);
  c.shear_forces = new_array(k, 2);
  c.points = new_array(k, 2);
  c.couples = py::array_t<double>(k);
  c.ip_areas = py::array_t<double>(k);
  c.ip_lengths = py::array_t<double>(k);
  c.sliding = py::array_t<bool>(k);
  std::vector<Vec2> ip_points;
  std::vector<long> offsets{0};
  auto pairs = c.pairs.mutable_unchecked<2>();
  auto fn = c.normal_forces.mutable_unchecked<2>(), ft = c.shear_forces.mutable_unchecked<2>(),
       pg = c.points.mutable_unchecked<2>();
  auto couple = c.couples.mutable_unchecked<1>(), area = c.ip_areas.mutable_unchecked<1>(),
       len = c.ip_lengths.mutable_unchecked<1>();
  auto slide = c.sliding.mutable_unchecked<1>();
  for (py::ssize_t j = 0; j < k; ++j) {
    const ContactInfo& ci = info[static_cast<std::size_t>(j)];
    pairs(j, 0) = ci.cp, pairs(j, 1) = ci.tp;
    fn(j, 0) = ci.normal_force.x, fn(j, 1) = ci.normal_force.y;
    ft(j, 0) = ci.tangential_force.x, ft(j, 1) = ci.tangential_force.y;
    pg(j, 0) = ci.point.x, pg(j, 1) = ci.point.y;
    couple(j) = ci.couple, area(j) = ci.ip_area, len(j) = ci.ip_length, slide(j) = ci.sliding;
    // The step's intersection polygon: the same kernel call on the same
    // polygons with the same pair tolerance (overlap_and_intersection's IP
    // vertices are intersection_polygon's).
    const PolygonView a = s.polygon_view(ci.cp), b = s.polygon_view(ci.tp);
    const Polygon ip = intersection_polygon(a, b, pair_tolerance(a, b));
    for (int v = 0; v < ip.count; ++v) ip_points.push_back(ip.vertex(v));
    offsets.push_back(static_cast<long>(ip_points.size()));
  }
  c.ip_vertices = vertices_array(ip_points);
  c.ip_offsets = py::array_t<long>(static_cast<py::ssize_t>(offsets.size()), offsets.data());
  return c;
}

}  // namespace

void bind_simulation(py::module_& m) {
  py::class_<Energy>(m, "Energy", "The energy budget of the state, J/m (dda::Energy).")
      .def_readonly("kinetic", &Energy::kinetic)
      .def_readonly("gravity", &Energy::gravity, "-sum m g . x_c, relative to the origin")
      .def_readonly("strain", &Energy::strain)
      .def_readonly("contact", &Energy::contact, "penalty energy stored in the overlaps")
      .def_readonly("friction_spring", &Energy::friction_spring)
      .def_readonly("dissipated", &Energy::dissipated, "work taken out by friction and damping since t = 0")
      .def_readonly("initial", &Energy::initial, "total at t = 0")
      .def_property_readonly("total", &Energy::total, "kinetic + gravity + strain + contact + friction_spring")
      .def_property_readonly("balance_error", &Energy::balance_error, "total + dissipated - initial")
      .def("as_dict",
           [](const Energy& e) {
             return py::dict(py::arg("kinetic") = e.kinetic, py::arg("gravity") = e.gravity,
                             py::arg("strain") = e.strain, py::arg("contact") = e.contact,
                             py::arg("friction_spring") = e.friction_spring, py::arg("total") = e.total(),
                             py::arg("dissipated") = e.dissipated, py::arg("initial") = e.initial,
                             py::arg("balance_error") = e.balance_error());
           })
      .def("__repr__", [](const Energy& e) {
        char buf[320];
        std::snprintf(buf, sizeof buf,
                      "Energy(kinetic=%.6g, gravity=%.6g, strain=%.6g, contact=%.6g, friction_spring=%.6g, "
                      "dissipated=%.6g, balance_error=%.6g)",
                      e.kinetic, e.gravity, e.strain, e.contact, e.friction_spring, e.dissipated, e.balance_error());
        return std::string(buf);
      });

  py::class_<Contacts>(m, "Contacts",
                       "The contacts of the last force evaluation, one row each (copies).\n"
                       "pairs (k, 2): contact polygon, target polygon; normal_forces, shear_forces (k, 2):\n"
                       "on the contact polygon, N/m; points (k, 2): loading points; couples (k,): N m/m;\n"
                       "ip_areas, ip_lengths, sliding (k,); ip_vertices (V, 2) with ip_offsets (k + 1,):\n"
                       "the intersection polygons (intersection_polygon(j) gives contact j's).")
      .def_readonly("pairs", &Contacts::pairs)
      .def_readonly("normal_forces", &Contacts::normal_forces)
      .def_readonly("shear_forces", &Contacts::shear_forces)
      .def_readonly("points", &Contacts::points)
      .def_readonly("couples", &Contacts::couples)
      .def_readonly("ip_areas", &Contacts::ip_areas)
      .def_readonly("ip_lengths", &Contacts::ip_lengths)
      .def_readonly("sliding", &Contacts::sliding)
      .def_readonly("ip_vertices", &Contacts::ip_vertices)
      .def_readonly("ip_offsets", &Contacts::ip_offsets)
      .def("__len__", [](const Contacts& c) { return c.pairs.shape(0); })
      .def("intersection_polygon", [](const Contacts& c, py::ssize_t j) {
        if (j < 0 || j >= c.pairs.shape(0)) throw py::index_error("contact index out of range");
        const long* o = c.ip_offsets.data();
        return c.ip_vertices[py::slice(o[j], o[j + 1], 1)];
      });

  py::class_<PySimulation> c(m, "Simulation");
  c.def(py::init<std::shared_ptr<io::SceneFile>, int, const std::string&>(), py::arg("scene_file"),
        py::arg("threads") = 1, py::arg("label") = "<scene>")
      // --- stepping (and step(n): bind_stepping) ---
      .def(
          "_run",
          [](py::object self, double until, std::int64_t every, py::object callback) {
            PySimulation& s = self.cast<PySimulation&>();
            if (every < 1) throw py::value_error("every: must be >= 1");
            return s.run_steps(self, steps_until(s.read(), until), PyStepped::kNoEnd, every, callback);
          },
          py::arg("until"), py::arg("every"), py::arg("callback"))
      .def_property_readonly("time", [](const PySimulation& s) { return s.read().time(); }, "Simulated time, s.")
      .def_property_readonly("step_count", [](const PySimulation& s) { return s.read().step_count(); })
      .def_property_readonly("dt", [](const PySimulation& s) { return s.read().dt(); }, "The step used, s.")
      .def_property(
          "threads", [](const PySimulation& s) { return s.read().threads(); },
          [](PySimulation& s, int n) {
            if (n < 1) throw py::value_error("threads: must be >= 1");
            s.write().set_threads(n);
          },
          "Threads of a step (OpenMP); results are bit-identical for any count.")
      .def_property_readonly("predicted_critical_step",
                             [](const PySimulation& s) { return s.read().predicted_critical_step(); })
      .def("critical_time_step", [](const PySimulation& s) { return s.read().critical_time_step(); },
           "2 / omega_max bound with the current contacts, s.")
      // --- sizes ---
      .def_property_readonly("block_count", [](const PySimulation& s) { return s.read().block_count(); },
                             "Polygons: the scene's blocks, then one per boundary segment.")
      .def_property_readonly("scene_block_count", [](const PySimulation& s) { return s.read().scene_block_count(); })
      // --- state, copies ---
      .def_property_readonly("centroids",
                             per_block<2>([](const auto& sim, int i) {
                               const Vec2 c = sim.centroid(i);
                               return std::array<double, 2>{c.x, c.y};
                             }),
                             "(n, 2) block centroids, m (copy).")
      .def_property_readonly("velocities",
                             per_block<2>([](const auto& sim, int i) {
                               return std::array<double, 2>{sim.velocity(i)[0], sim.velocity(i)[1]};
                             }),
                             "(n, 2) centroid velocities, m/s (copy).")
      .def_property_readonly("spins", per_block_scalar([](const auto& sim, int i) { return sim.velocity(i)[2]; }),
                             "(n,) angular velocities, rad/s (copy).")
      .def_property_readonly("rotations",
                             per_block_scalar([](const auto& sim, int i) { return sim.displacement(i)[2]; }),
                             "(n,) rotations accumulated since t = 0, rad (copy).")
      .def_property_readonly("velocity_dofs", per_block<6>([](const auto& sim, int i) { return sim.velocity(i); }),
                             "(n, 6) velocity DOFs (u0, v0, r0, ex, ey, gxy rates) (copy).")
      .def_property_readonly("displacements", per_block<6>([](const auto& sim, int i) { return sim.displacement(i); }),
                             "(n, 6) displacement DOFs accumulated since t = 0 (copy).")
      .def_property_readonly("stresses", per_block<3>([](const auto& sim, int i) { return sim.stress(i); }),
                             "(n, 3) stresses (sx, sy, txy), Pa (copy).")
      .def_property_readonly("masses", per_block_scalar([](const auto& sim, int i) {
                               return i >= sim.scene_block_count() || sim.fixed(i) ? 0.0 : sim.mass(i);
                             }),
                             "(n,) masses, kg/m (0 for fixed blocks and boundaries, as run.json) (copy).")
      .def_property_readonly("areas", per_block_scalar([](const auto& sim, int i) { return sim.area(i); }),
                             "(n,) areas, m^2 (copy).")
      .def_property_readonly("potential_lengths",
                             per_block_scalar([](const auto& sim, int i) { return sim.potential_length(i); }),
                             "(n,) H of each block's potential, m (copy).")
      .def_property_readonly(
          "fixed", [](const PySimulation& s) {
            const Simulation& sim = s.read();
            py::array_t<bool> a(sim.block_count());
            auto w = a.mutable_unchecked<1>();
            for (int i = 0; i < sim.block_count(); ++i) w(i) = sim.fixed(i);
            return a;
          }, "(n,) fixed blocks and boundaries (copy).")
      .def_property_readonly(
          "vertices", [](const PySimulation& s) {
            const Simulation& sim = s.read();
            std::vector<Vec2> v;
            for (int i = 0; i < sim.block_count(); ++i) {
              const PolygonView p = sim.polygon_view(i);
              v.insert(v.end(), p.v, p.v + p.count);
            }
            return vertices_array(v);
          }, "(V, 2) every polygon's vertices, one block after another (copy); see vertex_offsets.")
      .def_property_readonly(
          "vertex_offsets", [](const PySimulation& s) {
            const Simulation& sim = s.read();
            py::array_t<long> a(sim.block_count() + 1);
            auto w = a.mutable_unchecked<1>();
            w(0) = 0;
            for (int i = 0; i < sim.block_count(); ++i) w(i + 1) = w(i) + sim.polygon_view(i).count;
            return a;
          }, "(n + 1,): block i's vertices are vertices[vertex_offsets[i]:vertex_offsets[i + 1]].")
      .def("polygon", [](const PySimulation& s, int i) {
            const Simulation& sim = s.read();
            if (i < 0 || i >= sim.block_count()) throw py::index_error("block index out of range");
            return vertices_array(sim.polygon_view(i));
          }, py::arg("i"), "(m, 2) block i's vertices, counter-clockwise (copy).")
      .def_property_readonly("momentum", [](const PySimulation& s) {
            const Vec2 p = s.read().momentum();
            py::array_t<double> a(2);
            a.mutable_at(0) = p.x, a.mutable_at(1) = p.y;
            return a;
          }, "(2,) momentum of the moving blocks, kg m/s per m.")
      .def("energy", [](const PySimulation& s) { return s.read().energy(); },
           "The energy budget's terms now (dda.Energy; recomputes the contact energy).")
      .def("contacts", [](const PySimulation& s) { return make_contacts(s.read()); },
           "The contacts of the last force evaluation (dda.Contacts, copies).")
      .def("contact_count", [](const PySimulation& s) { return s.read().contact_count(); },
           "len(contacts()), counted without building them (cheap enough for every step).")
      // --- state, read-only views ---
      .def("velocity_dofs_view",
           [](const py::object& self) {
             return state_view<6>(self, [](const Simulation& s, int i) { return &s.velocity(i)[0]; });
           },
           "(n, 6) velocity DOFs as a READ-ONLY VIEW of the simulation's state, no copy: it shows the\n"
           "values of the current step and changes in place at the next step (copy it to keep them).")
      .def("displacements_view",
           [](const py::object& self) {
             return state_view<6>(self, [](const Simulation& s, int i) { return &s.displacement(i)[0]; });
           },
           "(n, 6) displacement DOFs as a READ-ONLY VIEW (see velocity_dofs_view).")
      .def("stresses_view",
           [](const py::object& self) {
             return state_view<3>(self, [](const Simulation& s, int i) { return &s.stress(i)[0]; });
           },
           "(n, 3) stresses as a READ-ONLY VIEW (see velocity_dofs_view).");
  bind_stepping(c);

  m.def("timeseries_header",
        [](const std::vector<int>& tracked, bool rotation) { return io::timeseries_header(tracked, rotation); },
        py::arg("tracked"), py::arg("rotation") = true,
        "Column names of `dda run`'s timeseries.csv for these scene blocks; rotation=False: without\n"
        "each block's rot and spin (Paper B's model, dda.CdemSimulation).");
  m.def("format_number", &io::format_number, "Shortest decimal text that reads back to the same double.");

  m.def(
      "_time_cpp_steps",
      [](PySimulation& s, std::int64_t n) {
        // Benchmark helper: n calls of Simulation::step() in C++, wall s.
        Simulation& sim = s.write();
        py::gil_scoped_release release;
        const Clock::time_point t0 = Clock::now();
        for (std::int64_t k = 0; k < n; ++k) sim.step();
        return seconds(Clock::now() - t0);
      },
      py::arg("sim"), py::arg("n"));
}

}  // namespace dda::py_bindings
