// Paper A Sect. 5.2: one small-angle run and the point-symmetry row, shared by
// the driver (small_angles.cpp) and the negative control
// (repro/common/test_controls.cpp).
#pragma once
#include <algorithm>
#include <string>

#include "dda/robustness_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/common/claims.hpp"
#include "repro/common/cli.hpp"
#include "repro/common/csv.hpp"
#include "repro/common/sim_output.hpp"

namespace small_angles {
using dda::Vec2;
using repro::format_short;

struct Result {
  dda::paper::RunStats stats;
  double asymmetry = 0.0;   // largest point-symmetry error, m
  bool apart_at_end = false;  // no contact between the triangles at the end
  Vec2 v0_end{};
  double rotation_end = 0.0;
  double seconds = 0.0;
};

inline Result run(const dda::paper::SmallAngleTriangles& st, repro::CsvWriter* traces, repro::CsvWriter* snaps) {
  const repro::Progress clock("run");
  dda::Simulation sim(st.scene);
  dda::paper::RunMonitor mon(sim, 0, 1);
  Result r;
  auto record = [&] {
    const double a = dda::paper::point_symmetry_error(sim.polygon(0), sim.polygon(1), st.centre);
    r.asymmetry = std::max(r.asymmetry, a);
    if (traces && sim.step_count() % 5 == 0) {
      const Vec2 p0 = sim.polygon(0).vertex(st.apex[0]), p1 = sim.polygon(1).vertex(st.apex[1]);
      const dda::Energy e = sim.energy();
      traces->row({sim.time(), p0.x, p0.y, p1.x, p1.y, sim.centroid(0).x, sim.centroid(0).y, sim.centroid(1).x,
                   sim.centroid(1).y, a, e.total(), e.contact,
                   dda::paper::overlap_thickness(sim.polygon(0), sim.polygon(1))});
    }
  };
  if (snaps) repro::write_snapshot(*snaps, sim);
  record();
  while (sim.time() < st.scene.duration - 0.5 * sim.dt()) {
    sim.step();
    mon.sample();
    record();
  }
  if (snaps) repro::write_snapshot(*snaps, sim);
  r.stats = mon.stats();
  r.v0_end = {sim.velocity(0)[0], sim.velocity(0)[1]};
  r.apart_at_end = sim.contacts().empty();
  r.rotation_end = sim.displacement(0)[2];
  r.seconds = clock.elapsed_seconds();
  return r;
}

// Point symmetry to 1e-9 m (1e-9 of the block size: round-off differences in
// the order of operations of CP and TP may grow through the impact but stay
// far below anything visible).
constexpr double kSymmetryTol = 1e-9;  // m

inline repro::Claim symmetry_row(const Result& r, const std::string& geo) {
  repro::Claim c{"5.2", "the two triangles move point-symmetrically about the collision centre" + geo,
                 "Fig. 16: 'the two triangles move symmetrically regarding the collision centroid'",
                 "max over 0.2 s of |v0_k + v1_k - 2c| (every vertex) = " + format_short(r.asymmetry, 3) + " m",
                 "< " + format_short(kSymmetryTol) + " m", r.asymmetry < kSymmetryTol};
  c.control = "repro_controls: 5.2 point symmetry: FAIL when one triangle is 1 % faster";
  return c;
}

}  // namespace small_angles
