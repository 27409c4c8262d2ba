// Plain byte streams for saving and restoring a model's state (the
// checkpoints of lib/io): fixed-width little-endian integers and IEEE-754
// doubles by their bits, so that a state read back holds exactly the bits
// that were saved, on any host. No I/O: the bytes go where the caller puts
// them. A reader never reads past its end: a short or inconsistent stream
// throws StateError naming what was being read.
#pragma once
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "dda/vec2.hpp"

namespace dda {

// A saved state that cannot be restored: truncated, inconsistent, or of
// another scene (what() says which and where).
struct StateError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class ByteWriter {
 public:
  void u8(std::uint8_t x) { buf_.push_back(static_cast<char>(x)); }
  void boolean(bool x) { u8(x ? 1 : 0); }
  void u32(std::uint32_t x) {
    for (int k = 0; k < 4; ++k) u8(static_cast<std::uint8_t>(x >> (8 * k)));
  }
  void u64(std::uint64_t x) {
    for (int k = 0; k < 8; ++k) u8(static_cast<std::uint8_t>(x >> (8 * k)));
  }
  void i32(std::int32_t x) { u32(static_cast<std::uint32_t>(x)); }
  void i64(std::int64_t x) { u64(static_cast<std::uint64_t>(x)); }
  void f64(double x) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    u64(bits);
  }
  void vec2(Vec2 v) {
    f64(v.x);
    f64(v.y);
  }
  void text(const std::string& s) {
    u64(s.size());
    buf_.append(s);
  }
  // A list: its length, then each element written by `each(*this, element)`.
  template <class T, class F>
  void list(const std::vector<T>& v, F each) {
    u64(v.size());
    for (const T& x : v) each(*this, x);
  }

  const std::string& bytes() const { return buf_; }
  std::string take() { return std::move(buf_); }

 private:
  std::string buf_;
};

class ByteReader {
 public:
  // Reads [data, data + size); `what` names the stream in messages.
  ByteReader(const char* data, std::size_t size, std::string what) : p_(data), end_(data + size), what_(std::move(what)) {}

  std::uint8_t u8() {
    need(1, "a byte");
    return static_cast<std::uint8_t>(*p_++);
  }
  bool boolean() {
    const std::uint8_t b = u8();
    if (b > 1) fail("a flag is neither 0 nor 1");
    return b == 1;
  }
  std::uint32_t u32() {
    need(4, "a 32-bit integer");
    std::uint32_t x = 0;
    for (int k = 0; k < 4; ++k) x |= static_cast<std::uint32_t>(static_cast<unsigned char>(*p_++)) << (8 * k);
    return x;
  }
  std::uint64_t u64() {
    need(8, "a 64-bit integer");
    std::uint64_t x = 0;
    for (int k = 0; k < 8; ++k) x |= static_cast<std::uint64_t>(static_cast<unsigned char>(*p_++)) << (8 * k);
    return x;
  }
  std::int32_t i32() { return static_cast<std::int32_t>(u32()); }
  std::int64_t i64() { return static_cast<std::int64_t>(u64()); }
  double f64() {
    const std::uint64_t bits = u64();
    double x = 0.0;
    std::memcpy(&x, &bits, sizeof x);
    return x;
  }
  Vec2 vec2() {
    const double x = f64();
    return {x, f64()};
  }
  std::string text() {
    const std::size_t n = count(1);
    std::string s(p_, n);
    p_ += n;
    return s;
  }
  // A list's length, refused when the rest of the stream cannot hold that
  // many elements of at least `min_bytes` each (a corrupt length would
  // otherwise allocate without bound).
  std::size_t count(std::size_t min_bytes) {
    const std::uint64_t n = u64();
    if (min_bytes > 0 && n > remaining() / min_bytes) fail("a list of " + std::to_string(n) + " elements runs past the end");
    return static_cast<std::size_t>(n);
  }
  // Reads a list written by ByteWriter::list: `each(*this)` returns an element.
  template <class T, class F>
  void list(std::vector<T>& v, std::size_t min_bytes, F each) {
    const std::size_t n = count(min_bytes);
    v.clear();
    v.reserve(n);
    for (std::size_t k = 0; k < n; ++k) v.push_back(each(*this));
  }

  std::size_t remaining() const { return static_cast<std::size_t>(end_ - p_); }
  // Throws unless every byte was read.
  void expect_end() const {
    if (p_ != end_) fail(std::to_string(remaining()) + " bytes left over after the state");
  }
  [[noreturn]] void fail(const std::string& why) const { throw StateError(what_ + ": " + why); }

 private:
  void need(std::size_t n, const char* what) const {
    if (remaining() < n) fail(std::string("truncated: ends where ") + what + " should be");
  }
  const char* p_;
  const char* end_;
  std::string what_;
};

}  // namespace dda
