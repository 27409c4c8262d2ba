// Negative controls of the B-6 energy rows: the energy account closing at
// every row and the touch loss following Eq. 5 over the contact-point mass.
// Each test applies the driver's own criterion to the paper's run (PASS)
// and to a deliberately wrong account or series (FAIL): a loss left out, a
// made-up series, Eq. 5 with the wrong masses.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "dda/cdem/model.hpp"
#include "dda/cdem/scenes.hpp"
#include "repro/B_6_two_prisms/controls_b6.hpp"
#include "repro/B_6_two_prisms/two_prisms.hpp"
#include "repro/common/claims.hpp"

// The default is the sub-model (Sect. 5), whose row fails (paper_method:
// the fine-scale kinetic energy of its free sub-nodes is in `other`);
// the in-place option's row beside it passes.
TEST_CASE(prisms::kTestEnergyCloses, "[controls][B-6][energy]") {
  const prisms::Result sub = prisms::simulate(dda::cdem::two_prisms(2));
  const prisms::Result paper = prisms::simulate(dda::cdem::two_prisms(2, controls_b6::in_place()));
  const prisms::Result coarse = prisms::simulate(dda::cdem::two_prisms(2, controls_b6::no_subdivision()));
  controls_b6::names_test_both(sub, paper, coarse,
                "the energy account closes at every time-series row (kinetic + strain + touch loss + refine and "
                "deletion losses)",
                prisms::kTestEnergyCloses);
  CHECK(prisms::energy_closes(paper.accounts));
  CHECK_FALSE(prisms::energy_closes(sub.accounts));
  // The account without the deletion loss (2.6 kJ/m, 0.9 % of E0): the
  // patch deletion's energy is unaccounted for.
  std::vector<dda::cdem::CdemEnergyAccount> without = paper.accounts;
  for (auto& a : without) a.deletion_loss = 0.0;
  CHECK_FALSE(prisms::energy_closes(without));
  // A made-up series: 1 % more kinetic energy in every row.
  std::vector<dda::cdem::CdemEnergyAccount> made_up = paper.accounts;
  for (auto& a : made_up) a.kinetic *= 1.01;
  CHECK_FALSE(prisms::energy_closes(made_up));
  CHECK_FALSE(prisms::energy_closes({}));  // no rows: nothing closes
}

TEST_CASE(prisms::kTestContactMass, "[controls][B-6][energy]") {
  const prisms::Result coarse = prisms::simulate(dda::cdem::two_prisms(2, controls_b6::no_subdivision()));
  const double m_node = prisms::touching_node_mass(prisms::simulate(dda::cdem::two_prisms(2, controls_b6::in_place())));
  std::vector<prisms::MassPoint> pts;
  for (double f : {1.0 / 4, 1.0 / 16, 1.0 / 64})
    pts.push_back(prisms::contact_mass_point(f * m_node, prisms::kMassMaxSubdivision));
  CHECK(prisms::touch_loss_follows_eq5(pts));
  // Eq. 5 evaluated with the coarse nodes' masses instead of the clone's.
  std::vector<prisms::MassPoint> wrong_masses = pts;
  for (auto& p : wrong_masses) p.loss_eq5 = coarse.touch.energy_loss_eq5;
  CHECK_FALSE(prisms::touch_loss_follows_eq5(wrong_masses));
  // A made-up series whose loss grows as the mass falls (Eq. 5 set equal to it).
  std::vector<prisms::MassPoint> reversed = pts;
  for (std::size_t i = 0; i < reversed.size(); ++i) {
    reversed[i].loss = pts[pts.size() - 1 - i].loss;
    reversed[i].loss_eq5 = reversed[i].loss;
  }
  CHECK_FALSE(prisms::touch_loss_follows_eq5(reversed));
  CHECK_FALSE(prisms::touch_loss_follows_eq5({pts.front()}));  // one mass is no range
}
