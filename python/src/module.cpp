// The Python module's compiled part, dda._core: the library's scenes,
// simulation and contact kernel bound with pybind11. The package dda
// (python/dda/) re-exports it with the pure-Python parts (scene building,
// errors, sweeps). Thin: every computation is the C++ library's.
#include <algorithm>
#include <cmath>
#include <string>

#include "bindings.hpp"
#include "dda/cdem/records.hpp"
#include "dda/io/scene_file.hpp"
#include "dda/simulation.hpp"

namespace dda::py_bindings {

std::vector<Vec2> points_from(const py::handle& obj, const char* what) {
  DoubleArray a;
  try {
    a = DoubleArray::ensure(obj);
  } catch (const py::error_already_set&) {
    a = DoubleArray();
  }
  if (!a || a.ndim() != 2 || a.shape(1) != 2)
    throw py::value_error(std::string(what) + ": expected an (n, 2) array of points");
  std::vector<Vec2> p(static_cast<std::size_t>(a.shape(0)));
  const auto r = a.unchecked<2>();
  for (py::ssize_t i = 0; i < a.shape(0); ++i) p[static_cast<std::size_t>(i)] = {r(i, 0), r(i, 1)};
  return p;
}

Polygon polygon_from(const py::handle& obj, const char* what) {
  const std::vector<Vec2> p = points_from(obj, what);
  const PolygonCheck c = validate_polygon(p.data(), static_cast<int>(p.size()));
  if (!c.ok()) {
    std::string m = std::string(what) + ": ";
    if (c.vertex >= 0) m += "vertex " + std::to_string(c.vertex) + ": ";
    m += describe(c.fault);
    if (c.fault == PolygonFault::kTooManyVertices)
      m += " (at most " + std::to_string(kMaxBlockVertices) + ", got " + std::to_string(p.size()) + ")";
    throw py::value_error(m);
  }
  return make_polygon(p.data(), static_cast<int>(p.size()));
}

py::array_t<double> vertices_array(PolygonView poly) {
  py::array_t<double> a = new_array(poly.count, 2);
  auto w = a.mutable_unchecked<2>();
  for (int i = 0; i < poly.count; ++i) w(i, 0) = poly.vertex(i).x, w(i, 1) = poly.vertex(i).y;
  return a;
}

py::array_t<double> vertices_array(const std::vector<Vec2>& points) {
  py::array_t<double> a = new_array(static_cast<py::ssize_t>(points.size()), 2);
  auto w = a.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i)
    w(static_cast<py::ssize_t>(i), 0) = points[i].x, w(static_cast<py::ssize_t>(i), 1) = points[i].y;
  return a;
}

namespace {

const char* reason_name(StopReason r) {
  switch (r) {
    case StopReason::kOther: return "other";
    case StopReason::kNonFinite: return "non_finite";
    case StopReason::kAreaCollapsed: return "area_collapsed";
    case StopReason::kStepMotion: return "step_motion";
    case StopReason::kEnergyGrowth: return "energy_growth";
    case StopReason::kEnergyBudget: return "energy_budget";
    case StopReason::kPenetration: return "penetration";
    case StopReason::kApproachEnergy: return "approach_energy";
  }
  return "other";
}

}  // namespace

void register_errors(py::module_& m) {
  // The raw form of a scene error: the library's message; dda/_scene.py
  // re-raises it as dda.SceneError with field and position.
  static py::exception<io::SceneFileError> raw(m, "RawSceneError", PyExc_ValueError);
  py::register_exception_translator([](std::exception_ptr p) {
    if (!p) return;
    try {
      std::rethrow_exception(p);
    } catch (const io::SceneFileError& e) {
      raw(e.what());
    } catch (const SceneError& e) {
      raw(e.what());
    } catch (const cdem::ContactError& e) {
      // Paper B's model: a contact it cannot resolve (node, its block, the other block).
      const py::object cls = py::module_::import("dda._errors").attr("SimulationError");
      const py::object pair = e.block >= 0 && e.other_block >= 0
                                  ? py::object(py::make_tuple(std::min(e.block, e.other_block),
                                                              std::max(e.block, e.other_block)))
                                  : py::object(py::none());
      const py::object block = e.block >= 0 ? py::object(py::int_(e.block)) : py::object(py::none());
      const py::object err = cls(e.what(), py::arg("reason") = reason_name(e.reason), py::arg("step") = e.step,
                                 py::arg("time") = e.time, py::arg("block") = block, py::arg("pair") = pair);
      err.attr("node") = e.node;
      err.attr("depth") = e.depth;
      PyErr_SetObject(cls.ptr(), err.ptr());
    } catch (const SimulationError& e) {
      // dda.SimulationError(message, reason=, step=, time=, block=, pair=).
      const py::object cls = py::module_::import("dda._errors").attr("SimulationError");
      const py::object pair =
          e.pair_a >= 0 ? py::object(py::make_tuple(e.pair_a, e.pair_b)) : py::object(py::none());
      const py::object block = e.block >= 0 ? py::object(py::int_(e.block)) : py::object(py::none());
      const py::object step = e.step >= 0 ? py::object(py::int_(e.step)) : py::object(py::none());
      const py::object time = std::isfinite(e.time) ? py::object(py::float_(e.time)) : py::object(py::none());
      const py::object err = cls(e.what(), py::arg("reason") = reason_name(e.reason), py::arg("step") = step,
                                 py::arg("time") = time, py::arg("block") = block, py::arg("pair") = pair);
      PyErr_SetObject(cls.ptr(), err.ptr());
    }
  });
}

}  // namespace dda::py_bindings

namespace py = pybind11;

PYBIND11_MODULE(_core, m) {
  namespace b = dda::py_bindings;
  m.doc() = "Compiled part of the dda package (use `import dda`).";
  b::register_errors(m);
  b::bind_scene(m);
  b::bind_simulation(m);
  b::bind_cdem(m);
  py::module_ kernel = m.def_submodule("kernel", "The contact kernel of Paper A on numpy polygons.");
  b::bind_kernel(kernel);
}
