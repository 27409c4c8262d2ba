// The 5.5 driver's runs (segmentation.hpp): the contacts along the Sect. 4-5
// runs, the fuzzed pairs and the side-by-side trajectories.
#include <algorithm>
#include <cmath>
#include <utility>

#include "dda/paper_scenes.hpp"
#include "dda/robustness_scenes.hpp"
#include "repro/5_5_segmentation/segmentation.hpp"
#include "repro/common/common.hpp"

namespace segmentation {

using dda::Integration;
using dda::Polygon;
using dda::SmallEdgeRays;
using dda::Vec2;
using repro::format_short;

// ---- 1. contacts along a run ----------------------------------------------------

// The errors of a compared pair under both readings, as columns.
std::vector<repro::Column<Compared>> error_columns() {
  return {{"force_error_paper", [](const Compared& c) { return c.e.mode[0].force; }},
          {"point_error_paper", [](const Compared& c) { return c.e.mode[0].point; }},
          {"force_error_replace", [](const Compared& c) { return c.e.mode[1].force; }},
          {"point_error_replace", [](const Compared& c) { return c.e.mode[1].point; }}};
}

std::vector<repro::Column<Compared>> contact_columns() {
  std::vector<repro::Column<Compared>> columns = {{"scene", [](const Compared& c) { return c.scene; }},
                                                  {"time", [](const Compared& c) { return c.time; }}};
  for (repro::Column<Compared>& c : error_columns()) columns.push_back(std::move(c));
  columns.push_back({"depth_ratio", [](const Compared& c) { return c.e.depth_ratio; }});
  return columns;
}

std::vector<repro::Column<Compared>> fuzz_columns() {
  std::vector<repro::Column<Compared>> columns = {{"depth_ratio", [](const Compared& c) { return c.e.depth_ratio; }}};
  for (repro::Column<Compared>& c : error_columns()) columns.push_back(std::move(c));
  columns.push_back({"has_small_edge", [](const Compared& c) { return c.small_edge; }});
  return columns;
}

SceneStats scan(const std::string& name, const dda::Scene& scene, int every, int scene_id,
                repro::TableWriter<Compared>* table) {
  const repro::Progress clock(name);
  SceneStats st;
  st.name = name;
  dda::Scene s = scene;  // the library defaults, made explicit
  s.contact.integration = Integration::kPaperBisector;
  s.contact.small_edge_rays = SmallEdgeRays::kVirtualAndVertex;
  dda::Simulation sim(s);
  const dda::ContactParams& c = s.contact;
  while (sim.time() < scene.duration - 0.5 * sim.dt()) {
    sim.step();
    if (sim.step_count() % every != 0) continue;
    for (const dda::ContactInfo& ci : sim.contacts()) {
      const double ha = sim.potential_length(ci.cp), hb = sim.potential_length(ci.tp);
      const Errors e = compare(sim.polygon(ci.cp), c.kn / ha, c.small_edge_fraction * ha, sim.polygon(ci.tp), c.kn / hb,
                               c.small_edge_fraction * hb);
      if (!e.valid) continue;
      for (std::size_t m = 0; m < kModes.size(); ++m) st.mode[m].add(e.mode[m]);
      if (table) table->row({scene_id, sim.time(), e, false});
    }
  }
  st.seconds = clock.elapsed_seconds();
  return st;
}

// ---- 2. fuzzed pairs ---------------------------------------------------------------

std::vector<Vec2> random_polygon(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 3 + static_cast<int>(u(rng) * 8.0);  // 3..10 vertices
  std::vector<double> ang(static_cast<std::size_t>(n));
  for (double& a : ang) a = 2.0 * M_PI * u(rng);
  std::sort(ang.begin(), ang.end());
  const double aspect = std::exp(std::log(6.0) * u(rng));  // 1..6: elongated shapes have long medial segments
  const double rot = 2.0 * M_PI * u(rng);
  std::vector<Vec2> p;
  for (double a : ang) p.push_back(dda::rotate(Vec2{aspect * std::cos(a), std::sin(a)}, rot));
  // Sometimes cut one corner with a small edge (1e-3 to 5e-2 of the size).
  if (u(rng) < 0.3 && n >= 3) {
    const std::size_t i = static_cast<std::size_t>(u(rng) * n) % p.size();
    const Vec2 v = p[i], prev = p[(i + p.size() - 1) % p.size()], next = p[(i + 1) % p.size()];
    const double len = std::exp(std::log(1e-3) + (std::log(5e-2) - std::log(1e-3)) * u(rng));
    const Vec2 ua = dda::normalized(prev - v), ub = dda::normalized(next - v);
    const double t = len / dda::length(ua - ub);
    if (t < 0.3 * std::min(dda::distance(v, prev), dda::distance(v, next))) {
      p[i] = v + t * ub;
      p.insert(p.begin() + static_cast<long>(i), v + t * ua);
    }
  }
  return p;
}

int fuzz(const std::string& dir, std::vector<repro::Claim>& claims) {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  repro::TableWriter<Compared> fuzz(dir + "/fuzz.csv", fuzz_columns(),
                        {"20000 random convex pairs (seed 20240611), overlap thickness log-uniform in [1e-3, 1] of the "
                         "smaller inscribed diameter, kn/H = 1/H with H the mean of the pair's "
                         "smallest and largest edge, small edges below 0.05 H get virtual nodes; *_paper: "
                         "kVirtualAndVertex (library default), *_replace: kVirtualReplacesVertex"});
  struct Bin {
    Bin(double l, double h) : lo(l), hi(h) {}
    double lo, hi;
    std::array<ModeStats, 2> mode;
    ModeStats small_paper, small_replace;  // the pairs with an edge below 0.05 H
  };
  std::vector<Bin> bins = {{0.0, 0.01}, {0.01, 0.1}, {0.1, 0.3}, {0.3, 1.01}};
  int accepted = 0, tries = 0;
  while (accepted < 20000 && tries < 1000000) {
    ++tries;
    const std::vector<Vec2> pa = random_polygon(rng), pb = random_polygon(rng);
    if (!dda::validate_polygon(pa.data(), static_cast<int>(pa.size())).ok() ||
        !dda::validate_polygon(pb.data(), static_cast<int>(pb.size())).ok())
      continue;
    Polygon a = dda::make_polygon(pa.data(), static_cast<int>(pa.size()));
    const Polygon b = dda::make_polygon(pb.data(), static_cast<int>(pb.size()));
    // Place A along a random direction from B's centroid at the distance
    // where the overlap thickness is a target fraction (log-uniform in
    // [1e-3, 1]) of the smaller inscribed diameter: found by bisection on
    // the distance (thickness falls as A moves out; 40 halvings).
    const double target = std::exp(std::log(1e-3) * u(rng)) * 2.0 *
                          std::min(dda::inscribed_circle(a).radius, dda::inscribed_circle(b).radius);
    const Vec2 dirn = dda::rotate(Vec2{1.0, 0.0}, 2.0 * M_PI * u(rng));
    a = dda::translated(a, dda::centroid(b) - dda::centroid(a));
    double lo = 0.0, hi = dda::diameter(a) + dda::diameter(b);
    for (int it = 0; it < 40; ++it) {
      const double mid = 0.5 * (lo + hi);
      (dda::paper::overlap_thickness(dda::translated(a, mid * dirn), b) > target ? lo : hi) = mid;
    }
    a = dda::translated(a, lo * dirn);
    const double lmin = std::min(dda::min_edge_length(a), dda::min_edge_length(b));
    const double lmax = std::max(dda::max_edge_length(a), dda::max_edge_length(b));
    const double h = 0.5 * (lmin + lmax);
    const Errors e = compare(a, 1.0 / h, 0.05 * h, b, 1.0 / h, 0.05 * h);
    if (!e.valid) continue;
    ++accepted;
    const bool small = lmin < 0.05 * h;
    fuzz.row({0, 0.0, e, small});
    for (Bin& bn : bins)
      if (e.depth_ratio >= bn.lo && e.depth_ratio < bn.hi) {
        for (std::size_t m = 0; m < kModes.size(); ++m) bn.mode[m].add(e.mode[m]);
        if (small) {
          bn.small_paper.add(e.mode[0]);
          bn.small_replace.add(e.mode[1]);
        }
      }
  }
  fuzz.commit();
  for (const Bin& bn : bins)
    claims.push_back(
        {kSection,
         "fuzzed convex pairs, overlap depth " + format_short(bn.lo) + " to " + format_short(std::min(bn.hi, 1.0)) +
             " of the smaller inscribed diameter: paper's segmentation vs exact",
         "Sect. 3.2.3 (exactness implied)",
         std::to_string(bn.mode[0].n) + " pairs. " + kPaperRuleName + ": " + bn.mode[0].brief() + ". " +
             kReplaceRuleName + ": " + bn.mode[1].brief() + ". Of these, the " + std::to_string(bn.small_paper.n) +
             " pairs with an edge below 0.05 H: paper's rule " + format_short(bn.small_paper.nonzero_percent(), 3) +
             " % nonzero (max " + format_short(bn.small_paper.max_force, 3) + "), replacing reading " +
             format_short(bn.small_replace.nonzero_percent(), 3) + " % (max " +
             format_short(bn.small_replace.max_force, 3) + ")",
         "information (exact would be 0)", false, repro::Kind::kMeasurement});
  return accepted;
}

// ---- 3. trajectories ------------------------------------------------------------

std::vector<repro::Column<TrajSample>> trajectory_columns() {
  return {{"scene", [](const TrajSample& s) { return s.scene; }},
          {"time", [](const TrajSample& s) { return s.time; }},
          {"difference_paper", [](const TrajSample& s) { return s.difference_paper; }},
          {"difference_replace", [](const TrajSample& s) { return s.difference_replace; }}};
}

TrajResult run_trajectory(const Traj& t, std::size_t k, repro::TableWriter<TrajSample>& traj) {
  // Runs 0, 1: paper segmentation with each small-edge reading; 2: exact.
  std::array<dda::Scene, 3> sc = {t.scene, t.scene, t.scene};
  for (std::size_t m = 0; m < kModes.size(); ++m) {
    sc[m].contact.integration = Integration::kPaperBisector;
    sc[m].contact.small_edge_rays = kModes[m];
  }
  sc[2].contact.integration = Integration::kExactEnvelope;
  dda::Simulation s0(sc[0]), s1(sc[1]), s2(sc[2]);
  std::array<dda::Simulation*, 3> sim = {&s0, &s1, &s2};
  dda::paper::RunMonitor m0(s0, 0, 1), m1(s1, 0, 1), m2(s2, 0, 1);
  std::array<dda::paper::RunMonitor*, 3> mon = {&m0, &m1, &m2};
  auto diff = [&](const dda::Simulation& a, const dda::Simulation& b) {
    return t.q ? std::fabs(t.q(a) - t.q(b)) : dda::distance(t.q2(a), t.q2(b));
  };
  TrajResult r;
  double between = 0.0;  // largest difference between the two readings' runs
  while (s0.time() < sc[0].duration - 0.5 * s0.dt()) {
    for (int i = 0; i < 3; ++i) {
      sim[i]->step();
      mon[i]->sample();
    }
    const double d0 = diff(s0, s2), d1 = diff(s1, s2);
    r.worst = {std::max(r.worst[0], d0), std::max(r.worst[1], d1)};
    between = std::max(between, diff(s0, s1));
    if (s0.step_count() % t.every == 0) traj.row({k, s0.time(), d0, d1});
  }
  r.energy = {m0.stats().energy_error, m1.stats().energy_error, m2.stats().energy_error};
  r.identical = between == 0.0 && r.energy[0] == r.energy[1];
  return r;
}

}  // namespace segmentation
