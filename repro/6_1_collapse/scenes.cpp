// Paper A Sect. 6.1: the scene of a case, the column recut by other joint
// sets, and the output files written once for both cases (collapse.hpp).
#include "repro/6_1_collapse/collapse.hpp"
#include "repro/common/common.hpp"

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
  repro::CsvWriter summary(dir + "/summary.csv",
                           {"case", "joint_friction_deg", "blocks", "dropped", "dropped_area", "H", "dt",
                            "dt_over_dt_crit_start", "dt_over_dt_crit_max", "duration", "steps", "wall_s",
                            "steps_per_s", "front_x_end", "runout_mass_end"});
  for (const CaseResult& r : runs)
    summary.row({static_cast<double>(r.index), r.friction, static_cast<double>(r.blocks),
                 static_cast<double>(r.dropped), r.dropped_area, r.h, r.dt, r.dt_ratio0, r.dt_ratio_max, r.duration,
                 static_cast<double>(r.steps), r.wall, static_cast<double>(r.steps) / r.wall,
                 r.series.back().front_x, r.series.back().runout_mass});
  summary.commit();
}

void write_boundaries(const std::string& dir) {
  const dda::paper::Collapse col = dda::paper::collapse(kFrictions[0]);
  repro::CsvWriter b(dir + "/boundaries.csv", {"ax", "ay", "bx", "by", "depth"},
                     {"boundary segments, solid on the right of a -> b"});
  for (const dda::BoundarySegment& s : col.scene.boundaries) b.row({s.a.x, s.a.y, s.b.x, s.b.y, s.depth});
  b.commit();
}

void write_renumbered(const std::string& dir, const Ends& ends) {
  repro::CsvWriter rn(dir + "/renumbered.csv", {"case", "order", "front_x_end", "runout_mass_end", "mean_drop_end"},
                      {"Paper A Sect. 6.1 reconstructed: each case with its blocks numbered by the generator, by "
                       "centroid x and by centroid y (order: 0 generator, 1 x, 2 y), end of the run"});
  for (int o = 0; o < 3; ++o)
    for (int c = 0; c < 2; ++c) {
      const Sample& e = ends[static_cast<std::size_t>(o)][static_cast<std::size_t>(c)];
      rn.row({c + 1.0, static_cast<double>(o), e.front_x, e.runout_mass, e.mean_drop});
    }
  rn.commit();
}

}  // namespace collapse61
