// Writes a ParaView series of Paper B's two-prisms scene (Sect. 6, built in
// C++: dda::cdem::two_prisms, the sub-model subdivision) through the Paper B
// adapter, and beside it CSV files of what the model itself reports, for
// vtk_readback.py to compare after VTK's reader has read the series:
//   OUT/vtk/elements.pvd, elements_*.vtu   element_mesh
//   OUT/vtk/clones.pvd, clones_*.vtu       contact_mesh
//   OUT/elements.csv  frame,time,block,fine,x0,y0,x1,y1,x2,y2,sxx,syy,sxy   (Model::snapshot())
//   OUT/clones.csv    frame,time,node,x,y,fx,fy,nx,ny                        (Model::clones())
// Frames at t = 0, every 0.01 s, and at each step from 0.333 s to 0.342 s
// (the touch, the clone with its sub-model, the separation).
// Usage: io_vtk_cdem_series OUT
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <string>

#include "dda/cdem/scenes.hpp"
#include "dda/io/csv.hpp"
#include "dda/io/vtk_cdem.hpp"
#include "dda/io/vtk_series.hpp"

int main(int argc, char** argv) try {
  if (argc != 2) {
    std::fprintf(stderr, "usage: io_vtk_cdem_series OUT\n");
    return 2;
  }
  const std::string out = argv[1];
  std::filesystem::create_directories(out);
  dda::cdem::Model model(dda::cdem::two_prisms());
  dda::io::VtkSeries elements(out + "/vtk", "elements"), clones(out + "/vtk", "clones");
  dda::io::CsvFile tris(out + "/elements.csv",
                        {"frame", "time", "block", "fine", "x0", "y0", "x1", "y1", "x2", "y2", "sxx", "syy", "sxy"});
  dda::io::CsvFile ties(out + "/clones.csv", {"frame", "time", "node", "x", "y", "fx", "fy", "nx", "ny"});
  auto frame = [&] {
    const long long k = static_cast<long long>(elements.frames());
    const double t = model.time();
    for (const dda::cdem::Snapshot::Tri& tri : model.snapshot().tris)
      tris.row({k, t, tri.block, tri.fine ? 1 : 0, tri.x[0].x, tri.x[0].y, tri.x[1].x, tri.x[1].y, tri.x[2].x,
                tri.x[2].y, tri.stress[0], tri.stress[1], tri.stress[2]});
    for (const dda::cdem::CloneView& c : model.clones())
      ties.row({k, t, c.main_node, c.point.x, c.point.y, c.force.x, c.force.y, c.normal.x, c.normal.y});
    elements.add(t, dda::io::element_mesh(model));
    clones.add(t, dda::io::contact_mesh(model));
  };
  const double dt = model.dt();
  const auto every = static_cast<std::int64_t>(std::llround(0.01 / dt));
  frame();
  while (model.time() + 0.5 * dt < model.scene().duration) {
    model.step();
    const double t = model.time();
    if (model.step_count() % every == 0 || (t > 0.333 - 0.5 * dt && t < 0.342 + 0.5 * dt)) frame();
  }
  elements.write_collection();
  clones.write_collection();
  tris.commit();
  ties.commit();
  std::printf("io_vtk_cdem_series: %zu frames, %zu element rows, %zu clone rows in %s\n", elements.frames(),
              tris.rows(), ties.rows(), out.c_str());
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "io_vtk_cdem_series: %s\n", e.what());
  return 1;
}
