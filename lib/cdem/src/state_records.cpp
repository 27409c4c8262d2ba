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
  put(w, b.nodes);
  put(w, b.outline);
  put(w, b.material);
  put(w, b.fixed);
  put(w, b.initial_mean);
}
void put(ByteWriter& w, const Element& e) {
  put(w, e.n);
  put(w, e.block);
  put(w, e.level);
  put(w, e.parent);
  put(w, e.lattice);
  put(w, e.active);
  put(w, e.stress);
  put(w, e.last);
  put(w, e.mass);
}
void put(ByteWriter& w, const Lattice& l) {
  put(w, l.elem);
  put(w, l.k);
  put(w, l.nodes);
  put(w, l.children);
}
void put(ByteWriter& w, const MeshEdge& e) {
  put(w, e.lo);
  put(w, e.hi);
  put(w, e.elems);
  put(w, e.nodes);
}
void put(ByteWriter& w, const BoundaryEdge& e) {
  put(w, e.a);
  put(w, e.b);
  put(w, e.block);
  put(w, e.fine);
}
void put(ByteWriter& w, const Clone& c) {
  put(w, c.main);
  put(w, c.t);
  put(w, c.w);
  put(w, c.ea);
  put(w, c.eb);
  put(w, c.area);
  put(w, c.fine);
  put(w, c.sliding);
  put(w, c.lambda);
}
void put(ByteWriter& w, const SubElement& e) {
  put(w, e.n);
  put(w, e.parent);
  put(w, e.stress);
  put(w, e.last);
  put(w, e.mass);
}
void put(ByteWriter& w, const SubModel& s) {
  put(w, s.record);
  put(w, s.k);
  put(w, s.substeps);
  put(w, s.parents);
  put(w, s.x);
  put(w, s.v);
  put(w, s.f);
  put(w, s.m);
  put(w, s.inv_m);
  put(w, s.block);
  put(w, s.drive);
  put(w, s.drive_w);
  put_bytes(w, s.prescribed);
  put(w, s.home);
  put(w, s.home_ab);
  put(w, s.home_c);
  put(w, s.elems);
  put(w, s.coarse);
  put(w, s.coarse_x0);
  put(w, s.coarse_force);
  put(w, s.bc);
}
void put(ByteWriter& w, const SubModelRequest& q) {
  put(w, q.main_node);
  put(w, q.ea);
  put(w, q.eb);
  put(w, q.point);
  put(w, q.dt2);
}
void put(ByteWriter& w, const SubModelRecord& r) {
  put(w, r.created);
  put(w, r.deleted);
  put(w, r.main_node);
  put(w, r.main_block);
  put(w, r.target_block);
  put(w, r.elements);
  put(w, r.k);
  put(w, r.sub_nodes);
  put(w, r.free_nodes);
  put(w, r.substeps);
  put(w, r.sub_critical_dt);
  put(w, r.substeps_taken);
  put(w, r.radius);
  put(w, r.kinetic_dropped);
  put(w, r.strain_change);
}
void put(ByteWriter& w, const PenaltyContact& p) {
  put(w, p.node);
  put(w, p.a);
  put(w, p.b);
  put(w, p.xi);
  put(w, p.depth);
  put(w, p.normal);
}
void put(ByteWriter& w, const Snapshot::Tri& t) {
  put(w, t.x);
  put(w, t.velocity);
  put(w, t.block);
  put(w, t.fine);
  put(w, t.node);
  put(w, t.v);
  put(w, t.stress);
}
void put(ByteWriter& w, const Snapshot& s) {
  put(w, s.time);
  put(w, s.tris);
  put(w, s.clone_points);
}
void put(ByteWriter& w, const TouchRecord& t) {
  put(w, t.time);
  put(w, t.step_start);
  put(w, t.step_end);
  put(w, t.dt1);
  put(w, t.dt2);
  put(w, t.fine);
  put(w, t.main_node);
  put(w, t.main_block);
  put(w, t.target_block);
  put(w, t.node_to_node);
  put(w, t.point);
  put(w, t.mass_main);
  put(w, t.mass_target);
  put(w, t.v_main);
  put(w, t.v_target);
  put(w, t.v_clone);
  put(w, t.energy_loss_eq5);
  put(w, t.energy_loss_eq5_group);
  put(w, t.energy_loss);
  put(w, t.impulse_normal);
  put(w, t.impulse_tangential);
  put(w, t.coulomb_capped);
  put(w, t.subdivision);
  put(w, t.radius);
  put(w, t.refined_elements);
  put(w, t.snapshot);
}
void put(ByteWriter& w, const SeparationRecord& s) {
  put(w, s.time);
  put(w, s.main_node);
  put(w, s.main_block);
  put(w, s.target_block);
  put_enum(w, s.criterion);
  put(w, s.normal_force);
  put(w, s.shear_force);
  put(w, s.limit);
  put(w, s.contact_area);
  put(w, s.fine);
}

// --- reading -------------------------------------------------------------

void get(ByteReader& r, BlockState& b) {
  get(r, b.nodes);
  get(r, b.outline);
  get(r, b.material);
  get(r, b.fixed);
  get(r, b.initial_mean);
}
void get(ByteReader& r, Element& e) {
  get(r, e.n);
  get(r, e.block);
  get(r, e.level);
  get(r, e.parent);
  get(r, e.lattice);
  get(r, e.active);
  get(r, e.stress);
  get(r, e.last);
  get(r, e.mass);
}
void get(ByteReader& r, Lattice& l) {
  get(r, l.elem);
  get(r, l.k);
  get(r, l.nodes);
  get(r, l.children);
}
void get(ByteReader& r, MeshEdge& e) {
  get(r, e.lo);
  get(r, e.hi);
  get(r, e.elems);
  get(r, e.nodes);
}
void get(ByteReader& r, BoundaryEdge& e) {
  get(r, e.a);
  get(r, e.b);
  get(r, e.block);
  get(r, e.fine);
}
void get(ByteReader& r, Clone& c) {
  get(r, c.main);
  get(r, c.t);
  get(r, c.w);
  get(r, c.ea);
  get(r, c.eb);
  get(r, c.area);
  get(r, c.fine);
  get(r, c.sliding);
  get(r, c.lambda);
}
void get(ByteReader& r, SubElement& e) {
  get(r, e.n);
  get(r, e.parent);
  get(r, e.stress);
  get(r, e.last);
  get(r, e.mass);
}
void get(ByteReader& r, SubModel& s) {
  get(r, s.record);
  get(r, s.k);
  get(r, s.substeps);
  get(r, s.parents);
  get(r, s.x);
  get(r, s.v);
  get(r, s.f);
  get(r, s.m);
  get(r, s.inv_m);
  get(r, s.block);
  get(r, s.drive);
  get(r, s.drive_w);
  get_bytes(r, s.prescribed);
  get(r, s.home);
  get(r, s.home_ab);
  get(r, s.home_c);
  get(r, s.elems);
  get(r, s.coarse);
  get(r, s.coarse_x0);
  get(r, s.coarse_force);
  get(r, s.bc);
}
void get(ByteReader& r, SubModelRequest& q) {
  get(r, q.main_node);
  get(r, q.ea);
  get(r, q.eb);
  get(r, q.point);
  get(r, q.dt2);
}
void get(ByteReader& r, SubModelRecord& x) {
  get(r, x.created);
  get(r, x.deleted);
  get(r, x.main_node);
  get(r, x.main_block);
  get(r, x.target_block);
  get(r, x.elements);
  get(r, x.k);
  get(r, x.sub_nodes);
  get(r, x.free_nodes);
  get(r, x.substeps);
  get(r, x.sub_critical_dt);
  get(r, x.substeps_taken);
  get(r, x.radius);
  get(r, x.kinetic_dropped);
  get(r, x.strain_change);
}
void get(ByteReader& r, PenaltyContact& p) {
  get(r, p.node);
  get(r, p.a);
  get(r, p.b);
  get(r, p.xi);
  get(r, p.depth);
  get(r, p.normal);
}
void get(ByteReader& r, Snapshot::Tri& t) {
  get(r, t.x);
  get(r, t.velocity);
  get(r, t.block);
  get(r, t.fine);
  get(r, t.node);
  get(r, t.v);
  get(r, t.stress);
}
void get(ByteReader& r, Snapshot& s) {
  get(r, s.time);
  get(r, s.tris);
  get(r, s.clone_points);
}
void get(ByteReader& r, TouchRecord& t) {
  get(r, t.time);
  get(r, t.step_start);
  get(r, t.step_end);
  get(r, t.dt1);
  get(r, t.dt2);
  get(r, t.fine);
  get(r, t.main_node);
  get(r, t.main_block);
  get(r, t.target_block);
  get(r, t.node_to_node);
  get(r, t.point);
  get(r, t.mass_main);
  get(r, t.mass_target);
  get(r, t.v_main);
  get(r, t.v_target);
  get(r, t.v_clone);
  get(r, t.energy_loss_eq5);
  get(r, t.energy_loss_eq5_group);
  get(r, t.energy_loss);
  get(r, t.impulse_normal);
  get(r, t.impulse_tangential);
  get(r, t.coulomb_capped);
  get(r, t.subdivision);
  get(r, t.radius);
  get(r, t.refined_elements);
  get(r, t.snapshot);
}
void get(ByteReader& r, SeparationRecord& s) {
  get(r, s.time);
  get(r, s.main_node);
  get(r, s.main_block);
  get(r, s.target_block);
  s.criterion = get_enum<SeparationCriterion>(r, static_cast<std::uint8_t>(SeparationCriterion::kSlidOff),
                                              "a separation's criterion");
  get(r, s.normal_force);
  get(r, s.shear_force);
  get(r, s.limit);
  get(r, s.contact_area);
  get(r, s.fine);
}

}  // namespace dda::cdem::state_io
