// Paper B Sect. 6, two prisms: the data files of the driver, each declared
// as a column table.
#include "repro/B_6_two_prisms/output.hpp"

#include <cmath>

namespace prisms {
namespace {

using Model = dda::cdem::Model;

// history.csv's columns: the block motion, the energies and the energy
// account (Model::energy_account, J/m) of one step.
std::vector<repro::Column<HistoryRow>> history_columns() {
  return {{"time", [](const HistoryRow& h) { return h.m->time(); }},
          {"ux_i", [](const HistoryRow& h) { return h.m->block_displacement(0).x; }},
          {"ux_j", [](const HistoryRow& h) { return h.m->block_displacement(1).x; }},
          {"vx_i", [](const HistoryRow& h) { return h.m->block_velocity(0).x; }},
          {"vx_j", [](const HistoryRow& h) { return h.m->block_velocity(1).x; }},
          {"vx_max_j", [](const HistoryRow& h) { return h.m->block_max_velocity_x(1); }},
          {"momentum_x", [](const HistoryRow& h) { return h.m->momentum().x; }},
          {"kinetic", [](const HistoryRow& h) { return h.e.kinetic; }},
          {"strain", [](const HistoryRow& h) { return h.e.strain; }},
          {"total_energy", [](const HistoryRow& h) { return h.e.total(); }},
          {"impact_loss", [](const HistoryRow& h) { return h.m->impact_energy_loss(); }},
          {"remap_change", [](const HistoryRow& h) { return h.m->remap_energy_change(); }},
          {"clones", [](const HistoryRow& h) { return h.m->clones().size(); }},
          {"patch_elements", [](const HistoryRow& h) { return h.m->active_elements(true); }},
          {"patch_substeps", [](const HistoryRow& h) { return h.m->patch_substeps(); }},
          {"energy_initial", [](const HistoryRow& h) { return h.a.initial; }},
          {"gravity", [](const HistoryRow& h) { return h.a.gravity; }},
          {"touch_loss", [](const HistoryRow& h) { return h.a.touch_loss; }},
          {"touch_loss_eq5", [](const HistoryRow& h) { return h.a.touch_loss_eq5; }},
          {"refine_loss", [](const HistoryRow& h) { return h.a.refine_loss; }},
          {"deletion_loss", [](const HistoryRow& h) { return h.a.deletion_loss; }},
          {"energy_other", [](const HistoryRow& h) { return h.a.other; }}};
}

// snapshots.csv: one row per triangle of a snapshot.
struct ShotTri {
  int id;
  double time;
  std::string label;
  dda::cdem::Snapshot::Tri t;
};
std::vector<repro::Column<ShotTri>> tri_columns() {
  const auto corner = [](int k, bool y) {
    return [k, y](const ShotTri& s) { return y ? s.t.x[k].y : s.t.x[k].x; };
  };
  return {{"snapshot", [](const ShotTri& s) { return s.id; }},
          {"time", [](const ShotTri& s) { return s.time; }},
          {"label", [](const ShotTri& s) { return s.label; }},
          {"block", [](const ShotTri& s) { return s.t.block; }},
          {"fine", [](const ShotTri& s) { return s.t.fine; }},
          {"x0", corner(0, false)}, {"y0", corner(0, true)},
          {"x1", corner(1, false)}, {"y1", corner(1, true)},
          {"x2", corner(2, false)}, {"y2", corner(2, true)},
          {"vx", [](const ShotTri& s) { return s.t.velocity.x; }},
          {"vy", [](const ShotTri& s) { return s.t.velocity.y; }}};
}

// clones.csv: one row per clone point of a snapshot.
struct ShotClone {
  int id;
  double time;
  std::string label;
  dda::Vec2 p;
};
const std::vector<repro::Column<ShotClone>> kCloneColumns = {
    {"snapshot", [](const ShotClone& s) { return s.id; }},
    {"time", [](const ShotClone& s) { return s.time; }},
    {"label", [](const ShotClone& s) { return s.label; }},
    {"x", [](const ShotClone& s) { return s.p.x; }},
    {"y", [](const ShotClone& s) { return s.p.y; }}};

// events.csv: a touch or a separation, its details as text.
struct Event {
  std::string kind;
  double time;
  std::string a, b, c, d;
};
const std::vector<repro::Column<Event>> kEventColumns = {{"kind", [](const Event& e) { return e.kind; }},
                                                         {"time", [](const Event& e) { return e.time; }},
                                                         {"detail_a", [](const Event& e) { return e.a; }},
                                                         {"detail_b", [](const Event& e) { return e.b; }},
                                                         {"detail_c", [](const Event& e) { return e.c; }},
                                                         {"detail_d", [](const Event& e) { return e.d; }}};

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
    : table_(path, history_columns(), {title + kRebuilt, "subdivision mode: " + subdivision_mode_text(opt)}) {}

void History::row(const Model& m) { table_.row({&m, m.energy(), m.energy_account()}); }

struct FigureFiles::Shots {
  repro::TableWriter<ShotTri> tris;
  repro::TableWriter<ShotClone> clones;
  int next_id = 0;
  // Writes snapshot `s` under `label` with the next id.
  void write(const std::string& label, const dda::cdem::Snapshot& s) {
    const int id = next_id++;
    for (const auto& t : s.tris) tris.row({id, s.time, label, t});
    for (const dda::Vec2& p : s.clone_points) clones.row({id, s.time, label, p});
  }
};

FigureFiles::FigureFiles(const std::string& dir, const dda::cdem::CdemOptions& opt)
    : dir_(dir),
      hist_(dir + "history.csv", "Paper B Sect. 6, two prisms, clone node + subdivision; ", opt),
      shots_(new Shots{{dir + "snapshots.csv", tri_columns(), {kRebuilt, "subdivision mode: " + subdivision_mode_text(opt)}},
                       {dir + "clones.csv", kCloneColumns}}) {}

FigureFiles::~FigureFiles() = default;

void FigureFiles::on_step(const Model& m) {
  if (before_separation_ && !m.separations().empty()) {
    before_separation_ = false;
    shots_->write("last step with the clone: " + repro::format_short(previous_.time, 5) + " s", previous_);
  }
  if (before_separation_) previous_ = m.snapshot();
  hist_.row(m);
  while (next_shot_ < kShotCount && std::fabs(m.time() - kShots[next_shot_].time) < 0.5 * m.dt())
    shots_->write(kShots[next_shot_++].label, m.snapshot());
  if (m.touches().size() != touches_.size()) touches_ = m.touches();
  if (m.separations().size() != separations_.size()) separations_ = m.separations();
}

void FigureFiles::commit(const Result& r) {
  using repro::format_short;
  shots_->write("Fig. 13: touch " + format_short(r.touch.time, 6) + " s", r.touch.snapshot.at(0));
  std::vector<Event> events;
  for (const auto& t : touches_)
    events.push_back({"touch", t.time, "dt1=" + format_short(t.dt1, 6), "dt2=" + format_short(t.dt2, 6),
                      "k=" + std::to_string(t.subdivision), "loss=" + format_short(t.energy_loss, 6)});
  for (const auto& s : separations_)
    events.push_back({"separation", s.time,
                      s.criterion == dda::cdem::SeparationCriterion::kTension ? "tension" : "shear",
                      "Fn=" + format_short(s.normal_force, 6), "Fs=" + format_short(s.shear_force, 6),
                      "limit=" + format_short(s.limit, 6)});
  hist_.commit();
  shots_->tris.commit();
  shots_->clones.commit();
  repro::write_table(dir_ + "events.csv", kEventColumns, events);
}

// The columns both refinement studies have: the mesh, the step, and j's
// velocities and the separation, empty where `has_data` says the point has
// none (a stopped run).
template <class Point>
std::vector<repro::Column<Point>> refinement_columns(bool (*has_data)(const Point&)) {
  const auto data = [has_data](double Point::*f) {
    return [has_data, f](const Point& p) { return repro::cell_if(has_data(p), p.*f); };
  };
  return {repro::field("divisions", &Point::divisions), repro::field("dt", &Point::dt),
          {"vj_block_average", data(&Point::vj)}, {"vj_node_at_0.34", data(&Point::node_vj_fig14c)},
          {"t_sep", data(&Point::t_sep)}};
}

void write_mesh_study(const std::string& path, const std::vector<MeshPoint>& mesh) {
  repro::write_table(
      path, refinement_columns<MeshPoint>([](const MeshPoint&) { return true; }), mesh,
      {std::string("Paper B Sect. 6, two prisms on finer meshes, dt scaled with the element size (c dt / h fixed); ") +
       kRebuilt});
}

void write_submodel_mesh_study(const std::string& path, const std::vector<SubMeshPoint>& pts) {
  const auto finished = [](const SubMeshPoint& p) { return p.stopped.empty(); };
  std::vector<repro::Column<SubMeshPoint>> columns = refinement_columns<SubMeshPoint>(finished);
  columns.push_back(
      {"momentum_drift", [](const SubMeshPoint& p) { return repro::cell_if(p.stopped.empty(), p.momentum); }});
  columns.push_back({"stopped", [](const SubMeshPoint& p) { return p.stopped.empty() ? "" : "stopped"; }});
  repro::write_table(path, columns, pts,
                     {std::string("Paper B Sect. 5 as written (sub-model) on the refinement study's meshes, dt scaled "
                                  "with the element size; ") + kRebuilt});
}

void write_contact_mass(const std::string& path, const std::vector<MassPoint>& pts, double coarse_loss) {
  repro::write_table<MassPoint>(
      path,
      {repro::field("contact_point_mass", &MassPoint::target),
       repro::field("k", &MassPoint::k),
       repro::field("mass_main", &MassPoint::mass_main),
       repro::field("mass_target", &MassPoint::mass_target),
       repro::field("loss", &MassPoint::loss),
       repro::field("loss_eq5", &MassPoint::loss_eq5),
       {"loss_over_coarse", [coarse_loss](const MassPoint& p) { return p.loss / coarse_loss; }}},
      pts,
      {"Paper B Sect. 4.1: one touch of the prisms with the contact points' mass set through the subdivision k "
       "(CdemOptions::contact_point_mass); masses kg/m, losses J/m; loss_over_coarse: against the touch of coarse "
       "nodes (no subdivision); " + std::string(kRebuilt)});
}

}  // namespace prisms
