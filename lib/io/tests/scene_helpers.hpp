// Scene files in the tests: a scene's text written to a fresh directory, the
// message a scene is refused with, and the check that such a message names
// the file, the field and the reason.
#pragma once
#include <catch2/catch.hpp>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "dda/io/scene_file.hpp"

namespace dda::io::test {

// The names every scene-file test uses (`using namespace dda::io::test;`).
using dda::io::parse_scene;
using dda::io::SceneFile;
using dda::io::SceneFileError;
using nlohmann::json;

// `text` written to `<dir>/<name>`, `dir` created first; the file's path.
inline std::string write_scene(const std::string& dir, const std::string& text, const std::string& name = "s.json") {
  std::filesystem::create_directories(dir);
  const std::string path = dir + "/" + name;
  std::ofstream(path) << text;
  return path;
}

// The message of the SceneFileError parsing `text` as "scene.json" raises
// ("" if accepted).
inline std::string error_of(const std::string& text, const ReadOptions& opt = {}) {
  try {
    parse_scene(text, "scene.json", opt);
  } catch (const SceneFileError& e) {
    return e.what();
  }
  return "";
}
inline std::string error_of(const char* text) { return error_of(std::string(text)); }
inline std::string error_of(const nlohmann::json& j, const ReadOptions& opt = {}) { return error_of(j.dump(2), opt); }

// The message of the SceneFileError loading the file `path` raises ("" if
// it loads).
inline std::string load_error_of(const std::string& path) {
  try {
    load_scene_file(path);
  } catch (const SceneFileError& e) {
    return e.what();
  }
  return "";
}

// "<file>:<line>:<col>: " or "<file>: " (a field not in the file): the
// length of that prefix of `message`, or npos.
inline std::size_t location_prefix(const std::string& message, const std::string& file) {
  if (message.rfind(file, 0) != 0) return std::string::npos;
  std::size_t i = file.size();
  for (int part = 0; part < 2 && i < message.size() && message[i] == ':'; ++part) {
    std::size_t j = i + 1;
    while (j < message.size() && std::isdigit(static_cast<unsigned char>(message[j]))) ++j;
    if (j == i + 1) break;
    i = j;
  }
  return message.compare(i, 2, ": ") == 0 ? i + 2 : std::string::npos;
}

// "<file>[:line:col]: <field>: ..." containing `reason`.
inline void check_rejected(const std::string& message, const std::string& field, const std::string& reason,
                           const std::string& file = "scene.json") {
  INFO("message: " << message);
  const std::size_t at = location_prefix(message, file);
  REQUIRE(at != std::string::npos);
  CHECK(message.compare(at, field.size() + 2, field + ": ") == 0);
  CHECK(message.find(reason) != std::string::npos);
}
inline void check_rejected(const nlohmann::json& j, const std::string& field, const std::string& reason) {
  check_rejected(error_of(j), field, reason);
}

}  // namespace dda::io::test
