// Paper A, Sect. 4.3 "Sliding block on an inclined plane" (Figs. 11-12).
//
// GEOMETRY RECONSTRUCTED: Fig. 11 is lost. A 1 m square B on a fixed 12 m
// slab A inclined at 30 deg (dda::paper::incline), from rest, friction angle
// phi = 0, 10, 20 deg; rho 2000, E 1 GPa, nu 0.25, kn 10 MPa, kt 1e7 N/m,
// dt 1e-5 s (Table 4), 1.0 s. Expected (paper): the sliding distance follows
// Eq. 30, l = g (sin t - cos t tan phi) t^2 / 2 ("good agreements").
//
// Extra runs beyond the paper (each a report row): B starting just touching
// instead of at its static penetration, and a stiffer tangential penalty,
// to show where the gap to Eq. 30 comes from; beside each Eq. 30 row the
// friction start-up option (Scene::damping settle_sticking: settled with
// sticking contacts, then released; not the paper's start), which removes
// the head start of the unloaded springs; and the creep of a block that has
// slid to a stop (20 deg slope, phi = 30 deg) with the paper's friction
// update and with the return mapping. Expected: the option within 1 % of
// Eq. 30 at the paper's kt; creep below 1 mm with the return mapping.
//
// Option: --return-mapping 1 runs every case with the elastic-plastic
// friction update (dda::FrictionUpdate::kReturnMapping) instead of the
// paper's Eq. 26; the claims say so.
//
// Output: data/incline/sliding.csv (Fig. 12), sliding_start_up.csv (the start-up
// option's curves), claims/4_3_incline.csv.
#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/4_3_incline/incline.hpp"
#include "repro/common/common.hpp"

using incline::kG;
using incline::kPi;
using incline::Run;
using incline::run;
using repro::format_short;

// The driver: its name in errors, its progress lines' prefix and its usage line.
const repro::DriverInfo kInfo = {
    "incline", "4.3 incline",
    "Paper A Sect. 4.3 (Figs. 11-12, geometry reconstructed): a block sliding on a 30-degree incline."};

// Its options besides --out.
const std::initializer_list<repro::OptionHelp> kOptions = {
    {"--return-mapping", "0|1", "1: return-mapping friction update instead of the paper's (default 0)", true}};

namespace {

using Claims = std::vector<repro::Claim>;

// The paper's three cases (Fig. 12) and beside each the friction start-up
// option (not the paper's): their curves in sliding.csv and
// sliding_start_up.csv, their Eq. 30 rows.
void paper_cases(const repro::Driver& d, dda::FrictionUpdate update, const std::string& update_text, Claims& claims) {
  repro::TableWriter<incline::Sample> csv(d.out + "/data/incline/sliding.csv", incline::sliding_columns(),
                                          {"Paper A Sect. 4.3, geometry reconstructed (Fig. 11 lost): theta = 30 deg",
                                           "start: the paper's (from rest); " + update_text});
  repro::TableWriter<incline::Sample> option_csv(
      d.out + "/data/incline/sliding_start_up.csv", incline::sliding_columns(),
      {"Paper A Sect. 4.3, geometry reconstructed (Fig. 11 lost): theta = 30 deg",
       "start: friction start-up option (settled with sticking contacts, not the paper's start); " + update_text});
  for (double phi : {0.0, 10.0, 20.0}) {
    const Run r = run(dda::paper::incline(phi), &csv, phi, update);
    d.progress("phi = " + format_short(phi) + ": l = " + format_short(r.distance, 6) + " m, Eq. 30 " +
               format_short(r.analytic, 6) + " m");
    claims.push_back(incline::eq30_row(phi, r));
    repro::explain_fail(claims.back(), repro::Root::kFrictionStartUp,
                        "Table 4's finite kt = 1e7 N/m: B first sticks elastically and gains a lead that rigid "
                        "Coulomb friction (Eq. 30) does not have (predicted below), and the friction torque rocks B "
                        "on the soft contact of the paper's H = 6.5 m; the friction start-up option beyond the "
                        "paper (next row: springs pre-loaded by settling) passes");
    // Beside it, the friction start-up option (not the paper's).
    const Run s = run(incline::with_start_up(dda::paper::incline(phi)), &option_csv, phi, update);
    repro::explain_fail(
        repro::add_claim(
            claims,
            {"4.3 (option)",
             "phi = " + format_short(phi) +
                 " deg, friction start-up option (settled with sticking contacts, not the "
                 "paper's start): sliding distance follows Eq. 30",
             "Eq. 30",
             "l = " + format_short(s.distance, 5) + " m vs " + format_short(s.analytic, 5) + " m, rel. error " +
                 format_short(s.rel_error(), 3),
             "|rel. error| < 1 %", incline::eq30_met(s)},
            phi > 0.0 ? incline::kControlEq30Friction : repro::control_test(incline::kControlEq30Frictionless),
            repro::Scope::kOption),
        repro::Root::kUnexplained, "the start-up option should remove the stick-phase lead; not explained");
  }
  csv.commit();
  option_csv.commit();
}

// A block at rest on a slope gentler than its friction angle, with the paper's
// start and with the start-up option.
void rest_rows(const repro::Driver& d, dda::FrictionUpdate update, Claims& claims) {
  const Run r = run(dda::paper::incline(incline::kRestPhi), nullptr, incline::kRestPhi, update);
  claims.push_back(incline::rest_row(r));
  repro::explain_fail(claims.back(), repro::Root::kFrictionStartUp,
                      "the paper's undamped explicit scheme loads the stick spring (Eq. 26, kt = 1e7 N/m) suddenly: "
                      "the shear demand overshoots to twice its static value, 2 m g sin 30 = 1.0 m g, beyond the "
                      "limit m g cos 30 tan 35 = 0.61 m g, so B slips in its stick oscillations (analytic); the "
                      "return-mapping update still moves B 0.11 m, so it is not the re-stick "
                      "ratchet; the friction start-up option beyond the paper (next row) passes");
  d.progress("phi = " + format_short(incline::kRestPhi) + ": moved " + format_short(r.distance, 3) + " m");
  // Beside it, the friction start-up option (not the paper's): the stick
  // spring is loaded while settling, so gravity is not applied suddenly.
  repro::Claim c = incline::rest_row(
      run(incline::with_start_up(dda::paper::incline(incline::kRestPhi)), nullptr, incline::kRestPhi, update));
  c.section = "4.3 (option)";
  c.claim += ", friction start-up option (settled with sticking contacts, not the paper's start)";
  c.key = "rest-start-up";
  c.scope = repro::Scope::kOption;
  claims.push_back(c);
  repro::explain_fail(claims.back(), repro::Root::kUnexplained,
                      "the start-up option should remove the sudden loading; not explained");
}

// Creep after a stop, with each friction update (incline::creep).
void creep_rows(Claims& claims) {
  for (dda::FrictionUpdate u : {dda::FrictionUpdate::kPaper, dda::FrictionUpdate::kReturnMapping}) {
    const incline::Creep cr = incline::creep(u);
    const double early = cr.early, rate = cr.rate;
    const bool paper = u == dda::FrictionUpdate::kPaper;
    repro::explain_fail(
        repro::add_claim(
            claims,
            {paper ? "4.3 (extra)" : "4.3 (option)",
             std::string("creep: a block that slid to a stop on a slope gentler than its friction angle "
                         "(20 deg, phi = 30 deg, H = 1 m) stays put, ") +
                 (paper ? "paper's friction update (Eq. 26)" : "return-mapping friction update (not the paper's)"),
             "Coulomb friction: no motion once stopped",
             "slid " + format_short(early * 1e3, 3) + " mm, then creeps at " + format_short(rate * 1e3, 3) + " mm/s",
             "|creep rate| < 1 mm/s", incline::creep_stopped(cr)},
            repro::control_test(incline::kControlCreep), paper ? repro::Scope::kExtension : repro::Scope::kOption),
        paper ? repro::Root::kFrictionUpdate : repro::Root::kUnexplained,
        paper ? "Eq. 26's friction update: the return mapping on the same run (next row) stays put"
              : "the return mapping should stop creep; not explained");
  }
}

// Where the gap comes from. (1) With finite kt the pair starts in an
// elastic stick phase: friction ramps up from zero until kt |d| reaches
// fn tan(phi), so B gains speed that rigid Coulomb friction (Eq. 30) would
// not give it. For a spring-mass start from rest (translation only) slip
// begins at w t* = acos(1 - tan(phi) cot(theta)), w = sqrt(kt / m), and B
// leads Eq. 30 by dv = g [tan(phi) cos(theta) t* - sin(theta) (t* - sin(w t*) / w)].
// (2) The friction torque rocks B on the soft contact (H = 6.5 m from the
// long slab) and the contact point's motion reverses, which re-enters the
// stick phase. Rows below: the predicted offset, and runs with a smaller
// H and stiffer kt, which do not remove the gap (the sudden start remains),
// each beside the start-up option, which does.
void stick_lead_row(Claims& claims) {
  const double th = 30.0 * kPi / 180.0, mu = std::tan(20.0 * kPi / 180.0), m = 2000.0, t_end = 1.0;
  const double w = std::sqrt(1e7 / m);
  const double ts = std::acos(1.0 - mu / std::tan(th)) / w;
  const double dv = kG * (mu * std::cos(th) * ts - std::sin(th) * (ts - std::sin(w * ts) / w));
  const double la = dda::paper::incline_distance(kG, th, std::atan(mu), t_end);
  const double predicted = dv * (t_end - ts) / la;
  claims.push_back(
      {"4.3 (extra)", "phi = 20 deg: predicted lead of B from the elastic stick phase alone",
       "not discussed in the paper",
       "stick phase t* = " + format_short(ts * 1e3, 3) + " ms, predicted rel. lead " + format_short(predicted, 3),
       "information (no tolerance)", false, repro::Kind::kMeasurement});
  claims.back().scope = repro::Scope::kExtension;
}

// H = 1 m (less rocking) and stiffer kt (shorter stick phase): measured,
// neither removes the gap (+1.9 % at kt = 1e9 N/m, whatever dt or the
// integration), while the start-up option on the same runs does (1.2e-4):
// from rest, friction and its torque about the centroid (applied at the
// base, h / 2 below it) are switched on at once on an undamped block,
// which starts rocking on its contact and keeps rocking (the normal force
// still swings +-12 % at t = 1 s); each row has the option beside it.
void stiffer_rows(dda::FrictionUpdate update, Claims& claims) {
  for (double kt : {1e7, 1e9, 1e11}) {
    dda::paper::Incline in = dda::paper::incline(20.0, 30.0, 1.0, true, 1.0);
    in.scene.contact.kt = kt;
    const std::string what =
        "phi = 20 deg, H = 1 m (the paper's rule gives 6.5 m here)" +
        (kt == 1e7 ? std::string(", kt = 1e7 N/m (Table 4)") : ", kt = " + format_short(kt) + " N/m (paper: 1e7)");
    const Run r = run(in, nullptr, 20.0, update);
    repro::explain_fail(repro::add_claim(claims,
                                         {"4.3 (extra)", what + ": sliding distance follows Eq. 30", "Eq. 30",
                                          "rel. error " + format_short(r.rel_error(), 3) +
                                              " (l = " + format_short(r.distance, 5) + " m)",
                                          "|rel. error| < 1 %", incline::eq30_met(r)},
                                         incline::kControlEq30Friction, repro::Scope::kExtension),
                        repro::Root::kFrictionStartUp,
                        "the paper's start from rest: friction and its torque switched on at once on the undamped "
                        "block, which gains a lead in the stick phase and keeps rocking on its contact (measured: "
                        "independent of dt and of the integration); the friction start-up option beyond the paper "
                        "(next row) passes");
    const Run s = run(incline::with_start_up(in), nullptr, 20.0, update);
    repro::explain_fail(
        repro::add_claim(
            claims,
            {"4.3 (option)",
             what + ", friction start-up option (not the paper's start): sliding distance "
                    "follows Eq. 30",
             "Eq. 30", "rel. error " + format_short(s.rel_error(), 3) + " (l = " + format_short(s.distance, 5) + " m)",
             "|rel. error| < 1 %", incline::eq30_met(s)},
            incline::kControlEq30Friction, repro::Scope::kOption),
        repro::Root::kUnexplained, "the start-up option should remove the sudden start; not explained");
  }
}

// B starting just touching instead of at its static penetration.
void touching_row(dda::FrictionUpdate update, Claims& claims) {
  const Run r = run(dda::paper::incline(20.0, 30.0, 1.0, false), nullptr, 20.0, update);
  repro::explain_fail(
      repro::add_claim(claims,
                       {"4.3 (extra)", "phi = 20 deg, B starting just touching (falls into its static penetration)",
                        "not stated in the paper", "rel. error " + format_short(r.rel_error(), 3), "|rel. error| < 1 %",
                        incline::eq30_met(r)},
                       incline::kControlEq30Friction, repro::Scope::kExtension),
      repro::Root::kUnstatedSetup,
      "the paper does not give B's start; dropped onto the slab B bounces and rocks before it "
      "slides, so this start is not the paper's case");
}

// The run: what main's driver_main calls once the command line is checked.
int reproduce(const repro::Driver& d) {
  const bool return_mapping = d.whole("--return-mapping", 0) != 0;
  const dda::FrictionUpdate update = return_mapping ? dda::FrictionUpdate::kReturnMapping : dda::FrictionUpdate::kPaper;
  // The mode of each curve, in a comment line the figure reads.
  const std::string update_text =
      std::string("friction update: ") + (return_mapping ? "return mapping (not the paper's)" : "the paper's Eq. 26");
  Claims claims;
  paper_cases(d, update, update_text, claims);
  rest_rows(d, update, claims);
  creep_rows(claims);
  stick_lead_row(claims);
  stiffer_rows(update, claims);
  touching_row(update, claims);
  if (return_mapping)
    for (repro::Claim& c : claims) c.claim += " [RETURN MAPPING: friction update not the paper's Eq. 26]";
  repro::write_claims(repro::claims_path(d.out, "4_3_incline"), claims);
  d.progress("done");
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return repro::driver_main(argc, argv, kInfo, kOptions, reproduce); }
