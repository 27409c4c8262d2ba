#include "dda/cdem/scenes.hpp"

#include "dda/paper_scenes.hpp"

namespace dda::cdem {

dda::Scene two_prisms_scene(const PrismGeometry& g) {
  dda::Scene s;
  s.name = "B-6 two triangular prisms (reconstructed)";
  s.materials = {{2700.0, 40e9, 0.25}};
  s.contact.kn = 40e9 / 100.0;
  s.dt = 5e-4;
  s.duration = 0.5;
  const double h2 = 0.5 * g.height;
  BlockSpec i;
  i.vertices = {{-g.length, -h2}, {0.0, 0.0}, {-g.length, h2}};
  i.velocity = {g.speed, 0.0};
  i.name = "i";
  BlockSpec j;
  j.vertices = {{g.gap, -h2}, {g.gap + g.length, 0.0}, {g.gap, h2}};
  j.name = "j";
  s.blocks = {i, j};
  return s;
}

CdemScene two_prisms(int divisions, const CdemOptions& options, const PrismGeometry& g) {
  CdemScene s = from_dda_scene(two_prisms_scene(g), divisions, options);
  s.name = "B-6 two triangular prisms (reconstructed), CDEM";
  return s;
}

CdemScene two_squares(int divisions, const CdemOptions& options) {
  CdemScene s = from_dda_scene(dda::paper::two_squares(), divisions, options);
  s.name = "4.1 two squares, CDEM";
  return s;
}

}  // namespace dda::cdem
