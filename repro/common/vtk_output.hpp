// Block polygons as legacy VTK polydata (ASCII, "# vtk DataFile Version 3.0"),
// one file per snapshot, for ParaView / VisIt users: the drivers' form of the
// one VTK writer (dda_io's vtk_series.hpp, which `dda run` uses for its
// ParaView series). Header only; a driver that includes it links dda_io.
//
// Written atomically: "<path>.tmp", then renamed, so a reader never sees half
// a file. Every number is checked finite first (a NaN is a failed run, never
// data): dda::io::NonFiniteValue names the array and the block.
//
// Points are (x, y, 0); one POLYGON cell per block (scene blocks, then the
// boundary polygons if `with_boundaries`), vertices counter-clockwise. Cell
// data: block (index), fixed (0/1), speed (m/s, centroid), rotation (rad,
// since t = 0, counter-clockwise), velocity (vector, m/s), displacement
// (vector, m, centroid since t = 0): the first six arrays of
// dda::io::block_mesh.
#pragma once
#include <string>

#include "dda/io/csv.hpp"
#include "dda/io/vtk_dda.hpp"
#include "dda/io/vtk_series.hpp"
#include "dda/simulation.hpp"
#include "repro/common/csv.hpp"

namespace repro {

inline void write_vtk_polydata(const std::string& path, const dda::Simulation& sim, const std::string& title,
                               bool with_boundaries = false) {
  dda::io::VtkMesh mesh = dda::io::block_mesh(sim, with_boundaries);
  mesh.cell_data.resize(6);  // block, fixed, speed, rotation, velocity, displacement
  const std::string text = dda::io::legacy_vtk_text(mesh, title, "write_vtk_polydata(" + path + ")");
  make_parent_dirs(path);
  dda::io::write_file_atomic(path, text);
}

}  // namespace repro
