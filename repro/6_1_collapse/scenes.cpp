// Paper A Sect. 6.1: the scene of a case, the column recut by other joint
// sets, and the output files written once for both cases (collapse.hpp).
#include "repro/6_1_collapse/collapse.hpp"
#include "repro/common/common.hpp"
#include "repro/common/rock_run.hpp"

namespace collapse61 {

std::string time_tag(double t) { return repro::format_fixed(t, 1); }

dda::paper::Collapse scene(double friction, double duration, dda::RotationUpdate rotation) {
  dda::paper::Collapse col = dda::paper::collapse(friction, 0.5, duration);
  col.scene.rotation_update = rotation;
  return col;
}

dda::paper::Collapse recut(dda::paper::Collapse col, const std::vector<dda::JointSet>& sets, double min_area) {
  const dda::GeneratedBlocks g = dda::generate_blocks(col.region, sets, min_area);
  col.joint_sets = sets;
  col.min_area = min_area;
  col.dropped = g.dropped;
  col.dropped_area = g.dropped_area;
  col.scene.blocks.clear();
  for (const dda::Polygon& p : g.blocks) {
    dda::BlockSpec b;
    b.vertices.assign(p.v.begin(), p.v.begin() + p.count);
    b.group = dda::paper::kRockGroup;
    col.scene.blocks.push_back(std::move(b));
  }
  return col;
}

void write_summary(const std::string& dir, const std::vector<CaseResult>& runs) {
  using R = CaseResult;
  repro::write_table<R>(dir + "/summary.csv",
                        {repro::field("case", &R::index),
                         repro::field("joint_friction_deg", &R::friction),
                         repro::field("blocks", &R::blocks),
                         repro::field("dropped", &R::dropped),
                         repro::field("dropped_area", &R::dropped_area),
                         repro::field("H", &R::h),
                         repro::field("dt", &R::dt),
                         repro::field("dt_over_dt_crit_start", &R::dt_ratio0),
                         repro::field("dt_over_dt_crit_max", &R::dt_ratio_max),
                         repro::field("duration", &R::duration),
                         {"steps", [](const R& r) { return static_cast<double>(r.steps); }},
                         repro::field("wall_s", &R::wall),
                         {"steps_per_s", [](const R& r) { return static_cast<double>(r.steps) / r.wall; }},
                         {"front_x_end", [](const R& r) { return r.series.back().front_x; }},
                         {"runout_mass_end", [](const R& r) { return r.series.back().runout_mass; }}},
                        runs);
}

void write_boundaries(const std::string& dir) {
  repro::write_boundaries(dir + "/boundaries.csv", dda::paper::collapse(kFrictions[0]).scene.boundaries);
}

void write_renumbered(const std::string& dir, const Ends& ends) {
  struct End {
    int order, c;
    const Sample* e;
  };
  std::vector<End> rows;
  for (int o = 0; o < 3; ++o)
    for (int c = 0; c < 2; ++c) rows.push_back({o, c, &ends[static_cast<std::size_t>(o)][static_cast<std::size_t>(c)]});
  repro::write_table<End>(dir + "/renumbered.csv",
                          {{"case", [](const End& r) { return r.c + 1.0; }},
                           {"order", [](const End& r) { return r.order; }},
                           {"front_x_end", [](const End& r) { return r.e->front_x; }},
                           {"runout_mass_end", [](const End& r) { return r.e->runout_mass; }},
                           {"mean_drop_end", [](const End& r) { return r.e->mean_drop; }}},
                          rows,
                          {"Paper A Sect. 6.1 reconstructed: each case with its blocks numbered by the generator, by "
                           "centroid x and by centroid y (order: 0 generator, 1 x, 2 y), end of the run"});
}

}  // namespace collapse61
