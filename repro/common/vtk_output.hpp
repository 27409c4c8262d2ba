// Block polygons as legacy VTK polydata (ASCII, "# vtk DataFile Version 3.0"),
// one file per snapshot, for ParaView / VisIt users. Header only, like
// sim_output.hpp (the repro_common library itself does not depend on dda).
//
// Written atomically: "<path>.tmp", then renamed, so a reader never sees half
// a file. Every number is checked finite first (a NaN is a failed run, never
// data): std::invalid_argument names the block and the field.
//
// Points are (x, y, 0); one POLYGON cell per block (scene blocks, then the
// boundary polygons if `with_boundaries`), vertices counter-clockwise. Cell
// data: block (index), fixed (0/1), speed (m/s, centroid), velocity (vector,
// m/s), displacement (vector, m, centroid since t = 0), rotation (rad, since
// t = 0, counter-clockwise).
#pragma once
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "dda/simulation.hpp"
#include "repro/common/csv.hpp"

namespace repro {

inline void write_vtk_polydata(const std::string& path, const dda::Simulation& sim, const std::string& title,
                               bool with_boundaries = false) {
  const int n = with_boundaries ? sim.block_count() : sim.scene_block_count();
  auto finite = [&](double v, int block, const char* what) {
    if (!std::isfinite(v))
      throw std::invalid_argument("write_vtk_polydata(" + path + "): block " + std::to_string(block) + " " + what +
                                  " is not finite");
    return v;
  };
  int points = 0;
  for (int i = 0; i < n; ++i) points += sim.polygon(i).count;
  std::string s;
  s.reserve(static_cast<std::size_t>(points) * 48 + static_cast<std::size_t>(n) * 160 + 512);
  std::string t = title;
  for (char& c : t)
    if (c == '\n' || c == '\r') c = ' ';
  if (t.size() > 255) t.resize(255);  // the legacy format limits the title line to 256 characters
  s += "# vtk DataFile Version 3.0\n" + t + "\nASCII\nDATASET POLYDATA\n";
  s += "POINTS " + std::to_string(points) + " double\n";
  for (int i = 0; i < n; ++i) {
    const dda::Polygon& p = sim.polygon(i);
    for (int k = 0; k < p.count; ++k)
      s += format_full(finite(p.vertex(k).x, i, "x")) + " " + format_full(finite(p.vertex(k).y, i, "y")) + " 0\n";
  }
  s += "POLYGONS " + std::to_string(n) + " " + std::to_string(n + points) + "\n";
  int next = 0;
  for (int i = 0; i < n; ++i) {
    const int c = sim.polygon(i).count;
    s += std::to_string(c);
    for (int k = 0; k < c; ++k) s += " " + std::to_string(next++);
    s += "\n";
  }
  s += "CELL_DATA " + std::to_string(n) + "\n";
  s += "SCALARS block int 1\nLOOKUP_TABLE default\n";
  for (int i = 0; i < n; ++i) s += std::to_string(i) + "\n";
  s += "SCALARS fixed int 1\nLOOKUP_TABLE default\n";
  for (int i = 0; i < n; ++i) s += std::string(sim.fixed(i) ? "1" : "0") + "\n";
  s += "SCALARS speed double 1\nLOOKUP_TABLE default\n";
  for (int i = 0; i < n; ++i) {
    const dda::Vec6& v = sim.velocity(i);
    s += format_full(finite(std::hypot(v[0], v[1]), i, "speed")) + "\n";
  }
  s += "SCALARS rotation double 1\nLOOKUP_TABLE default\n";
  for (int i = 0; i < n; ++i) s += format_full(finite(sim.displacement(i)[2], i, "rotation")) + "\n";
  s += "VECTORS velocity double\n";
  for (int i = 0; i < n; ++i) {
    const dda::Vec6& v = sim.velocity(i);
    s += format_full(finite(v[0], i, "vx")) + " " + format_full(finite(v[1], i, "vy")) + " 0\n";
  }
  s += "VECTORS displacement double\n";
  for (int i = 0; i < n; ++i) {
    const dda::Vec6& d = sim.displacement(i);
    s += format_full(finite(d[0], i, "dx")) + " " + format_full(finite(d[1], i, "dy")) + " 0\n";
  }

  make_parent_dirs(path);
  const std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "w");
  if (!f) throw std::runtime_error("write_vtk_polydata: cannot open " + tmp + " for writing");
  const bool ok = std::fwrite(s.data(), 1, s.size(), f) == s.size();
  const bool closed = std::fclose(f) == 0;
  std::error_code ec;
  if (!ok || !closed) {
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error("write_vtk_polydata: write error on " + tmp);
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error("write_vtk_polydata: cannot rename " + tmp + " to " + path);
  }
}

}  // namespace repro
