// Strict JSON reading for the scene files: the text read within the
// reader's limits (file size, nesting depth, array and object sizes, checked
// while the text is parsed, before a too-big document is built), duplicate
// keys refused, and typed access to the document with field paths, so that
// every error says "<file>:<line>:<col>: <field>: <reason>". Internal to
// dda_io (scene_read.cpp and the model sections read through it).
#pragma once
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>
#include <string>
#include <type_traits>
#include <utility>

#include <nlohmann/json.hpp>

#include "dda/io/scene_file.hpp"
#include "dda/vec2.hpp"

namespace dda::io::detail {

using json = nlohmann::json;

// "parent.key" (or "key" at the top level) and "parent[i]".
std::string join_path(const std::string& parent, const std::string& key);
std::string index_path(const std::string& parent, std::size_t i);
std::string single_quoted(const std::string& s);
// "string \"abc\"", "number 2.5", "array", ... for "expected X, got Y".
std::string describe_value(const json& v);

// "file:line:col" of `path` in the file (re-reading it), or "file" if the
// path is not in the file.
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

  // Checks v is an object whose keys are all in `allowed` (an unknown key
  // fails naming the nearest allowed one).
  void object(const json& v, const std::string& path, std::initializer_list<const char*> allowed) const;

  static const json* find(const json& obj, const char* key) {
    const auto it = obj.find(key);
    return it == obj.end() ? nullptr : &*it;
  }

  // If `obj` has `key`: `to` = its value read as `to`'s type says (a number,
  // an integer, a boolean, a string or a point; `path`.`key` in messages);
  // else `to` keeps its default.
  template <class T>
  void optional(const json& obj, const std::string& path, const char* key, T& to) const {
    const json* v = find(obj, key);
    if (!v) return;
    const std::string at = join_path(path, key);
    if constexpr (std::is_same_v<T, double>)
      to = number(*v, at);
    else if constexpr (std::is_same_v<T, int>)
      to = integer(*v, at);
    else if constexpr (std::is_same_v<T, bool>)
      to = boolean(*v, at);
    else if constexpr (std::is_same_v<T, std::string>)
      to = string(*v, at);
    else {
      static_assert(std::is_same_v<T, Vec2>, "optional: a number, integer, boolean, string or point");
      to = vec2(*v, at);
    }
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
    return choice(v, path, options.begin(), options.end());
  }
  template <typename E, std::size_t N>
  E choice(const json& v, const std::string& path, const std::pair<const char*, E> (&options)[N]) const {
    return choice(v, path, options, options + N);
  }
  template <typename E>
  E choice(const json& v, const std::string& path, const std::pair<const char*, E>* first,
           const std::pair<const char*, E>* last) const {
    const std::string s = string(v, path);
    std::string list;
    for (const auto* o = first; o != last; ++o) {
      if (s == o->first) return o->second;
      list += std::string(list.empty() ? "" : ", ") + "\"" + o->first + "\"";
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

// Parses `text` within the reader's limits (scene_file.hpp): a syntax error,
// a limit exceeded, a duplicate key or a number beyond the double range
// throws SceneFileError with the position and the field being read.
json parse_json(const std::string& text, const Reader& reader);

// The bytes of the file at `path`, refused (SceneFileError) beyond
// kMaxSceneFileBytes before more than one byte past the limit is read.
std::string read_text_file(const std::string& path);

}  // namespace dda::io::detail
