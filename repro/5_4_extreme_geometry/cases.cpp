// Beyond Paper A Sect. 5: the cases, one attempt, the "clean" criterion
// (extreme_geometry.hpp).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dda/robustness_scenes.hpp"
#include "repro/5_4_extreme_geometry/extreme_geometry.hpp"
#include "repro/common/common.hpp"

namespace extreme {
namespace {
using dda::Vec2;
using repro::format_short;
}  // namespace

Outcome attempt(const Case& c, double dt, bool motion_guard, dda::Integration integration) {
  const repro::Progress clock("attempt");
  Outcome o;
  dda::Scene s = c.scene;
  s.dt = dt;
  s.contact.integration = integration;
  if (!motion_guard) s.guards.max_step_motion = 1e300;  // effectively off (the scene check wants a finite value)
  o.dt = dt;
  double min_push = 0.0, lowest = 1e300, max_up = 0.0;
  double asym = c.asymmetry ? 0.0 : -1.0;
  try {
    dda::Simulation sim(s);
    o.dt_crit = sim.predicted_critical_step();
    o.dt_strain = 1e300;
    for (int i = 0; i < sim.scene_block_count(); ++i)
      if (!sim.fixed(i)) o.dt_strain = std::min(o.dt_strain, sim.strain_critical_step(i));
    dda::paper::RunMonitor mon(sim, c.a, c.b);
    bool touched = false;
    auto watch = [&] {
      if (sim.contact_count() > 0) touched = true;
      if (touched && sim.contact_count() == 0 && o.first_release_asymmetry < 0.0 && c.asymmetry)
        o.first_release_asymmetry = c.asymmetry(sim);
      for (const dda::ContactInfo& ci : sim.contacts()) {
        const Vec2 f = ci.cp == c.pushed ? ci.normal_force : (ci.tp == c.pushed ? -1.0 * ci.normal_force : Vec2{});
        min_push = std::min(min_push, f.y);
      }
      const dda::Polygon& p = sim.polygon(c.pushed);
      for (int k = 0; k < p.count; ++k) lowest = std::min(lowest, p.vertex(k).y);
      if (c.asymmetry) asym = std::max(asym, c.asymmetry(sim));
      if (mon.stats().first_contact >= 0.0) max_up = std::max(max_up, sim.velocity(c.pushed)[1]);
    };
    while (sim.time() < s.duration - 0.5 * sim.dt()) {
      sim.step();
      mon.sample();
      watch();
    }
    o.finished = true;
    o.steps = sim.step_count();
    o.energy_error = mon.stats().energy_error;
    o.energy_growth = mon.stats().energy_growth;
    o.thickness = mon.stats().peak_thickness;
    o.depth = mon.stats().peak_vertex_depth;
    o.asymmetry = asym;
    std::vector<std::string> why;
    // Tolerance on the force sign: a relative 1e-9 of the largest push,
    // taken as 1e-6 N (forces here are 1e2 to 1e6 N).
    const bool wrong_side = c.floor_y > -1e300 && sim.centroid(c.pushed).y < c.floor_y;
    if (min_push < -1e-6 || wrong_side)
      why.push_back("flip-through: the normal force pulled the block in (" + format_short(min_push, 3) + " N)" +
                    (wrong_side ? ", it ends below B" : ""));
    else if (lowest < c.floor_y)
      why.push_back("pierced: A's base went " + format_short(c.floor_y - lowest, 3) +
                    " m below B's bottom (through B's whole thickness), the normal force on A never pointing down, "
                    "A rebounding at up to " + format_short(max_up, 3) + " m/s");
    if (c.apart_at_end && sim.contact_count() > 0) why.push_back("still in contact at the end");
    if (!(o.energy_error < 0.01)) why.push_back("energy error " + format_short(o.energy_error, 3) + " > 1 %");
    if (c.asymmetry && !(asym < 1e-9)) why.push_back("asymmetry " + format_short(asym, 3) + " m > 1e-9 m");
    o.flip = min_push < -1e-6 || wrong_side;
    o.pierced = !o.flip && lowest < c.floor_y;
    o.energy_bad = !(o.energy_error < 0.01);
    o.asymmetric = c.asymmetry && !(asym < 1e-9);
    o.still_touching = c.apart_at_end && sim.contact_count() > 0;
    o.min_push = min_push;
    o.below = lowest < c.floor_y ? c.floor_y - lowest : 0.0;
    o.max_up = max_up;
    o.clean = why.empty();
    if (o.clean) {
      o.verdict = "clean";
    } else {
      for (std::size_t i = 0; i < why.size(); ++i) o.verdict += (i ? "; " : "") + why[i];
    }
  } catch (const dda::SimulationError& e) {
    o.verdict = std::string("stopped by the solver: ") + e.what();
    o.asymmetry = asym;  // up to the stop
  } catch (const dda::SceneError& e) {
    o.verdict = std::string("scene rejected: ") + e.what();
  }
  o.seconds = clock.elapsed_seconds();
  return o;
}

std::string pm(double x) { return format_short(x, 3); }

std::vector<Case> make_cases() {
  std::vector<Case> cases;
  for (dda::HRule rule : {dda::HRule::kMinMaxEdge, dda::HRule::kInscribedRadius})
    for (double h : {0.1, 1e-2, 1e-3, 1e-4, 1e-5}) {
      const dda::paper::BouncingBlock bb = dda::paper::bouncing_block(h, rule);
      Case c;
      c.family = "5.1";
      c.parameter = h;
      c.label = "bouncing block, B height " + format_short(h) + " m, " +
                (rule == dda::HRule::kMinMaxEdge ? "unified H" : "inscribed-radius H");
      c.scene = bb.scene;
      c.a = bb.fixed;
      c.b = c.pushed = bb.falling;
      c.apart_at_end = false;
      c.floor_y = -h;
      c.thin_height = h;
      const int falling = bb.falling;
      c.asymmetry = [falling](const dda::Simulation& sim) {
        return dda::paper::mirror_symmetry_error(sim, falling, 0.0);
      };
      cases.push_back(c);
    }
  for (double angle : {5.0, 2.0, 1.0, 0.5}) {
    const dda::paper::SmallAngleTriangles st = dda::paper::small_angle_triangles(angle);
    Case c;
    c.family = "5.2";
    c.parameter = angle;
    c.label = "triangles, apex angle " + format_short(angle) + " deg";
    c.scene = st.scene;
    c.pushed = 1;  // the upper triangle must be pushed up
    const Vec2 centre = st.centre;
    c.asymmetry = [centre](const dda::Simulation& sim) {
      return dda::paper::point_symmetry_error(sim.polygon(0), sim.polygon(1), centre);
    };
    cases.push_back(c);
  }
  for (dda::paper::SmallEdgeCase which :
       {dda::paper::SmallEdgeCase::kOnSmallEdge, dda::paper::SmallEdgeCase::kOnNeighbourEdge})
    for (double e : {1e-2, 1e-3, 1e-4, 1e-5}) {
      const dda::paper::SmallEdgeImpact si = dda::paper::small_edge_impact(which, e);
      Case c;
      c.family = "5.3";
      c.parameter = e;
      c.label = std::string("vertex impact ") +
                (which == dda::paper::SmallEdgeCase::kOnSmallEdge ? "on" : "next to") + " a " + format_short(e) +
                " m edge";
      c.scene = si.scene;
      c.a = si.lower;
      c.b = c.pushed = si.upper;
      if (si.mirror_symmetric) {
        const int upper = si.upper;
        c.asymmetry = [upper](const dda::Simulation& sim) {
          return dda::paper::mirror_symmetry_error(sim, upper, 0.0);
        };
      }
      cases.push_back(c);
    }
  return cases;
}

// Summary of one outcome for the report row.
std::string describe(const Outcome& o) {
  std::string m = "dt " + pm(o.dt) + " s: " + o.verdict;
  if (o.finished)
    m += " (energy error " + pm(o.energy_error) + ", asymmetry " +
         (o.asymmetry < 0.0 ? std::string("n/a") : pm(o.asymmetry) + " m") + ", peak overlap " + pm(o.thickness) +
         " m, deepest vertex " + pm(o.depth) + " m)";
  return m;
}

}  // namespace extreme
