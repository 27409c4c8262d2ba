// Paper B Sect. 6, two prisms: the data files of the driver.
#include "repro/B_6_two_prisms/output.hpp"

#include <cmath>

namespace prisms {
namespace {

std::vector<std::string> history_header() {
  return {"time",        "ux_i",         "ux_j",    "vx_i",           "vx_j",
          "vx_max_j",    "momentum_x",   "kinetic", "strain",         "total_energy",
          "impact_loss", "remap_change", "clones",  "patch_elements", "patch_substeps",
          // the energy account (Model::energy_account), J/m
          "energy_initial", "gravity", "touch_loss", "touch_loss_eq5", "refine_loss", "deletion_loss", "energy_other"};
}

void write_snapshot(repro::CsvWriter& tris, repro::CsvWriter& clones, int id, const std::string& label,
                    const dda::cdem::Snapshot& s) {
  for (const auto& t : s.tris)
    tris.row(std::vector<std::string>{std::to_string(id), repro::format_full(s.time), label, std::to_string(t.block),
                                      t.fine ? "1" : "0", repro::format_full(t.x[0].x), repro::format_full(t.x[0].y),
                                      repro::format_full(t.x[1].x), repro::format_full(t.x[1].y),
                                      repro::format_full(t.x[2].x), repro::format_full(t.x[2].y),
                                      repro::format_full(t.velocity.x), repro::format_full(t.velocity.y)});
  for (const dda::Vec2& p : s.clone_points)
    clones.row(std::vector<std::string>{std::to_string(id), repro::format_full(s.time), label, repro::format_full(p.x),
                                        repro::format_full(p.y)});
}

// Snapshot times: Fig. 13 (start, touch), Fig. 14 a-c, Fig. 15 a-b; and
// the last step before the first separation ("last step with the clone").
struct Shot {
  double time;
  const char* label;
};
const Shot kShots[] = {{0.0, "Fig. 13: t = 0"},        {0.3335, "Fig. 14a: 0.3335 s"},
                       {0.3340, "Fig. 14b: 0.3340 s"}, {0.3400, "Fig. 14c: 0.3400 s"},
                       {0.3405, "Fig. 15a: 0.3405 s"}, {0.4960, "Fig. 15b: 0.4960 s"}};
constexpr std::size_t kShotCount = sizeof(kShots) / sizeof(kShots[0]);

}  // namespace

std::string subdivision_mode_text(const dda::cdem::CdemOptions& o) {
  if (!o.subdivision) return "none (clone node of the coarse nodes)";
  switch (o.subdivision_mode) {
    case dda::cdem::SubdivisionMode::kSubModel:
      return o.submodel_transfer == dda::cdem::SubModelTransfer::kWholeElement
                 ? "sub-model of the colliding elements (Paper B Sect. 5; step 5 returns every sub-node's force)"
                 : "sub-model of the colliding elements (Paper B Sect. 5; step 5 read literally)";
    case dda::cdem::SubdivisionMode::kInPlace:
      return "in-place refinement (beyond the paper)";
  }
  return "unnamed mode";
}

History::History(const std::string& path, const std::string& title, const dda::cdem::CdemOptions& opt)
    : csv_(path, history_header(), {title + kRebuilt, "subdivision mode: " + subdivision_mode_text(opt)}) {}

void History::row(const dda::cdem::Model& m) {
  const dda::cdem::CdemEnergy e = m.energy();
  const dda::cdem::CdemEnergyAccount a = m.energy_account();
  csv_.row({m.time(), m.block_displacement(0).x, m.block_displacement(1).x, m.block_velocity(0).x,
            m.block_velocity(1).x, m.block_max_velocity_x(1), m.momentum().x, e.kinetic, e.strain, e.total(),
            m.impact_energy_loss(), m.remap_energy_change(), static_cast<double>(m.clones().size()),
            static_cast<double>(m.active_elements(true)), static_cast<double>(m.patch_substeps()), a.initial,
            a.gravity, a.touch_loss, a.touch_loss_eq5, a.refine_loss, a.deletion_loss, a.other});
}

FigureFiles::FigureFiles(const std::string& dir, const dda::cdem::CdemOptions& opt)
    : dir_(dir),
      hist_(dir + "history.csv", "Paper B Sect. 6, two prisms, clone node + subdivision; ", opt),
      tris_(dir + "snapshots.csv",
            {"snapshot", "time", "label", "block", "fine", "x0", "y0", "x1", "y1", "x2", "y2", "vx", "vy"},
            {kRebuilt, "subdivision mode: " + subdivision_mode_text(opt)}),
      clones_(dir + "clones.csv", {"snapshot", "time", "label", "x", "y"}) {}

void FigureFiles::on_step(const dda::cdem::Model& m) {
  if (before_separation_ && !m.separations().empty()) {
    before_separation_ = false;
    write_snapshot(tris_, clones_, shot_id_++,
                   "last step with the clone: " + repro::format_short(previous_.time, 5) + " s", previous_);
  }
  if (before_separation_) previous_ = m.snapshot();
  hist_.row(m);
  while (next_shot_ < kShotCount && std::fabs(m.time() - kShots[next_shot_].time) < 0.5 * m.dt())
    write_snapshot(tris_, clones_, shot_id_++, kShots[next_shot_++].label, m.snapshot());
  if (m.touches().size() != touches_.size()) touches_ = m.touches();
  if (m.separations().size() != separations_.size()) separations_ = m.separations();
}

void FigureFiles::commit(const Result& r) {
  using repro::format_short;
  write_snapshot(tris_, clones_, shot_id_++, "Fig. 13: touch " + format_short(r.touch.time, 6) + " s",
                 r.touch.snapshot.at(0));
  repro::CsvWriter events(dir_ + "events.csv", {"kind", "time", "detail_a", "detail_b", "detail_c", "detail_d"});
  for (const auto& t : touches_)
    events.row(std::vector<std::string>{"touch", repro::format_full(t.time), "dt1=" + format_short(t.dt1, 6),
                                        "dt2=" + format_short(t.dt2, 6), "k=" + std::to_string(t.subdivision),
                                        "loss=" + format_short(t.energy_loss, 6)});
  for (const auto& s : separations_)
    events.row(std::vector<std::string>{"separation", repro::format_full(s.time),
                                        s.criterion == dda::cdem::SeparationCriterion::kTension ? "tension" : "shear",
                                        "Fn=" + format_short(s.normal_force, 6), "Fs=" + format_short(s.shear_force, 6),
                                        "limit=" + format_short(s.limit, 6)});
  hist_.commit();
  tris_.commit();
  clones_.commit();
  events.commit();
}

void write_mesh_study(const std::string& path, const std::vector<MeshPoint>& mesh) {
  repro::CsvWriter csv(path, {"divisions", "dt", "vj_block_average", "vj_node_at_0.34", "t_sep"},
                       {std::string("Paper B Sect. 6, two prisms on finer meshes, dt scaled with the element "
                                    "size (c dt / h fixed); ") + kRebuilt});
  for (const MeshPoint& p : mesh) csv.row({static_cast<double>(p.divisions), p.dt, p.vj, p.node_vj_fig14c, p.t_sep});
  csv.commit();
}

void write_submodel_mesh_study(const std::string& path, const std::vector<SubMeshPoint>& pts) {
  repro::CsvWriter csv(path,
                       {"divisions", "dt", "vj_block_average", "vj_node_at_0.34", "t_sep", "momentum_drift", "stopped"},
                       {std::string("Paper B Sect. 5 as written (sub-model) on the refinement study's meshes, dt "
                                    "scaled with the element size; ") + kRebuilt});
  for (const SubMeshPoint& p : pts) {
    const bool ok = p.stopped.empty();  // a stopped run's fields are no data
    auto num = [&](double x) { return ok ? repro::format_full(x) : std::string(); };
    csv.row(std::vector<std::string>{std::to_string(p.divisions), repro::format_full(p.dt), num(p.vj),
                                     num(p.node_vj_fig14c), num(p.t_sep), num(p.momentum), ok ? "" : "stopped"});
  }
  csv.commit();
}

void write_contact_mass(const std::string& path, const std::vector<MassPoint>& pts, double coarse_loss) {
  repro::CsvWriter csv(path,
                       {"contact_point_mass", "k", "mass_main", "mass_target", "loss", "loss_eq5", "loss_over_coarse"},
                       {"Paper B Sect. 4.1: one touch of the prisms with the contact points' mass set through "
                        "the subdivision k (CdemOptions::contact_point_mass); masses kg/m, losses J/m; "
                        "loss_over_coarse: against the touch of coarse nodes (no subdivision); " +
                        std::string(kRebuilt)});
  for (const MassPoint& p : pts)
    csv.row({p.target, static_cast<double>(p.k), p.mass_main, p.mass_target, p.loss, p.loss_eq5,
             p.loss / coarse_loss});
  csv.commit();
}

}  // namespace prisms
