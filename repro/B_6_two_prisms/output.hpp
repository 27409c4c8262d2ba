// Paper B Sect. 6, two prisms: the data files of the driver (history,
// snapshots, clones, events: Figs. 13-16; the refinement and contact-mass
// tables).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "dda/cdem/model.hpp"
#include "repro/B_6_two_prisms/two_prisms.hpp"
#include "repro/common/common.hpp"
#include "repro/common/table.hpp"

namespace prisms {

// The subdivision mode a run used, in words, for the data files' comment
// line "subdivision mode: ..." (the figures label the curves with it).
std::string subdivision_mode_text(const dda::cdem::CdemOptions& o);

// One step of a run as history.csv reads it: the model and its energies.
struct HistoryRow {
  const dda::cdem::Model* m;
  dda::cdem::CdemEnergy e;
  dda::cdem::CdemEnergyAccount a;
};

// history.csv's rows: one per step (Fig. 16, with the energy account).
class History {
 public:
  History(const std::string& path, const std::string& title, const dda::cdem::CdemOptions& opt);
  void row(const dda::cdem::Model& m);
  void commit() { table_.commit(); }

 private:
  repro::TableWriter<HistoryRow> table_;
};

// The main run's files: history.csv, snapshots.csv and clones.csv at the
// figures' times (Figs. 13-15) and events.csv (touches, separations).
class FigureFiles {
 public:
  FigureFiles(const std::string& dir, const dda::cdem::CdemOptions& opt);
  ~FigureFiles();
  void on_step(const dda::cdem::Model& m);  // after construction and after every step
  void commit(const Result& r);             // adds the touch snapshot, writes events.csv

 private:
  std::string dir_;
  History hist_;
  struct Shots;  // snapshots.csv and clones.csv (output.cpp)
  std::unique_ptr<Shots> shots_;
  std::size_t next_shot_ = 0;
  dda::cdem::Snapshot previous_;
  bool before_separation_ = true;
  std::vector<dda::cdem::TouchRecord> touches_;
  std::vector<dda::cdem::SeparationRecord> separations_;
};

void write_mesh_study(const std::string& path, const std::vector<MeshPoint>& mesh);
void write_submodel_mesh_study(const std::string& path, const std::vector<SubMeshPoint>& pts);
void write_contact_mass(const std::string& path, const std::vector<MassPoint>& pts, double coarse_loss);

}  // namespace prisms
