#include "json_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <vector>

namespace dda::io::detail {

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


void Reader::object(const json& v, const std::string& path, std::initializer_list<const char*> allowed) const {
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

namespace {

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

}  // namespace

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

std::string read_text_file(const std::string& path) {
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
  return text;
}

}  // namespace dda::io::detail
