// The encoding of the CDEM model state's parts (dda/cdem/model_state.hpp)
// in a checkpoint stream, with the dda/state_bytes.hpp encoding: put(w, x)
// writes a part, get(r, x) reads it back, field by field in the order the
// header lists them (doubles by their bits, lists with their length, enums
// and flags as bytes). A read refuses an enum value out of range, a flag
// that is neither 0 nor 1 and a length the stream cannot hold; the index
// checks of a whole state are state.cpp's. Internal: not installed.
#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "dda/cdem/model_state.hpp"
#include "dda/state_bytes.hpp"

namespace dda::cdem::state_io {

// The parts' overloads, declared before the list templates that call them.
void put(ByteWriter& w, const BlockState& b);
void put(ByteWriter& w, const Element& e);
void put(ByteWriter& w, const Lattice& l);
void put(ByteWriter& w, const MeshEdge& e);
void put(ByteWriter& w, const BoundaryEdge& e);
void put(ByteWriter& w, const Clone& c);
void put(ByteWriter& w, const SubElement& e);
void put(ByteWriter& w, const SubModel& s);
void put(ByteWriter& w, const SubModelRequest& q);
void put(ByteWriter& w, const SubModelRecord& r);
void put(ByteWriter& w, const PenaltyContact& p);
void put(ByteWriter& w, const Snapshot::Tri& t);
void put(ByteWriter& w, const Snapshot& s);
void put(ByteWriter& w, const TouchRecord& t);
void put(ByteWriter& w, const SeparationRecord& s);
void get(ByteReader& r, BlockState& b);
void get(ByteReader& r, Element& e);
void get(ByteReader& r, Lattice& l);
void get(ByteReader& r, MeshEdge& e);
void get(ByteReader& r, BoundaryEdge& e);
void get(ByteReader& r, Clone& c);
void get(ByteReader& r, SubElement& e);
void get(ByteReader& r, SubModel& s);
void get(ByteReader& r, SubModelRequest& q);
void get(ByteReader& r, SubModelRecord& x);
void get(ByteReader& r, PenaltyContact& p);
void get(ByteReader& r, Snapshot::Tri& t);
void get(ByteReader& r, Snapshot& s);
void get(ByteReader& r, TouchRecord& t);
void get(ByteReader& r, SeparationRecord& s);

// --- scalars, lists and enums (writing) ------------------------------------

inline void put(ByteWriter& w, double x) { w.f64(x); }
inline void put(ByteWriter& w, int x) { w.i32(x); }
inline void put(ByteWriter& w, std::int64_t x) { w.i64(x); }
inline void put(ByteWriter& w, bool x) { w.boolean(x); }
inline void put(ByteWriter& w, Vec2 v) { w.vec2(v); }
inline void put(ByteWriter& w, const Vec3& v) {
  for (int k = 0; k < 3; ++k) w.f64(v[k]);
}
inline void put(ByteWriter& w, const Mat3& m) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) w.f64(m(i, j));
}
template <class T, std::size_t N>
void put(ByteWriter& w, const std::array<T, N>& a) {
  for (const T& x : a) put(w, x);
}
template <class T>
void put(ByteWriter& w, const std::vector<T>& v) {
  w.u64(v.size());
  for (const T& x : v) put(w, x);
}
// std::vector<char> (SubModel::prescribed) and enums: as bytes.
inline void put_bytes(ByteWriter& w, const std::vector<char>& v) {
  w.u64(v.size());
  for (char c : v) w.u8(static_cast<std::uint8_t>(c));
}
template <class E>
void put_enum(ByteWriter& w, E e) {
  w.u8(static_cast<std::uint8_t>(e));
}

// --- scalars, lists and enums (reading) ------------------------------------

inline void get(ByteReader& r, double& x) { x = r.f64(); }
inline void get(ByteReader& r, int& x) { x = r.i32(); }
inline void get(ByteReader& r, std::int64_t& x) { x = r.i64(); }
inline void get(ByteReader& r, bool& x) { x = r.boolean(); }
inline void get(ByteReader& r, Vec2& v) { v = r.vec2(); }
inline void get(ByteReader& r, Vec3& v) {
  for (int k = 0; k < 3; ++k) v[k] = r.f64();
}
template <class T, std::size_t N>
void get(ByteReader& r, std::array<T, N>& a) {
  for (T& x : a) get(r, x);
}
// Each element takes at least one byte: a corrupt length is refused before
// it allocates (ByteReader::count).
template <class T>
void get(ByteReader& r, std::vector<T>& v) {
  const std::size_t n = r.count(1);
  v.clear();
  v.resize(n);
  for (T& x : v) get(r, x);
}
inline void get_bytes(ByteReader& r, std::vector<char>& v) {
  const std::size_t n = r.count(1);
  v.resize(n);
  for (char& c : v) {
    const std::uint8_t b = r.u8();
    if (b > 1) r.fail("a sub-node's prescribed flag is neither 0 nor 1");
    c = static_cast<char>(b);
  }
}
template <class E>
E get_enum(ByteReader& r, std::uint8_t last, const char* what) {
  const std::uint8_t b = r.u8();
  if (b > last) r.fail(std::string(what) + " " + std::to_string(b) + " is not one of 0.." + std::to_string(last));
  return static_cast<E>(b);
}

// --- several parts in turn --------------------------------------------------

// put(w, a), put(w, b), ... in the order given (one record's fields).
template <class... T>
void put_all(ByteWriter& w, const T&... parts) {
  (put(w, parts), ...);
}
// get(r, a), get(r, b), ... in the order given.
template <class... T>
void get_all(ByteReader& r, T&... parts) {
  (get(r, parts), ...);
}

}  // namespace dda::cdem::state_io
