#include "dda/io/scene_file.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "dda/io/csv.hpp"
#include "dda/joint_sets.hpp"
#include "dda/simulation.hpp"

namespace dda::io {

namespace {

using nlohmann::json;

constexpr double kPi = 3.14159265358979323846;

// ---------------------------------------------------------------------------
// Messages

std::string join_path(const std::string& parent, const std::string& key) {
  return parent.empty() ? key : parent + "." + key;
}

std::string index_path(const std::string& parent, std::size_t i) { return parent + "[" + std::to_string(i) + "]"; }

std::string single_quoted(const std::string& s) { return "'" + s + "'"; }

// "string \"abc\"", "number 2.5", "array", ... for "expected X, got Y".
std::string describe_value(const json& v) {
  std::string s = v.type_name();
  if (v.is_string() || v.is_number() || v.is_boolean()) {
    std::string d = v.dump();
    if (d.size() > 40) d = d.substr(0, 37) + "...";
    s += " " + d;
  }
  return s;
}

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0u : 1u)});
      diag = up;
    }
  }
  return row[b.size()];
}

// ---------------------------------------------------------------------------
// Reading with field paths

// "file:line:col" of `path` in the file (re-reading it), or "file" if the
// path is not in the file (defined below).
std::string locate(const std::string& file, const std::string* text, const std::string& path);

class Reader {
 public:
  explicit Reader(std::string file, const std::string* text = nullptr) : file_(std::move(file)), text_(text) {}

  // "<file>:<line>:<col>: <path>: <why>", the position that of `path` in the
  // file (found by reading it again, only on this error path).
  [[noreturn]] void fail(const std::string& path, const std::string& why) const {
    throw SceneFileError(where(path) + ": " + (path.empty() ? std::string() : path + ": ") + why);
  }

  std::string where(const std::string& path) const { return locate(file_, text_, path); }

  // Checks v is an object whose keys are all in `allowed`.
  void object(const json& v, const std::string& path, std::initializer_list<const char*> allowed) const {
    if (!v.is_object()) fail(path, "expected an object, got " + describe_value(v));
    for (auto it = v.begin(); it != v.end(); ++it) {
      const std::string& k = it.key();
      bool ok = false;
      for (const char* a : allowed) ok = ok || k == a;
      if (ok) continue;
      std::string best;
      std::size_t best_d = std::numeric_limits<std::size_t>::max();
      for (const char* a : allowed) {
        const std::size_t d = edit_distance(k, a);
        if (d < best_d) best_d = d, best = a;
      }
      std::string why = "unknown key";
      if (best_d <= std::max<std::size_t>(1, std::min(k.size(), best.size()) / 3)) {
        why += " (did you mean " + single_quoted(best) + "?)";
      } else {
        why += "; allowed here:";
        for (const char* a : allowed) why += std::string(" ") + a;
      }
      fail(join_path(path, k), why);
    }
  }

  static const json* find(const json& obj, const char* key) {
    const auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }

  const json& need(const json& obj, const std::string& path, const char* key) const {
    const json* v = find(obj, key);
    if (!v) fail(join_path(path, key), "missing required key");
    return *v;
  }

  double number(const json& v, const std::string& path) const {
    if (!v.is_number()) fail(path, "expected a number, got " + describe_value(v));
    return v.get<double>();
  }

  int integer(const json& v, const std::string& path) const {
    constexpr long long kMax = std::numeric_limits<int>::max(), kMin = std::numeric_limits<int>::min();
    if (v.is_number_unsigned()) {
      if (v.get<unsigned long long>() > static_cast<unsigned long long>(kMax)) fail(path, "integer out of range");
      return static_cast<int>(v.get<unsigned long long>());
    }
    if (v.is_number_integer()) {
      const long long x = v.get<long long>();
      if (x < kMin || x > kMax) fail(path, "integer out of range");
      return static_cast<int>(x);
    }
    if (v.is_number_float()) {
      const double x = v.get<double>();
      if (x == std::floor(x) && std::fabs(x) <= static_cast<double>(kMax)) return static_cast<int>(x);
    }
    fail(path, "expected an integer, got " + describe_value(v));
  }

  bool boolean(const json& v, const std::string& path) const {
    if (!v.is_boolean()) fail(path, "expected true or false, got " + describe_value(v));
    return v.get<bool>();
  }

  std::string string(const json& v, const std::string& path) const {
    if (!v.is_string()) fail(path, "expected a string, got " + describe_value(v));
    return v.get<std::string>();
  }

  const json& array(const json& v, const std::string& path, const char* what) const {
    if (!v.is_array()) fail(path, std::string("expected an array") + what + ", got " + describe_value(v));
    return v;
  }

  Vec2 vec2(const json& v, const std::string& path) const {
    if (!v.is_array() || v.size() != 2) fail(path, "expected [x, y] (an array of 2 numbers), got " + describe_value(v) +
                                                       (v.is_array() ? " of " + std::to_string(v.size()) : ""));
    return {number(v[0], index_path(path, 0)), number(v[1], index_path(path, 1))};
  }

  template <typename E>
  E choice(const json& v, const std::string& path, std::initializer_list<std::pair<const char*, E>> options) const {
    const std::string s = string(v, path);
    std::string list;
    for (const auto& [name, value] : options) {
      if (s == name) return value;
      list += std::string(list.empty() ? "" : ", ") + "\"" + name + "\"";
    }
    fail(path, "unknown value \"" + s + "\"; expected one of " + list);
  }

  std::int64_t int64(const json& v, const std::string& path) const {
    if (v.is_number_unsigned()) {
      if (v.get<unsigned long long>() > static_cast<unsigned long long>(std::numeric_limits<std::int64_t>::max()))
        fail(path, "integer out of range");
      return static_cast<std::int64_t>(v.get<unsigned long long>());
    }
    if (v.is_number_integer()) return v.get<std::int64_t>();
    if (v.is_number_float()) {
      const double x = v.get<double>();
      // 2^63 is exact in a double; the range is [-2^63, 2^63).
      constexpr double kTwo63 = 9223372036854775808.0;
      if (x == std::floor(x) && x >= -kTwo63 && x < kTwo63) return static_cast<std::int64_t>(x);
    }
    fail(path, "expected an integer, got " + describe_value(v));
  }

  const std::string& file() const { return file_; }

 private:
  std::string file_;
  const std::string* text_;
};

// ---------------------------------------------------------------------------
// Parsing: JSON syntax, duplicate keys, and where an overflowing number was.

// Where the lexer is: an iterator over the text that records how far it was
// read, so that an event of the parser callback knows its byte position.
class CountingIterator {
 public:
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;
  CountingIterator(const char* p, const char** reached) : p_(p), reached_(reached) {}
  reference operator*() const { return *p_; }
  CountingIterator& operator++() {
    *reached_ = ++p_;
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator old = *this;
    ++*this;
    return old;
  }
  bool operator==(const CountingIterator& o) const { return p_ == o.p_; }
  bool operator!=(const CountingIterator& o) const { return p_ != o.p_; }

 private:
  const char* p_;
  const char** reached_;
};

// 1-based line and column of the 0-based byte offset `pos` in `text`.
std::pair<std::size_t, std::size_t> line_column0(const std::string& text, std::size_t pos) {
  pos = std::min(pos, text.size());
  std::size_t line = 1, line_start = 0;
  for (std::size_t i = 0; i < pos; ++i)
    if (text[i] == '\n') ++line, line_start = i + 1;
  return {line, pos - line_start + 1};
}

std::string file_line_column(const std::string& file, const std::string& text, std::size_t pos) {
  const auto [line, col] = line_column0(text, pos);
  return file + ":" + std::to_string(line) + ":" + std::to_string(col);
}

// The most elements an array at `key` may have (kMaxArrayLength unless the
// schema gives the key a tighter limit).
std::size_t array_limit(const std::string& key) {
  if (key == "blocks") return kMaxBlocks;
  if (key == "vertices" || key == "region") return kMaxPolygonVertices;
  return kMaxArrayLength;
}

// Follows the parser's events: the field path of the element being read,
// duplicate keys, and the limits on nesting depth and array/object sizes,
// all checked as the text is read (before a too-big document is built).
// With a target path it instead stops (throws Found) where that path starts.
class PathTracker {
 public:
  struct Found {
    std::size_t offset;
  };
  // `reached`: how far the lexer has read (CountingIterator).
  PathTracker(const std::string& text, const char* const* reached, const std::string& file,
              const std::string* target = nullptr)
      : text_(text), reached_(reached), file_(file), target_(target) {}

  // The path of the element being parsed now (the last key of the innermost
  // object, or the next index of the innermost array).
  std::string current() const {
    if (stack_.empty()) return "";
    const Frame& f = stack_.back();
    return f.array ? index_path(f.path, f.index) : join_path(f.path, f.key);
  }

  // Byte offset of the last character the lexer read (0-based).
  std::size_t offset() const {
    const std::size_t n = static_cast<std::size_t>(*reached_ - text_.data());
    return n > 0 ? n - 1 : 0;
  }

  void event(json::parse_event_t ev, const json& parsed) {
    switch (ev) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start: {
        if (!stack_.empty()) element_started();
        if (stack_.size() >= kMaxNestingDepth)
          fail(current(), "nested deeper than " + std::to_string(kMaxNestingDepth) +
                              " objects/arrays (the reader's limit; a scene needs at most 5)");
        Frame f;
        f.array = ev == json::parse_event_t::array_start;
        f.path = current();
        f.limit = f.array ? array_limit(stack_.empty() ? std::string() : stack_.back().key) : kMaxArrayLength;
        stack_.push_back(std::move(f));
        break;
      }
      case json::parse_event_t::key: {
        Frame& f = stack_.back();
        f.key = parsed.get<std::string>();
        if (target_ && current() == *target_) throw Found{offset()};
        if (!target_) {
          if (!f.keys.insert(f.key).second) fail(current(), "duplicate key");
          if (f.keys.size() > f.limit)
            fail(f.path, "more than " + std::to_string(f.limit) + " keys (the reader's limit)");
        }
        break;
      }
      case json::parse_event_t::value:
        if (!stack_.empty() && stack_.back().array) {
          element_started();
          ++stack_.back().index;
        }
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        stack_.pop_back();
        if (!stack_.empty() && stack_.back().array) ++stack_.back().index;
        break;
    }
  }

 private:
  struct Frame {
    bool array = false;
    std::string path;
    std::size_t index = 0;
    std::size_t limit = kMaxArrayLength;
    std::string key;
    std::set<std::string> keys;
  };

  // A new element of the innermost array starts (or ended, for a scalar).
  void element_started() {
    const Frame& f = stack_.back();
    if (!f.array) return;
    if (target_ && current() == *target_) throw Found{offset()};
    if (!target_ && f.index >= f.limit)
      fail(f.path, "more than " + std::to_string(f.limit) + " elements (the reader's limit" +
                       (f.limit == kMaxPolygonVertices ? " on vertices per polygon" :
                        f.limit == kMaxBlocks && f.limit != kMaxArrayLength ? " on blocks" : "") + ")");
  }

  [[noreturn]] void fail(const std::string& path, const std::string& why) const {
    throw SceneFileError(file_line_column(file_, text_, offset()) + ": " + (path.empty() ? "" : path + ": ") + why);
  }

  const std::string& text_;
  const char* const* reached_;
  const std::string& file_;
  const std::string* target_;
  std::vector<Frame> stack_;
};

// The parser's events as SAX calls: each goes to the tracker (path, limits)
// first, then, when reading, to nlohmann's DOM builder. (Not json::parse
// with a callback: its DOM builder searches the enclosing array for a
// discarded value after every object, quadratic in the array's length.)
class TrackingSax {
 public:
  using Dom = nlohmann::detail::json_sax_dom_parser<json>;
  TrackingSax(PathTracker& tracker, Dom* dom) : t_(tracker), dom_(dom) {}
  bool null() { return value() && (!dom_ || dom_->null()); }
  bool boolean(bool v) { return value() && (!dom_ || dom_->boolean(v)); }
  bool number_integer(json::number_integer_t v) { return value() && (!dom_ || dom_->number_integer(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return value() && (!dom_ || dom_->number_unsigned(v)); }
  bool number_float(json::number_float_t v, const std::string& s) {
    return value() && (!dom_ || dom_->number_float(v, s));
  }
  bool string(std::string& v) { return value() && (!dom_ || dom_->string(v)); }
  bool binary(json::binary_t& v) { return value() && (!dom_ || dom_->binary(v)); }
  bool start_object(std::size_t n) {
    return on(json::parse_event_t::object_start) && (!dom_ || dom_->start_object(n));
  }
  bool end_object() { return on(json::parse_event_t::object_end) && (!dom_ || dom_->end_object()); }
  bool start_array(std::size_t n) { return on(json::parse_event_t::array_start) && (!dom_ || dom_->start_array(n)); }
  bool end_array() { return on(json::parse_event_t::array_end) && (!dom_ || dom_->end_array()); }
  bool key(std::string& k) {
    t_.event(json::parse_event_t::key, json(k));
    return !dom_ || dom_->key(k);
  }
  // With a DOM builder: throws the parse error (json::parse_error, or
  // json::out_of_range for a number beyond the double range).
  // (A template: the builder throws the exception's own type.)
  template <typename Exception>
  bool parse_error(std::size_t pos, const std::string& token, const Exception& ex) {
    return dom_ ? dom_->parse_error(pos, token, ex) : false;
  }

 private:
  bool value() { return on(json::parse_event_t::value); }
  bool on(json::parse_event_t ev) {
    t_.event(ev, none_);
    return true;
  }
  PathTracker& t_;
  Dom* dom_;
  const json none_;
};

json parse_json(const std::string& text, const Reader& reader) {
  // The lexer takes a NUL byte for the end of the input, and would accept
  // whatever follows it: a JSON text has no raw NUL (not even in a string).
  if (const void* nul = std::memchr(text.data(), '\0', text.size()))
    throw SceneFileError(
        file_line_column(reader.file(), text, static_cast<std::size_t>(static_cast<const char*>(nul) - text.data())) +
        ": a NUL byte (a JSON text has none: a binary or padded file?)");
  const char* reached = text.data();
  PathTracker tracker(text, &reached, reader.file());
  const CountingIterator first(text.data(), &reached), last(text.data() + text.size(), &reached);
  try {
    json root;
    TrackingSax::Dom dom(root, /*allow_exceptions=*/true);
    TrackingSax sax(tracker, &dom);
    json::sax_parse(first, last, &sax);
    return root;
  } catch (const json::parse_error& e) {
    // e.what(): "[json.exception.parse_error.101] parse error at line 3, column 8: syntax error while ..."
    std::string detail = e.what();
    const std::size_t colon = detail.find(": ");
    if (colon != std::string::npos) detail = detail.substr(colon + 2);
    if (detail.rfind("syntax error", 0) == 0) detail = "JSON " + detail;
    const std::string where = tracker.current();
    throw SceneFileError(file_line_column(reader.file(), text, e.byte > 0 ? e.byte - 1 : 0) + ": " +
                         (where.empty() ? "" : "near " + where + ": ") + detail);
  } catch (const json::out_of_range& e) {
    // A number beyond the double range ("1e400"): JSON has no infinity/NaN.
    std::string detail = e.what();
    const std::size_t b = detail.find("] ");
    if (b != std::string::npos) detail = detail.substr(b + 2);
    throw SceneFileError(file_line_column(reader.file(), text, tracker.offset()) + ": " + tracker.current() + ": " +
                         detail + " (not representable as a finite double)");
  }
}

std::string locate(const std::string& file, const std::string* text, const std::string& path) {
  if (!text || path.empty()) return file;
  const char* reached = text->data();
  PathTracker tracker(*text, &reached, file, &path);
  TrackingSax sax(tracker, nullptr);
  const CountingIterator first(text->data(), &reached), last(text->data() + text->size(), &reached);
  try {
    json::sax_parse(first, last, &sax);
  } catch (const PathTracker::Found& found) {
    return file_line_column(file, *text, found.offset);
  } catch (const std::exception&) {
  }
  return file;
}

// ---------------------------------------------------------------------------
// Sections

struct Names {
  std::vector<std::string> materials;  // optional material names
};

// Finite coordinates whose products are not: |x|, |y| beyond ~1e154 make a
// polygon's area or an edge's squared length overflow a double, which the
// kernel would misreport (as a duplicate vertex, say). Refused with the
// reason. Also catches a vertex that became infinite (x0 + w, a rotation).
void check_magnitude(const Reader& r, const std::vector<Vec2>& pts, const std::string& path) {
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (!is_finite(pts[i]))
      r.fail(path, "vertex " + std::to_string(i) + ": coordinate overflows (beyond the double range)");
  double twice_area = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Vec2 p = pts[i], q = pts[(i + 1) % pts.size()];
    const Vec2 d = q - p;
    if (!std::isfinite(d.x * d.x + d.y * d.y))
      r.fail(path, "coordinates too large: an edge's squared length overflows a double (keep |x|, |y| below 1e150 m)");
    twice_area += p.x * q.y - q.x * p.y;
  }
  if (!std::isfinite(twice_area))
    r.fail(path, "coordinates too large: the polygon's area overflows a double (keep |x|, |y| below 1e150 m)");
}

std::vector<Vec2> rect_vertices(const Reader& r, const json& v, const std::string& path) {
  if (!v.is_array() || v.size() != 4)
    r.fail(path, "expected [x0, y0, width, height] (an array of 4 numbers), got " + describe_value(v));
  double a[4];
  for (std::size_t i = 0; i < 4; ++i) a[i] = r.number(v[i], index_path(path, i));
  if (!(a[2] > 0.0 && a[3] > 0.0)) r.fail(path, "width and height must be positive");
  return {{a[0], a[1]}, {a[0] + a[2], a[1]}, {a[0] + a[2], a[1] + a[3]}, {a[0], a[1] + a[3]}};
}

Material read_material(const Reader& r, const json& v, const std::string& path, std::string& name) {
  r.object(v, path, {"name", "density", "young", "poisson"});
  Material m;
  if (const json* n = Reader::find(v, "name")) name = r.string(*n, join_path(path, "name"));
  m.density = r.number(r.need(v, path, "density"), join_path(path, "density"));
  m.young = r.number(r.need(v, path, "young"), join_path(path, "young"));
  m.poisson = r.number(r.need(v, path, "poisson"), join_path(path, "poisson"));
  return m;
}

// A material given by index or by name.
int material_ref(const Reader& r, const json& x, const std::string& mp, const Names& names) {
  if (x.is_string()) {
    const std::string name = x.get<std::string>();
    const auto it = std::find(names.materials.begin(), names.materials.end(), name);
    if (it == names.materials.end()) r.fail(mp, "no material named \"" + name + "\"");
    if (std::find(it + 1, names.materials.end(), name) != names.materials.end())
      r.fail(mp, "material name \"" + name + "\" is ambiguous (several materials have it)");
    return static_cast<int>(it - names.materials.begin());
  }
  if (x.is_number()) return r.integer(x, mp);
  r.fail(mp, "expected a material index or name, got " + describe_value(x));
}

BlockSpec read_block(const Reader& r, const json& v, const std::string& path, const Names& names) {
  r.object(v, path,
           {"name", "vertices", "rect", "rotate_deg", "about", "velocity", "spin", "fixed", "material", "group"});
  BlockSpec b;
  const json* verts = Reader::find(v, "vertices");
  const json* rect = Reader::find(v, "rect");
  if (verts && rect) r.fail(path, "give either 'vertices' or 'rect', not both");
  if (!verts && !rect) r.fail(join_path(path, "vertices"), "missing required key (or give 'rect')");
  if (verts) {
    const std::string vp = join_path(path, "vertices");
    r.array(*verts, vp, " of [x, y] points");
    for (std::size_t i = 0; i < verts->size(); ++i) b.vertices.push_back(r.vec2((*verts)[i], index_path(vp, i)));
  } else {
    b.vertices = rect_vertices(r, *rect, join_path(path, "rect"));
  }
  check_magnitude(r, b.vertices, join_path(path, verts ? "vertices" : "rect"));
  const json* rot = Reader::find(v, "rotate_deg");
  const json* about = Reader::find(v, "about");
  if (about && !rot) r.fail(join_path(path, "about"), "only used with 'rotate_deg'");
  if (rot) {
    const double deg = r.number(*rot, join_path(path, "rotate_deg"));
    Vec2 pivot{};
    if (about) {
      pivot = r.vec2(*about, join_path(path, "about"));
    } else if (!b.vertices.empty()) {
      for (const Vec2& p : b.vertices) pivot += p;
      pivot = pivot / static_cast<double>(b.vertices.size());
    }
    const double a = deg * kPi / 180.0;
    for (Vec2& p : b.vertices) p = pivot + rotate(p - pivot, a);
    check_magnitude(r, b.vertices, join_path(path, "rotate_deg"));
  }
  if (const json* x = Reader::find(v, "name")) b.name = r.string(*x, join_path(path, "name"));
  if (const json* x = Reader::find(v, "velocity")) b.velocity = r.vec2(*x, join_path(path, "velocity"));
  if (const json* x = Reader::find(v, "spin")) b.spin = r.number(*x, join_path(path, "spin"));
  if (const json* x = Reader::find(v, "fixed")) b.fixed = r.boolean(*x, join_path(path, "fixed"));
  if (const json* x = Reader::find(v, "group")) b.group = r.integer(*x, join_path(path, "group"));
  if (const json* x = Reader::find(v, "material")) b.material = material_ref(r, *x, join_path(path, "material"), names);
  if (b.fixed && (b.velocity != Vec2{} || b.spin != 0.0))
    r.fail(join_path(path, Reader::find(v, "velocity") ? "velocity" : "spin"),
           "a fixed block never moves: give it no velocity or spin");
  return b;
}

BoundarySegment read_boundary(const Reader& r, const json& v, const std::string& path) {
  r.object(v, path, {"a", "b", "depth", "group"});
  BoundarySegment s;
  s.a = r.vec2(r.need(v, path, "a"), join_path(path, "a"));
  s.b = r.vec2(r.need(v, path, "b"), join_path(path, "b"));
  if (!std::isfinite((s.b.x - s.a.x) * (s.b.x - s.a.x) + (s.b.y - s.a.y) * (s.b.y - s.a.y)))
    r.fail(path, "coordinates too large: the segment's squared length overflows a double (keep |x|, |y| below 1e150 m)");
  if (const json* x = Reader::find(v, "depth")) s.depth = r.number(*x, join_path(path, "depth"));
  if (const json* x = Reader::find(v, "group")) s.group = r.integer(*x, join_path(path, "group"));
  return s;
}

// A "generated" entry: a region cut into convex blocks by joint sets
// (dda::generate_blocks); appends the blocks to `blocks`.
GeneratedRegion read_generated(const Reader& r, const json& v, const std::string& path, const Names& names,
                               std::vector<BlockSpec>& blocks) {
  r.object(v, path, {"name", "region", "joint_sets", "min_area", "material", "group"});
  const std::string rp = join_path(path, "region");
  const json& reg = r.array(r.need(v, path, "region"), rp, " of [x, y] points");
  std::vector<Vec2> region;
  for (std::size_t i = 0; i < reg.size(); ++i) region.push_back(r.vec2(reg[i], index_path(rp, i)));
  check_magnitude(r, region, rp);
  const std::string jp = join_path(path, "joint_sets");
  const json& js = r.array(r.need(v, path, "joint_sets"), jp, " of {\"dip_deg\", \"spacing\", \"origin\"}");
  std::vector<JointSet> sets;
  for (std::size_t i = 0; i < js.size(); ++i) {
    const std::string ep = index_path(jp, i);
    r.object(js[i], ep, {"dip_deg", "spacing", "origin"});
    JointSet j;
    j.dip_deg = r.number(r.need(js[i], ep, "dip_deg"), join_path(ep, "dip_deg"));
    j.spacing = r.number(r.need(js[i], ep, "spacing"), join_path(ep, "spacing"));
    if (const json* x = Reader::find(js[i], "origin")) j.origin = r.vec2(*x, join_path(ep, "origin"));
    sets.push_back(j);
  }
  // The generator cuts the region with every line of every set: refuse a
  // spacing that would make more than kMaxBlocks pieces before it runs (a
  // tiny spacing would otherwise take forever). Parallel families of n_k
  // lines cut a convex part into at most prod (n_k + 1) pieces.
  double pieces = std::max<double>(1.0, static_cast<double>(region.size()));  // convex parts <= vertices
  for (std::size_t k = 0; k < sets.size(); ++k) {
    const JointSet& j = sets[k];
    if (!(j.spacing > 0.0) || !(j.dip_deg > 0.0 && j.dip_deg < 180.0)) continue;  // the generator says why
    const double a = j.dip_deg * kPi / 180.0;
    const Vec2 nrm{std::sin(a), std::cos(a)};
    double lo = std::numeric_limits<double>::max(), hi = -lo;
    for (const Vec2& p : region) {
      const double d = dot(nrm, p - j.origin);
      lo = std::min(lo, d);
      hi = std::max(hi, d);
    }
    // The generator counts lines k = lo / spacing ... hi / spacing in a
    // double: beyond 2^52, k + 1 == k and it would never finish (fuzzer
    // finding: an origin at 9.2e18 m).
    constexpr double kMaxLineIndex = 4503599627370496.0;  // 2^52
    if (!(std::max(std::fabs(lo), std::fabs(hi)) / j.spacing < kMaxLineIndex))
      r.fail(join_path(index_path(jp, k), "origin"),
             "too far from the region for the spacing (the region lies more than 2^52 spacings from the origin)");
    const double lines = (hi - lo) / j.spacing + 1.0;
    pieces *= lines + 1.0;
    if (!(pieces <= static_cast<double>(kMaxBlocks)))
      r.fail(join_path(index_path(jp, k), "spacing"),
             "the joint sets would cut the region into up to " + format_number(pieces) + " blocks, more than " +
                 std::to_string(kMaxBlocks) + " (the reader's limit on blocks)");
  }
  double min_area = 0.0;
  if (const json* x = Reader::find(v, "min_area")) {
    min_area = r.number(*x, join_path(path, "min_area"));
    if (!(min_area >= 0.0)) r.fail(join_path(path, "min_area"), "must be >= 0 (m^2)");
  }
  BlockSpec proto;
  if (const json* x = Reader::find(v, "material")) proto.material = material_ref(r, *x, join_path(path, "material"), names);
  if (const json* x = Reader::find(v, "group")) proto.group = r.integer(*x, join_path(path, "group"));
  std::string name;
  if (const json* x = Reader::find(v, "name")) name = r.string(*x, join_path(path, "name"));
  GeneratedBlocks g;
  try {
    g = generate_blocks(region, sets, min_area);
  } catch (const std::invalid_argument& e) {
    // The generator names "region..." or "joint_sets[k]..." first.
    const std::string m = e.what();
    if (m.rfind("region", 0) == 0 || m.rfind("joint_sets", 0) == 0) r.fail("", path + "." + m);
    r.fail(path, m);
  }
  GeneratedRegion out;
  out.first_block = static_cast<int>(blocks.size());
  out.count = static_cast<int>(g.blocks.size());
  out.dropped = g.dropped;
  out.dropped_area = g.dropped_area;
  for (std::size_t k = 0; k < g.blocks.size(); ++k) {
    BlockSpec b = proto;
    b.vertices.assign(g.blocks[k].v.begin(), g.blocks[k].v.begin() + g.blocks[k].count);
    if (!name.empty()) b.name = name + "_" + std::to_string(k);
    blocks.push_back(std::move(b));
  }
  return out;
}

ContactParams read_contact(const Reader& r, const json& v, const std::string& path) {
  r.object(v, path,
           {"kn", "kt", "friction_deg", "friction_rules", "h_rule", "h", "integration", "small_edge_fraction",
            "small_edge_rays", "friction_update"});
  ContactParams c;
  c.kn = r.number(r.need(v, path, "kn"), join_path(path, "kn"));
  if (const json* x = Reader::find(v, "kt")) c.kt = r.number(*x, join_path(path, "kt"));
  if (const json* x = Reader::find(v, "friction_deg")) c.friction_deg = r.number(*x, join_path(path, "friction_deg"));
  if (const json* x = Reader::find(v, "friction_rules")) {
    const std::string rp = join_path(path, "friction_rules");
    r.array(*x, rp, " of {\"groups\": [a, b], \"friction_deg\": phi}");
    for (std::size_t i = 0; i < x->size(); ++i) {
      const json& e = (*x)[i];
      const std::string ep = index_path(rp, i);
      r.object(e, ep, {"groups", "friction_deg"});
      const json& g = r.need(e, ep, "groups");
      const std::string gp = join_path(ep, "groups");
      if (!g.is_array() || g.size() != 2) r.fail(gp, "expected [a, b] (two group numbers), got " + describe_value(g));
      FrictionRule rule;
      rule.group_a = r.integer(g[0], index_path(gp, 0));
      rule.group_b = r.integer(g[1], index_path(gp, 1));
      rule.friction_deg = r.number(r.need(e, ep, "friction_deg"), join_path(ep, "friction_deg"));
      c.friction_rules.push_back(rule);
    }
  }
  if (const json* x = Reader::find(v, "h_rule"))
    c.h_rule = r.choice<HRule>(*x, join_path(path, "h_rule"),
                               {{"min_max_edge", HRule::kMinMaxEdge},
                                {"mean_edge", HRule::kMeanEdge},
                                {"given", HRule::kGiven},
                                {"inscribed_radius", HRule::kInscribedRadius}});
  if (const json* x = Reader::find(v, "h")) {
    if (c.h_rule != HRule::kGiven) r.fail(join_path(path, "h"), "only used with \"h_rule\": \"given\"");
    c.h = r.number(*x, join_path(path, "h"));
  }
  if (const json* x = Reader::find(v, "integration"))
    c.integration = r.choice<Integration>(
        *x, join_path(path, "integration"),
        {{"paper_bisector", Integration::kPaperBisector}, {"exact_envelope", Integration::kExactEnvelope}});
  if (const json* x = Reader::find(v, "small_edge_fraction"))
    c.small_edge_fraction = r.number(*x, join_path(path, "small_edge_fraction"));
  if (const json* x = Reader::find(v, "small_edge_rays"))
    c.small_edge_rays = r.choice<SmallEdgeRays>(*x, join_path(path, "small_edge_rays"),
                                                {{"virtual_and_vertex", SmallEdgeRays::kVirtualAndVertex},
                                                 {"virtual_replaces_vertex", SmallEdgeRays::kVirtualReplacesVertex}});
  if (const json* x = Reader::find(v, "friction_update"))
    c.friction_update = r.choice<FrictionUpdate>(
        *x, join_path(path, "friction_update"),
        {{"paper", FrictionUpdate::kPaper}, {"return_mapping", FrictionUpdate::kReturnMapping}});
  return c;
}

// The solver's stability guards; every key optional (the kernel checks the
// ranges, with the same field names: guards.max_step_motion, ...).
StabilityGuards read_guards(const Reader& r, const json& v, const std::string& path) {
  r.object(v, path,
           {"max_step_motion", "max_balance_error", "max_energy_growth", "energy_check_every", "max_penetration",
            "max_approach_energy"});
  StabilityGuards g;
  if (const json* x = Reader::find(v, "max_step_motion"))
    g.max_step_motion = r.number(*x, join_path(path, "max_step_motion"));
  if (const json* x = Reader::find(v, "max_balance_error"))
    g.max_balance_error = r.number(*x, join_path(path, "max_balance_error"));
  if (const json* x = Reader::find(v, "max_energy_growth"))
    g.max_energy_growth = r.number(*x, join_path(path, "max_energy_growth"));
  if (const json* x = Reader::find(v, "energy_check_every"))
    g.energy_check_every = r.integer(*x, join_path(path, "energy_check_every"));
  if (const json* x = Reader::find(v, "max_penetration"))
    g.max_penetration = r.number(*x, join_path(path, "max_penetration"));
  if (const json* x = Reader::find(v, "max_approach_energy"))
    g.max_approach_energy = r.number(*x, join_path(path, "max_approach_energy"));
  return g;
}

OutputSpec read_output(const Reader& r, const json* v, const Scene& scene) {
  OutputSpec out;
  const std::string path = "output";
  const std::vector<double> default_snapshots =
      scene.duration > 0.0 ? std::vector<double>{0.0, scene.duration} : std::vector<double>{0.0};
  if (!v) {
    out.snapshot_times = default_snapshots;
    return out;
  }
  r.object(*v, path, {"every", "snapshots", "tracked_blocks", "vtk", "vtk_every", "block_table"});
  if (const json* x = Reader::find(*v, "every")) {
    out.every = r.integer(*x, "output.every");
    if (out.every < 1) r.fail("output.every", "must be >= 1 (steps between time-series rows)");
  }
  if (const json* x = Reader::find(*v, "snapshots")) {
    r.array(*x, "output.snapshots", " of times");
    for (std::size_t i = 0; i < x->size(); ++i) {
      const std::string p = index_path("output.snapshots", i);
      const double t = r.number((*x)[i], p);
      if (!(t >= 0.0 && t <= scene.duration))
        r.fail(p, "snapshot time must lie in [0, duration] = [0, " + format_number(scene.duration) + "] s");
      out.snapshot_times.push_back(t);
    }
    std::sort(out.snapshot_times.begin(), out.snapshot_times.end());
  } else {
    out.snapshot_times = default_snapshots;
  }
  if (const json* x = Reader::find(*v, "tracked_blocks")) {
    r.array(*x, "output.tracked_blocks", " of block indices or names");
    const int n = static_cast<int>(scene.blocks.size());
    for (std::size_t i = 0; i < x->size(); ++i) {
      const json& e = (*x)[i];
      const std::string p = index_path("output.tracked_blocks", i);
      int id = -1;
      if (e.is_string()) {
        const std::string name = e.get<std::string>();
        for (int k = 0; k < n; ++k)
          if (scene.blocks[static_cast<std::size_t>(k)].name == name) {
            if (id >= 0) r.fail(p, "block name \"" + name + "\" is ambiguous (several blocks have it)");
            id = k;
          }
        if (id < 0) r.fail(p, "no block named \"" + name + "\"");
      } else if (e.is_number()) {
        id = r.integer(e, p);
        if (id < 0 || id >= n)
          r.fail(p, "no block " + std::to_string(id) + " (the scene has " + std::to_string(n) + " blocks)");
      } else {
        r.fail(p, "expected a block index or name, got " + describe_value(e));
      }
      if (std::find(out.tracked_blocks.begin(), out.tracked_blocks.end(), id) != out.tracked_blocks.end())
        r.fail(p, "block " + std::to_string(id) + " is listed twice");
      out.tracked_blocks.push_back(id);
    }
  }
  if (const json* x = Reader::find(*v, "vtk")) out.vtk = r.boolean(*x, "output.vtk");
  if (const json* x = Reader::find(*v, "vtk_every")) {
    out.vtk_every = r.integer(*x, "output.vtk_every");
    if (out.vtk_every < 1) r.fail("output.vtk_every", "must be >= 1 (steps between ParaView frames)");
    if (!out.vtk) r.fail("output.vtk_every", "needs \"vtk\": true (it would be ignored)");
  }
  if (const json* x = Reader::find(*v, "block_table")) out.block_table = r.boolean(*x, "output.block_table");
  return out;
}

// " (blocks[7] is block 2 of generated[0])" for a kernel message about a
// generated block, so that the file's author can find it; "" otherwise.
std::string generated_note(const std::string& message, const std::vector<GeneratedRegion>& generated,
                           const std::vector<std::string>& paths) {
  if (generated.empty()) return "";
  std::string note;
  std::size_t pos = 0;
  while ((pos = message.find("blocks[", pos)) != std::string::npos) {
    const std::size_t end = message.find(']', pos);
    if (end == std::string::npos) break;
    int id = -1;
    try {
      id = std::stoi(message.substr(pos + 7, end - pos - 7));
    } catch (const std::exception&) {
      break;
    }
    for (std::size_t g = 0; g < generated.size(); ++g) {
      const GeneratedRegion& gr = generated[g];
      if (id >= gr.first_block && id < gr.first_block + gr.count) {
        const std::string& where = paths[g];
        note += std::string(note.empty() ? " (" : "; ") + "blocks[" + std::to_string(id) + "] is block " +
                std::to_string(id - gr.first_block) + " of " + where;
      }
    }
    pos = end;
  }
  return note.empty() ? "" : note + ")";
}

// Eq. 5c damping; every key optional (the kernel checks the ranges).
Damping read_damping(const Reader& r, const json& v, const std::string& path) {
  r.object(v, path, {"mass", "stiffness", "settle_time", "settle_sticking", "settle_slip_time"});
  Damping d;
  if (const json* x = Reader::find(v, "mass")) d.mass = r.number(*x, join_path(path, "mass"));
  if (const json* x = Reader::find(v, "stiffness")) d.stiffness = r.number(*x, join_path(path, "stiffness"));
  if (const json* x = Reader::find(v, "settle_time")) d.settle_time = r.number(*x, join_path(path, "settle_time"));
  if (const json* x = Reader::find(v, "settle_sticking"))
    d.settle_sticking = r.boolean(*x, join_path(path, "settle_sticking"));
  if (const json* x = Reader::find(v, "settle_slip_time"))
    d.settle_slip_time = r.number(*x, join_path(path, "settle_slip_time"));
  return d;
}

// Names identify blocks (output.tracked_blocks) and materials: two with one
// name would make a reference ambiguous. Empty names (unnamed) may repeat.
void check_block_names(const Reader& r, const std::vector<BlockSpec>& blocks,
                       const std::vector<GeneratedRegion>& generated, const std::vector<std::string>& generated_paths) {
  // The file path of block i's name: "blocks[i].name" or "generated[g].name".
  auto name_path = [&](std::size_t i) {
    for (std::size_t g = 0; g < generated.size(); ++g)
      if (static_cast<int>(i) >= generated[g].first_block &&
          static_cast<int>(i) < generated[g].first_block + generated[g].count)
        return join_path(generated_paths[g], "name");
    return join_path(index_path("blocks", i), "name");
  };
  std::map<std::string, std::size_t> seen;
  for (std::size_t i = 0; i < blocks.size(); ++i) {
    const std::string& name = blocks[i].name;
    if (name.empty()) continue;
    const auto [it, fresh] = seen.emplace(name, i);
    if (fresh) continue;
    r.fail(name_path(i), "duplicate block name \"" + name + "\" (blocks[" + std::to_string(it->second) + "] and blocks[" +
                             std::to_string(i) + "] have it; names must be unique)");
  }
}

}  // namespace

void check_step_count(const SceneFile& file, double dt, const std::string& label) {
  const Scene& s = file.scene;
  if (!(dt > 0.0) || !(s.duration > 0.0)) return;  // check_scene's business
  const double steps = s.duration / dt;
  if (steps <= static_cast<double>(file.max_steps)) return;
  throw SceneFileError(label + ": duration: " + format_number(s.duration) + " s at dt = " + format_number(dt) +
                       " s is " + format_number(std::ceil(steps)) + " steps, more than max_steps = " +
                       std::to_string(file.max_steps) +
                       " (a typo in duration or dt?); to allow a run this long, set \"max_steps\" in the scene file "
                       "or give dda run --max-steps N");
}

SceneFile parse_scene(const std::string& json_text, const std::string& file_label, const ReadOptions& options) {
  const Reader r(file_label, &json_text);
  if (json_text.size() > kMaxSceneFileBytes)
    throw SceneFileError(file_label + ": " + std::to_string(json_text.size()) + " bytes, more than " +
                         std::to_string(kMaxSceneFileBytes) + " (the reader's limit on scene files)");
  const json root = parse_json(json_text, r);
  if (!root.is_object()) r.fail("", "the top level must be a JSON object, got " + describe_value(root));
  r.object(root, "",
           {"name", "description", "materials", "blocks", "generated", "boundaries", "contact", "gravity", "strains",
            "broad_phase", "initial_overlap", "dt", "dt_fraction", "duration", "max_steps", "guards", "rotation_update",
            "damping", "output"});

  SceneFile f;
  Scene& s = f.scene;
  if (const json* x = Reader::find(root, "name")) s.name = r.string(*x, "name");
  if (const json* x = Reader::find(root, "description")) r.string(*x, "description");

  Names names;
  const json& mats = r.array(r.need(root, "", "materials"), "materials", " of materials");
  s.materials.clear();
  for (std::size_t i = 0; i < mats.size(); ++i) {
    names.materials.emplace_back();
    s.materials.push_back(read_material(r, mats[i], index_path("materials", i), names.materials.back()));
    const std::string& name = names.materials.back();
    for (std::size_t k = 0; !name.empty() && k < i; ++k)
      if (names.materials[k] == name)
        r.fail(join_path(index_path("materials", i), "name"),
               "duplicate material name \"" + name + "\" (also materials[" + std::to_string(k) + "].name)");
  }
  const json& blocks = r.array(r.need(root, "", "blocks"), "blocks", " of blocks");
  for (std::size_t i = 0; i < blocks.size(); ++i)
    s.blocks.push_back(read_block(r, blocks[i], index_path("blocks", i), names));
  std::vector<std::string> generated_paths;
  if (const json* x = Reader::find(root, "generated")) {
    // One generator object, or an array of them.
    if (x->is_object()) {
      generated_paths.push_back("generated");
    } else {
      r.array(*x, "generated", " of generated regions (or one object)");
      for (std::size_t i = 0; i < x->size(); ++i) generated_paths.push_back(index_path("generated", i));
    }
    for (std::size_t i = 0; i < generated_paths.size(); ++i)
      f.generated.push_back(
          read_generated(r, x->is_object() ? *x : (*x)[i], generated_paths[i], names, s.blocks));
  }
  if (s.blocks.size() > kMaxBlocks)
    r.fail(f.generated.empty() ? "blocks" : "generated",
           std::to_string(s.blocks.size()) + " blocks, more than " + std::to_string(kMaxBlocks) +
               " (the reader's limit on blocks)");
  check_block_names(r, s.blocks, f.generated, generated_paths);
  if (const json* x = Reader::find(root, "boundaries")) {
    r.array(*x, "boundaries", " of segments");
    for (std::size_t i = 0; i < x->size(); ++i)
      s.boundaries.push_back(read_boundary(r, (*x)[i], index_path("boundaries", i)));
  }
  s.contact = read_contact(r, r.need(root, "", "contact"), "contact");
  if (const json* x = Reader::find(root, "gravity")) s.gravity = r.vec2(*x, "gravity");
  if (const json* x = Reader::find(root, "strains")) s.strains = r.boolean(*x, "strains");
  if (const json* x = Reader::find(root, "broad_phase"))
    s.broad_phase = r.choice<BroadPhase>(*x, "broad_phase", {{"none", BroadPhase::kNone}, {"sweep", BroadPhase::kSweep}});
  if (const json* x = Reader::find(root, "initial_overlap")) s.initial_overlap = r.number(*x, "initial_overlap");
  // The step: "dt", or "dt_fraction" > 0 (a fraction of the predicted
  // critical step, which replaces dt when the simulation is built; a "dt"
  // next to it would be silently ignored).
  if (const json* x = Reader::find(root, "dt_fraction")) {
    s.dt_fraction = r.number(*x, "dt_fraction");
    if (!(s.dt_fraction >= 0.0))
      r.fail("dt_fraction", "must be >= 0 (0: the step is dt; > 0: this fraction of the predicted critical step)");
  }
  if (s.dt_fraction > 0.0) {
    if (Reader::find(root, "dt"))
      r.fail("dt", "has no effect with dt_fraction > 0 (the step is dt_fraction times the predicted critical step); "
                   "give one of them");
  } else {
    s.dt = r.number(r.need(root, "", "dt"), "dt");
  }
  s.duration = r.number(r.need(root, "", "duration"), "duration");
  f.max_steps = kDefaultMaxSteps;
  if (const json* x = Reader::find(root, "max_steps")) {
    f.max_steps = r.int64(*x, "max_steps");
    if (f.max_steps < 1) r.fail("max_steps", "must be >= 1 (the most steps a run may take)");
  }
  if (options.max_steps > 0) f.max_steps = options.max_steps;
  if (const json* x = Reader::find(root, "guards")) s.guards = read_guards(r, *x, "guards");
  if (const json* x = Reader::find(root, "rotation_update"))
    s.rotation_update = r.choice<RotationUpdate>(
        *x, "rotation_update", {{"paper_linear", RotationUpdate::kPaperLinear}, {"exact", RotationUpdate::kExact}});
  if (const json* x = Reader::find(root, "damping")) s.damping = read_damping(r, *x, "damping");

  // The kernel's semantic checks (polygons, ranges, overlaps at t = 0).
  try {
    check_scene(s);
  } catch (const SceneError& e) {
    // The kernel's message starts with the field ("blocks[1].vertices: ...").
    const std::string m = e.what();
    const std::size_t colon = m.find(": ");
    throw SceneFileError(r.where(colon == std::string::npos ? "" : m.substr(0, colon)) + ": " + m +
                         generated_note(m, f.generated, generated_paths));
  }
  if (s.dt_fraction == 0.0) check_step_count(f, s.dt, file_label);
  // Consistency that only matters for a file: a friction angle or update rule
  // that would be silently ignored.
  if (!s.contact.friction()) {
    if (s.contact.friction_deg > 0.0)
      r.fail("contact.friction_deg", "has no effect with contact.kt = 0 (kt > 0 switches friction on)");
    if (!s.contact.friction_rules.empty())
      r.fail("contact.friction_rules", "have no effect with contact.kt = 0 (kt > 0 switches friction on)");
    if (s.contact.friction_update != FrictionUpdate::kPaper)
      r.fail("contact.friction_update", "has no effect with contact.kt = 0 (kt > 0 switches friction on)");
  }
  f.output = read_output(r, Reader::find(root, "output"), s);
  return f;
}

SceneFile load_scene_file(const std::string& path, const ReadOptions& options) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw SceneFileError(path + ": is a directory, not a scene file");
  const std::string too_big =
      path + ": more than " + std::to_string(kMaxSceneFileBytes) + " bytes (the reader's limit on scene files)";
  // The size first (a regular file), then at most one byte more than the
  // limit is read (a pipe or device has no size).
  const std::uintmax_t size = fs::file_size(path, ec);
  if (!ec && size > kMaxSceneFileBytes) throw SceneFileError(too_big);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneFileError(path + ": cannot open: " + std::strerror(errno));
  constexpr std::size_t kChunk = std::size_t{64} << 10;  // bytes per read
  std::string text;
  if (!ec) text.reserve(static_cast<std::size_t>(size));
  std::vector<char> chunk(kChunk);
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxSceneFileBytes) throw SceneFileError(too_big);
  }
  if (in.bad()) throw SceneFileError(path + ": read error");
  return parse_scene(text, path, options);
}

namespace {

using ojson = nlohmann::ordered_json;

ojson vec2_json(Vec2 v) { return ojson::array({v.x, v.y}); }

const char* name_of(SmallEdgeRays m) {
  switch (m) {
    case SmallEdgeRays::kVirtualAndVertex: return "virtual_and_vertex";
    case SmallEdgeRays::kVirtualReplacesVertex: return "virtual_replaces_vertex";
  }
  return "virtual_and_vertex";
}

const char* name_of(FrictionUpdate u) {
  switch (u) {
    case FrictionUpdate::kPaper: return "paper";
    case FrictionUpdate::kReturnMapping: return "return_mapping";
  }
  return "paper";
}

const char* name_of(HRule h) {
  switch (h) {
    case HRule::kMinMaxEdge: return "min_max_edge";
    case HRule::kMeanEdge: return "mean_edge";
    case HRule::kGiven: return "given";
    case HRule::kInscribedRadius: return "inscribed_radius";
  }
  return "min_max_edge";
}

}  // namespace

std::string write_scene(const SceneFile& file) {
  const Scene& s = file.scene;
  ojson root = ojson::object();
  if (!s.name.empty()) root["name"] = s.name;
  ojson mats = ojson::array();
  for (const Material& m : s.materials)
    mats.push_back({{"density", m.density}, {"young", m.young}, {"poisson", m.poisson}});
  root["materials"] = mats;
  ojson blocks = ojson::array();
  for (const BlockSpec& b : s.blocks) {
    ojson jb = ojson::object();
    if (!b.name.empty()) jb["name"] = b.name;
    ojson verts = ojson::array();
    for (const Vec2& p : b.vertices) verts.push_back(vec2_json(p));
    jb["vertices"] = verts;
    jb["velocity"] = vec2_json(b.velocity);
    jb["spin"] = b.spin;
    jb["fixed"] = b.fixed;
    jb["material"] = b.material;
    jb["group"] = b.group;
    blocks.push_back(jb);
  }
  root["blocks"] = blocks;
  ojson bounds = ojson::array();
  for (const BoundarySegment& g : s.boundaries)
    bounds.push_back({{"a", vec2_json(g.a)}, {"b", vec2_json(g.b)}, {"depth", g.depth}, {"group", g.group}});
  root["boundaries"] = bounds;
  const ContactParams& c = s.contact;
  ojson contact = {{"kn", c.kn},
                  {"kt", c.kt},
                  {"friction_deg", c.friction_deg},
                  {"h_rule", name_of(c.h_rule)},
                  {"integration", c.integration == Integration::kExactEnvelope ? "exact_envelope" : "paper_bisector"},
                  {"small_edge_fraction", c.small_edge_fraction},
                  {"small_edge_rays", name_of(c.small_edge_rays)},
                  {"friction_update", name_of(c.friction_update)}};
  ojson rules = ojson::array();
  for (const FrictionRule& fr : c.friction_rules)
    rules.push_back({{"groups", {fr.group_a, fr.group_b}}, {"friction_deg", fr.friction_deg}});
  contact["friction_rules"] = rules;
  if (c.h_rule == HRule::kGiven) contact["h"] = c.h;
  root["contact"] = contact;
  root["gravity"] = vec2_json(s.gravity);
  root["strains"] = s.strains;
  root["broad_phase"] = s.broad_phase == BroadPhase::kSweep ? "sweep" : "none";
  root["initial_overlap"] = s.initial_overlap;
  // With dt_fraction > 0 the reader refuses a "dt" (it would be ignored).
  if (s.dt_fraction > 0.0) {
    root["dt_fraction"] = s.dt_fraction;
  } else {
    root["dt"] = s.dt;
    root["dt_fraction"] = s.dt_fraction;
  }
  root["duration"] = s.duration;
  if (file.max_steps != kDefaultMaxSteps) root["max_steps"] = file.max_steps;
  root["guards"] = {{"max_step_motion", s.guards.max_step_motion},
                    {"max_balance_error", s.guards.max_balance_error},
                    {"max_energy_growth", s.guards.max_energy_growth},
                    {"energy_check_every", s.guards.energy_check_every},
                    {"max_penetration", s.guards.max_penetration},
                    {"max_approach_energy", s.guards.max_approach_energy}};
  root["rotation_update"] = s.rotation_update == RotationUpdate::kExact ? "exact" : "paper_linear";
  root["damping"] = {{"mass", s.damping.mass},
                     {"stiffness", s.damping.stiffness},
                     {"settle_time", s.damping.settle_time},
                     {"settle_sticking", s.damping.settle_sticking},
                     {"settle_slip_time", s.damping.settle_slip_time}};
  root["output"] = {{"every", file.output.every},
                    {"snapshots", file.output.snapshot_times},
                    {"tracked_blocks", file.output.tracked_blocks},
                    {"vtk", file.output.vtk},
                    {"block_table", file.output.block_table}};
  if (file.output.vtk_every > 0) root["output"]["vtk_every"] = file.output.vtk_every;
  return root.dump(2) + "\n";
}

void save_scene_file(const std::string& path, const SceneFile& file) { write_file_atomic(path, write_scene(file)); }

}  // namespace dda::io
