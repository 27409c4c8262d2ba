// Shared helpers of the Python module's C++ part (_core): numpy <-> Vec2
// conversions and the translation of the library's exceptions.
//
// Errors: dda::SimulationError becomes dda.SimulationError (with the reason,
// step, time, block and pair as attributes); dda::io::SceneFileError and
// dda::SceneError become _core.RawSceneError with the library's message,
// which the Python layer (dda/_scene.py) turns into dda.SceneError with the
// field and position (it knows the label the message starts with).
#pragma once
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "dda/polygon.hpp"
#include "dda/vec2.hpp"

namespace dda::py_bindings {

namespace py = pybind11;

using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

// A new (rows, cols) float64 array (C order), uninitialised.
inline py::array_t<double> new_array(py::ssize_t rows, py::ssize_t cols) {
  return py::array_t<double>(std::vector<py::ssize_t>{rows, cols});
}

// Points given as an (n, 2) array (or a sequence of pairs); `what` names
// the argument in the message of a ValueError.
std::vector<Vec2> points_from(const py::handle& obj, const char* what);

// A polygon argument of the kernel functions: an (n, 2) array of CCW
// vertices of a convex block, checked with dda::validate_polygon (ValueError
// naming the argument, the vertex and the reason).
Polygon polygon_from(const py::handle& obj, const char* what);

// The vertices of a polygon as an (n, 2) array.
py::array_t<double> vertices_array(PolygonView poly);
py::array_t<double> vertices_array(const std::vector<Vec2>& points);

// Registers the exception translators (called once from the module init).
void register_errors(py::module_& m);

void bind_scene(py::module_& m);
void bind_simulation(py::module_& m);
void bind_cdem(py::module_& m);
void bind_kernel(py::module_& m);

}  // namespace dda::py_bindings
