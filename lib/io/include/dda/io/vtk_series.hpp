// ParaView / VisIt output, model-neutral: a VtkMesh is points in the plane,
// cells as lists of point indices (polygons, triangles, single points) and
// named per-point and per-cell arrays. The adapters that turn a model's state
// into a VtkMesh live beside it (vtk_dda.hpp: Paper A's blocks and contacts;
// vtk_cdem.hpp: Paper B's elements, nodes and clone nodes); this file only
// writes.
//
// Formats:
//  * VTK XML unstructured grid (.vtu, ASCII, VTKFile version 1.0), one per
//    frame, with the frame's time as field data `TimeValue`; a VtkSeries
//    collects them in a ParaView collection file (.pvd) with their times.
//  * legacy VTK polydata (.vtk, "# vtk DataFile Version 3.0", ASCII), the
//    repro drivers' per-snapshot files (repro/common/vtk_output.hpp).
// Numbers are written in shortest round-trip form (format_number), so a
// value read back is the double that was written; integer arrays as
// integers. Every value is checked finite before anything is written
// (NonFiniteValue names the array and the tuple: a NaN is a failed run,
// never data). Files are written through "<file>.tmp" and renamed into place
// when complete (write_file_atomic), so a reader never sees half a file.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "dda/vec2.hpp"

namespace dda::io {

// One named array: `components` values per tuple (per point or per cell),
// tuple-major. Vectors are written with 3 components (z = 0) so that
// ParaView can draw them as glyphs.
struct VtkArray {
  std::string name;
  int components = 1;
  bool integer = false;       // Int64 in .vtu, int in .vtk; each value must be a whole number
  std::vector<double> values; // components x tuples
  std::vector<std::string> component_names;  // empty, or one per component (ParaView shows them)
};

struct VtkMesh {
  std::vector<Vec2> points;       // written as (x, y, 0)
  std::vector<int> connectivity;  // the point indices of cell 0, then of cell 1, ...
  std::vector<int> offsets{0};    // cell c is connectivity[offsets[c] .. offsets[c + 1])
  std::vector<VtkArray> point_data, cell_data;

  std::size_t point_count() const { return points.size(); }
  std::size_t cell_count() const { return offsets.empty() ? 0 : offsets.size() - 1; }
  // Appends a cell of the given points (indices into `points`).
  void add_cell(const int* first, int count);
  // Appends a point and a one-point cell (VTK_VERTEX) holding it.
  void add_vertex(Vec2 p);
  // The array named `name`, or null.
  const VtkArray* cell_array(const std::string& name) const;
  const VtkArray* point_array(const std::string& name) const;
};

// Shape checks: every cell index in range, every cell non-empty, array sizes
// matching the counts, component names matching the components, integer
// arrays whole; std::invalid_argument otherwise (a caller's bug). Values:
// NonFiniteValue naming `label`, the array and the tuple.
void check_mesh(const VtkMesh& mesh, const std::string& label);

// VTK XML unstructured grid text. Cell types from the cell's size: 1 point
// VTK_VERTEX, 2 VTK_LINE, 3 VTK_TRIANGLE, more VTK_POLYGON. `time` is
// written as the field data TimeValue.
std::string vtu_text(const VtkMesh& mesh, double time, const std::string& label);

// Legacy VTK polydata text: POINTS, POLYGONS (every cell, whatever its
// size), CELL_DATA then POINT_DATA (1-component arrays as SCALARS with the
// default lookup table, 3-component ones as VECTORS). `title` is the second
// line (line breaks become spaces; cut to 255 characters, the format's limit).
std::string legacy_vtk_text(const VtkMesh& mesh, const std::string& title, const std::string& label);

// A time series of .vtu files and the .pvd collection that lists them:
// <dir>/<name>_<frame>.vtu (frame = 000000, 000001, ...) and <dir>/<name>.pvd.
class VtkSeries {
 public:
  // Creates `dir` if missing (OutputError if it cannot).
  VtkSeries(std::string dir, std::string name);
  // Continues a series whose first times.size() frames are on disk (a
  // resumed run): the next frame is numbered after them.
  VtkSeries(std::string dir, std::string name, std::vector<double> times);
  // Writes the next frame (atomically) and records its time. Throws
  // NonFiniteValue (nothing written) or OutputError.
  void add(double time, const VtkMesh& mesh);
  // Writes <dir>/<name>.pvd (atomically) listing the frames written so far.
  void write_collection() const;

  std::size_t frames() const { return times_.size(); }
  const std::vector<double>& times() const { return times_; }
  std::string collection_path() const;
  std::string frame_file(std::size_t frame) const { return frame_file(name_, frame); }  // the file name (without dir)
  static std::string frame_file(const std::string& name, std::size_t frame);

 private:
  std::string dir_, name_;
  std::vector<double> times_;
};

}  // namespace dda::io
