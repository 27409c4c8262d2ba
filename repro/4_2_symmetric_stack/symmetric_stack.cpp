// Paper A, Sect. 4.2 "Collision of a polygon and a symmetric polygonal
// system" (Figs. 9-10).
//
// GEOMETRY RECONSTRUCTED: Fig. 9 is lost. Our stack (dda::paper::
// symmetric_stack): a fixed base, two 1 m squares side by side, a third
// centred on top (axis x = 0), and a pentagon symmetric about x = 0 falling
// on it at 2 m/s under gravity. rho 2000, E 0.1 GPa, nu 0.25, kn 10 MPa,
// dt 1e-3 s, 1.0 s (Table 4). Expected (paper): the system "will move in a
// symmetric way during the collision process"; the centroid traces of
// Fig. 10 are mirror images about the axis, and so are the rotations
// (mirror images turn by opposite angles).
//
// Output: data/symmetric_stack/traces.csv, snapshots.csv; claims.
#include <string>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "repro/4_2_symmetric_stack/symmetric_stack.hpp"
#include "repro/common/common.hpp"

int main(int argc, char** argv) {
  repro::check_command_line(argc, argv, "Paper A Sect. 4.2 (Figs. 9-10): a polygon hitting a symmetric polygonal system.");
  const std::string out = repro::out_dir(argc, argv);
  const repro::Progress progress("4.2 symmetric stack");
  const dda::paper::SymmetricStack st = dda::paper::symmetric_stack();
  const int n = static_cast<int>(st.scene.blocks.size());
  std::vector<std::string> header = {"time"};
  for (int i = 0; i < n; ++i) {
    header.push_back("x" + std::to_string(i));
    header.push_back("y" + std::to_string(i));
  }
  header.push_back("asymmetry");
  repro::CsvWriter traces(out + "/data/symmetric_stack/traces.csv", header,
                          {"Paper A Sect. 4.2, geometry reconstructed (Fig. 9 lost)"});
  repro::CsvWriter snaps(out + "/data/symmetric_stack/snapshots.csv", repro::snapshot_header());
  const symmetric_stack::Result r = symmetric_stack::run(st, &traces, &snaps);
  traces.commit();
  snaps.commit();
  progress("done: largest mirror asymmetry " + repro::format_short(r.worst_position, 3) + " m, " +
           repro::format_short(r.worst_rotation, 3) + " rad");
  const std::vector<repro::Claim> claims = {symmetric_stack::row(r)};
  repro::write_claims(repro::claims_path(out, "4_2_symmetric_stack"), claims);
  return 0;
}
