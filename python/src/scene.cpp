// _core.SceneFile: a scene read and validated by the scene-file reader
// (dda::io::parse_scene / load_scene_file, the same checks and messages as
// `dda check`), read-only. dda.Scene (dda/_scene.py) builds its JSON text.
#include <pybind11/stl.h>

#include <memory>

#include "bindings.hpp"
#include "dda/io/scene_file.hpp"

namespace dda::py_bindings {

void bind_scene(py::module_& m) {
  using io::SceneFile;
  py::class_<SceneFile, std::shared_ptr<SceneFile>> c(m, "SceneFile",
                                                      "A validated scene (read-only); made by dda.Scene.");
  m.def(
      "parse_scene",
      [](const std::string& text, const std::string& label, std::int64_t max_steps) {
        io::ReadOptions read;
        read.max_steps = max_steps;
        return std::make_shared<SceneFile>(io::parse_scene(text, label, read));
      },
      py::arg("text"), py::arg("label"), py::arg("max_steps") = 0,
      "Parses and validates scene JSON text (as `dda check`); `label` starts every message.");
  m.def(
      "load_scene_file",
      [](const std::string& path, std::int64_t max_steps) {
        io::ReadOptions read;
        read.max_steps = max_steps;
        return std::make_shared<SceneFile>(io::load_scene_file(path, read));
      },
      py::arg("path"), py::arg("max_steps") = 0, "Reads and validates a scene file (as `dda check`).");

  c.def("write_json", [](const SceneFile& f) { return io::write_scene(f); },
        "The scene as JSON text with every block's vertices written out (io::write_scene).")
      .def_property_readonly("name", [](const SceneFile& f) { return f.scene.name; })
      .def_property_readonly("model", [](const SceneFile& f) { return std::string(io::model_name(f.model)); },
                             "The contact model: \"penalty\" (Paper A) or \"cdem\" (Paper B).")
      .def_property_readonly("block_count", [](const SceneFile& f) { return f.scene.blocks.size(); },
                             "Blocks of the scene, listed then generated (boundaries not counted).")
      .def_property_readonly("boundary_count", [](const SceneFile& f) { return f.scene.boundaries.size(); })
      .def_property_readonly("dt", [](const SceneFile& f) { return f.scene.dt; },
                             "The scene's dt, s (unused when dt_fraction > 0: see Simulation.dt).")
      .def_property_readonly("dt_fraction", [](const SceneFile& f) { return f.scene.dt_fraction; })
      .def_property_readonly("duration", [](const SceneFile& f) { return f.scene.duration; })
      .def_property_readonly("max_steps", [](const SceneFile& f) { return f.max_steps; })
      .def_property_readonly("output_every", [](const SceneFile& f) { return f.output.every; })
      .def_property_readonly("snapshot_times", [](const SceneFile& f) { return f.output.snapshot_times; })
      .def_property_readonly("tracked_blocks",
                             [](const SceneFile& f) {
                               if (!f.output.tracked_blocks.empty()) return f.output.tracked_blocks;
                               std::vector<int> all(f.scene.blocks.size());
                               for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
                               return all;
                             })
      .def_property_readonly("block_names",
                             [](const SceneFile& f) {
                               std::vector<std::string> n;
                               for (const BlockSpec& b : f.scene.blocks) n.push_back(b.name);
                               return n;
                             })
      .def_property_readonly(
          "generated",
          [](const SceneFile& f) {
            py::list out;
            for (const io::GeneratedRegion& g : f.generated)
              out.append(py::dict(py::arg("first_block") = g.first_block, py::arg("count") = g.count,
                                  py::arg("dropped") = g.dropped, py::arg("dropped_area") = g.dropped_area));
            return out;
          },
          "Per generated region: its first block, block count, slivers dropped and their area (m^2).")
      .def(
          "block_vertices",
          [](const SceneFile& f) {
            std::vector<Vec2> v;
            std::vector<long> offsets{0};
            for (const BlockSpec& b : f.scene.blocks) {
              v.insert(v.end(), b.vertices.begin(), b.vertices.end());
              offsets.push_back(static_cast<long>(v.size()));
            }
            return py::make_tuple(vertices_array(v), py::array_t<long>(static_cast<py::ssize_t>(offsets.size()),
                                                                       offsets.data()));
          },
          "(vertices (V, 2), offsets (n + 1,)): block i's vertices at t = 0 are "
          "vertices[offsets[i]:offsets[i + 1]] (listed, then generated blocks).");
}

}  // namespace dda::py_bindings
