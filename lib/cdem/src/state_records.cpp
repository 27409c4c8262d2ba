// Writing and reading the parts of the CDEM model state (state_records.hpp):
// one put and one get per record type, each field in the order
// dda/cdem/model_state.hpp lists it; the reads refuse enum values out of
// range.
#include <cstdint>
#include <string>
#include <vector>

#include "state_records.hpp"

namespace dda::cdem::state_io {

// --- writing -------------------------------------------------------------

void put(ByteWriter& w, const BlockState& b) {
  put_all(w, b.nodes, b.outline, b.material, b.fixed, b.initial_mean);
}
void put(ByteWriter& w, const Element& e) {
  put_all(w, e.n, e.block, e.level, e.parent, e.lattice, e.active, e.stress, e.last, e.mass);
}
void put(ByteWriter& w, const Lattice& l) {
  put_all(w, l.elem, l.k, l.nodes, l.children);
}
void put(ByteWriter& w, const MeshEdge& e) {
  put_all(w, e.lo, e.hi, e.elems, e.nodes);
}
void put(ByteWriter& w, const BoundaryEdge& e) {
  put_all(w, e.a, e.b, e.block, e.fine);
}
void put(ByteWriter& w, const Clone& c) {
  put_all(w, c.main, c.t, c.w, c.ea, c.eb, c.area, c.fine, c.sliding, c.lambda);
}
void put(ByteWriter& w, const SubElement& e) {
  put_all(w, e.n, e.parent, e.stress, e.last, e.mass);
}
void put(ByteWriter& w, const SubModel& s) {
  put_all(w, s.record, s.k, s.substeps, s.parents, s.x, s.v, s.f, s.m, s.inv_m, s.block, s.drive, s.drive_w);
  put_bytes(w, s.prescribed);
  put_all(w, s.home, s.home_ab, s.home_c, s.elems, s.coarse, s.coarse_x0, s.coarse_force, s.bc);
}
void put(ByteWriter& w, const SubModelRequest& q) {
  put_all(w, q.main_node, q.ea, q.eb, q.point, q.dt2);
}
void put(ByteWriter& w, const SubModelRecord& r) {
  put_all(w, r.created, r.deleted, r.main_node, r.main_block, r.target_block, r.elements, r.k, r.sub_nodes,
          r.free_nodes, r.substeps, r.sub_critical_dt, r.substeps_taken, r.radius, r.kinetic_dropped, r.strain_change);
}
void put(ByteWriter& w, const PenaltyContact& p) {
  put_all(w, p.node, p.a, p.b, p.xi, p.depth, p.normal);
}
void put(ByteWriter& w, const Snapshot::Tri& t) {
  put_all(w, t.x, t.velocity, t.block, t.fine, t.node, t.v, t.stress);
}
void put(ByteWriter& w, const Snapshot& s) {
  put_all(w, s.time, s.tris, s.clone_points);
}
void put(ByteWriter& w, const TouchRecord& t) {
  put_all(w, t.time, t.step_start, t.step_end, t.dt1, t.dt2, t.fine, t.main_node, t.main_block, t.target_block,
          t.node_to_node, t.point, t.mass_main, t.mass_target, t.v_main, t.v_target, t.v_clone, t.energy_loss_eq5,
          t.energy_loss_eq5_group, t.energy_loss, t.impulse_normal, t.impulse_tangential, t.coulomb_capped,
          t.subdivision, t.radius, t.refined_elements, t.snapshot);
}
void put(ByteWriter& w, const SeparationRecord& s) {
  put_all(w, s.time, s.main_node, s.main_block, s.target_block);
  put_enum(w, s.criterion);
  put_all(w, s.normal_force, s.shear_force, s.limit, s.contact_area, s.fine);
}

// --- reading -------------------------------------------------------------

void get(ByteReader& r, BlockState& b) {
  get_all(r, b.nodes, b.outline, b.material, b.fixed, b.initial_mean);
}
void get(ByteReader& r, Element& e) {
  get_all(r, e.n, e.block, e.level, e.parent, e.lattice, e.active, e.stress, e.last, e.mass);
}
void get(ByteReader& r, Lattice& l) {
  get_all(r, l.elem, l.k, l.nodes, l.children);
}
void get(ByteReader& r, MeshEdge& e) {
  get_all(r, e.lo, e.hi, e.elems, e.nodes);
}
void get(ByteReader& r, BoundaryEdge& e) {
  get_all(r, e.a, e.b, e.block, e.fine);
}
void get(ByteReader& r, Clone& c) {
  get_all(r, c.main, c.t, c.w, c.ea, c.eb, c.area, c.fine, c.sliding, c.lambda);
}
void get(ByteReader& r, SubElement& e) {
  get_all(r, e.n, e.parent, e.stress, e.last, e.mass);
}
void get(ByteReader& r, SubModel& s) {
  get_all(r, s.record, s.k, s.substeps, s.parents, s.x, s.v, s.f, s.m, s.inv_m, s.block, s.drive, s.drive_w);
  get_bytes(r, s.prescribed);
  get_all(r, s.home, s.home_ab, s.home_c, s.elems, s.coarse, s.coarse_x0, s.coarse_force, s.bc);
}
void get(ByteReader& r, SubModelRequest& q) {
  get_all(r, q.main_node, q.ea, q.eb, q.point, q.dt2);
}
void get(ByteReader& r, SubModelRecord& x) {
  get_all(r, x.created, x.deleted, x.main_node, x.main_block, x.target_block, x.elements, x.k, x.sub_nodes,
          x.free_nodes, x.substeps, x.sub_critical_dt, x.substeps_taken, x.radius, x.kinetic_dropped, x.strain_change);
}
void get(ByteReader& r, PenaltyContact& p) {
  get_all(r, p.node, p.a, p.b, p.xi, p.depth, p.normal);
}
void get(ByteReader& r, Snapshot::Tri& t) {
  get_all(r, t.x, t.velocity, t.block, t.fine, t.node, t.v, t.stress);
}
void get(ByteReader& r, Snapshot& s) {
  get_all(r, s.time, s.tris, s.clone_points);
}
void get(ByteReader& r, TouchRecord& t) {
  get_all(r, t.time, t.step_start, t.step_end, t.dt1, t.dt2, t.fine, t.main_node, t.main_block, t.target_block,
          t.node_to_node, t.point, t.mass_main, t.mass_target, t.v_main, t.v_target, t.v_clone, t.energy_loss_eq5,
          t.energy_loss_eq5_group, t.energy_loss, t.impulse_normal, t.impulse_tangential, t.coulomb_capped,
          t.subdivision, t.radius, t.refined_elements, t.snapshot);
}
void get(ByteReader& r, SeparationRecord& s) {
  get_all(r, s.time, s.main_node, s.main_block, s.target_block);
  s.criterion = get_enum<SeparationCriterion>(r, static_cast<std::uint8_t>(SeparationCriterion::kSlidOff),
                                              "a separation's criterion");
  get_all(r, s.normal_force, s.shear_force, s.limit, s.contact_area, s.fine);
}

}  // namespace dda::cdem::state_io
