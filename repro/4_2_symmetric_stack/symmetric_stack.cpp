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

// The driver: its name in errors, its progress lines' prefix and its usage line.
const repro::DriverInfo kInfo = {"symmetric_stack", "4.2 symmetric stack",
                                 "Paper A Sect. 4.2 (Figs. 9-10): a polygon hitting a symmetric polygonal system."};

namespace {

// The run: what main's driver_main calls once the command line is checked.
int reproduce(const repro::Driver& d) {
  const dda::paper::SymmetricStack st = dda::paper::symmetric_stack();
  repro::TableWriter<symmetric_stack::Trace> traces(
      d.out + "/data/symmetric_stack/traces.csv",
      symmetric_stack::trace_columns(static_cast<int>(st.scene.blocks.size())),
      {"Paper A Sect. 4.2, geometry reconstructed (Fig. 9 lost)"});
  repro::TableWriter<repro::VertexRow> snaps(d.out + "/data/symmetric_stack/snapshots.csv", repro::snapshot_columns());
  const symmetric_stack::Result r = symmetric_stack::run(st, &traces, &snaps);
  traces.commit();
  snaps.commit();
  d.progress("done: largest mirror asymmetry " + repro::format_short(r.worst_position, 3) + " m, " +
             repro::format_short(r.worst_rotation, 3) + " rad");
  repro::write_claims(repro::claims_path(d.out, "4_2_symmetric_stack"), {symmetric_stack::row(r)});
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return repro::driver_main(argc, argv, kInfo, {}, reproduce); }
