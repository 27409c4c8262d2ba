// Scene files: JSON text <-> dda::Scene plus what a run should write.
// The schema is documented in lib/io/SCHEMA.md. Every error names the file,
// the field path and the reason, e.g.
//   "scene.json: blocks[3].vertices[2]: clockwise vertex order ..."
//   "scene.json: materials[0].densty: unknown key (did you mean 'density'?)"
//   "scene.json:7:12: JSON syntax error while parsing object - ..."
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include "dda/scene.hpp"

namespace dda::io {

// What `dda run` writes besides the scene's own state.
struct OutputSpec {
  int every = 100;                     // a time-series row every `every` steps (and at t = 0 and the end)
  std::vector<double> snapshot_times;  // s, ascending; vertices of every block at the step nearest each
  std::vector<int> tracked_blocks;     // scene block indices in the time series; empty = all
};

// One "generated" entry of a scene file: a region cut into blocks by joint
// sets (dda::generate_blocks). Its blocks are scene.blocks[first_block] to
// scene.blocks[first_block + count - 1], after the listed blocks.
struct GeneratedRegion {
  int first_block = 0;
  int count = 0;
  int dropped = 0;            // slivers below min_area, not in the scene
  double dropped_area = 0.0;  // m^2
};

struct SceneFile {
  dda::Scene scene;
  OutputSpec output;
  std::vector<GeneratedRegion> generated;  // empty if the file has no "generated" section
};

// Any problem with a scene file: unreadable, not JSON, not the schema, or a
// scene dda::check_scene rejects. what() is "<file>: <field>: <reason>" (or
// "<file>:<line>:<col>: ..." for syntax errors).
struct SceneFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Reads and validates a scene file; `path` labels the messages.
SceneFile load_scene_file(const std::string& path);

// Parses and validates JSON text; `file_label` prefixes every message.
// Also runs dda::check_scene (its message gets the file label in front).
SceneFile parse_scene(const std::string& json_text, const std::string& file_label);

// The JSON text of a scene file (vertices written out explicitly, numbers in
// shortest round-trip form): parse_scene(write_scene(f), ...) gives back f's
// scene and output (generated blocks come back as listed blocks, so
// `generated` comes back empty; with dt_fraction > 0 no "dt" is written, as
// the reader refuses it, so scene.dt comes back as its default, unused).
std::string write_scene(const SceneFile& file);

// Writes write_scene(file) to `path` atomically ("<path>.tmp", then rename).
// Throws std::runtime_error on I/O errors.
void save_scene_file(const std::string& path, const SceneFile& file);

}  // namespace dda::io
