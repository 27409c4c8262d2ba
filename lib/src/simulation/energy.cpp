// Energy and momentum of the state: kinetic, gravity and strain energy of
// the free blocks, and the penalty energy stored in the contacts' overlaps.
#include "simulation/internal.hpp"

namespace dda {

Vec2 Simulation::momentum() const {
  Vec2 p{};
  for (int i = 0; i < block_count(); ++i)
    if (!fixed_[i]) p += mass(i) * Vec2{vel_[i][0], vel_[i][1]};
  return p;
}

Energy Simulation::energy() const {
  Energy e = block_energy();
  for (const ContactInfo& ci : contact_info_) {
    const Polygon& a = poly_[ci.cp];
    const Polygon& b = poly_[ci.tp];
    const double tol = pair_tolerance(a, b);
    const Polygon ip = intersection_polygon(a, b, tol);
    e.contact += contact_energy(sides_[ci.cp].side, sides_[ci.tp].side, ip, tol);
  }
  return e;
}

Energy Simulation::block_energy() const {
  // Kinetic, gravity and strain energy of the free blocks (no contacts).
  Energy e;
  for (int i = 0; i < block_count(); ++i) {
    if (fixed_[i]) continue;
    const Mat6 m = mass_matrix(moments_[i], density_[i]);
    e.kinetic += 0.5 * vel_[i].dot(m * vel_[i]);
    e.gravity -= mass(i) * dot(scene_.gravity, moments_[i].centroid);
    if (strains_) e.strain += 0.5 * moments_[i].area * stress_[i].dot(elastic_[i].ldlt().solve(stress_[i]));
  }
  return e;
}

}  // namespace dda
