// Scene files: JSON text <-> dda::Scene plus what a run should write.
// The schema is documented in lib/io/SCHEMA.md. Every error names the file,
// the field path and the reason, e.g.
//   "scene.json: blocks[3].vertices[2]: clockwise vertex order ..."
//   "scene.json: materials[0].densty: unknown key (did you mean 'density'?)"
//   "scene.json:7:12: JSON syntax error while parsing object - ..."
#pragma once
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "dda/cdem/model.hpp"
#include "dda/scene.hpp"

namespace dda::io {

// Limits of the reader, checked while the JSON text is read (before a
// document bigger than these is built in memory), so that the reader's memory
// stays within a small multiple of the file size (SCHEMA.md, "Limits").
// Each is far above what a scene needs and far below what exhausts memory.
inline constexpr std::size_t kMaxSceneFileBytes = std::size_t{16} << 20;  // bytes; 16 MiB ~ 100,000 four-vertex blocks
inline constexpr std::size_t kMaxNestingDepth = 16;      // objects/arrays inside each other; the schema needs 5
inline constexpr std::size_t kMaxArrayLength = 100000;   // elements of any array, members of any object
inline constexpr std::size_t kMaxBlocks = 100000;        // scene blocks, listed plus generated
inline constexpr std::size_t kMaxPolygonVertices = 256;  // `vertices` of a block, `region` of a generated region
inline constexpr int kMaxThreads = 1024;               // "threads" and dda run --threads
// Steps of a run (duration / dt) allowed unless the file's `max_steps` or
// `dda run --max-steps` says more: a typo in duration or dt (1e11 s instead
// of 1e1 s) is refused instead of starting a run of years.
inline constexpr std::int64_t kDefaultMaxSteps = 10000000;

// What `dda run` writes besides the scene's own state.
struct OutputSpec {
  int every = 100;                     // a time-series row every `every` steps (and at t = 0 and the end)
  std::vector<double> snapshot_times;  // s, ascending; vertices of every block at the step nearest each
  std::vector<int> tracked_blocks;     // scene block indices in the time series; empty = all
  bool vtk = false;                    // a ParaView series in DIR/vtk/ (vtk_series.hpp)
  int vtk_every = 0;                   // > 0: a ParaView frame every vtk_every steps; 0: at snapshot_times
  bool block_table = false;            // DIR/blocks.csv, one row per block per time-series row
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

// The contact model a scene file selects (its top-level "model").
enum class ContactModel : std::uint8_t {
  kPenalty,  // "penalty": Paper A's potential-based penalty contact, dda::Simulation (the default)
  kCdem,     // "cdem": Paper B's two-scale contact on CST-meshed blocks, dda::cdem::Model
};
const char* model_name(ContactModel m);

// How one block is meshed for the CDEM model (a block's "mesh").
struct CdemMesh {
  int divisions = 0;           // > 0: mesh_convex_polygon with this many divisions; 0: CdemSettings::divisions
  int cells_x = 0, cells_y = 0;  // > 0: mesh_rectangle with these cells (an axis-aligned rectangle)
};

// The "cdem" section: the model's options and the blocks' meshes.
struct CdemSettings {
  cdem::CdemOptions options;
  int divisions = 1;             // mesh divisions per block edge, unless a block's mesh says otherwise
  std::vector<CdemMesh> meshes;  // one per scene block
};

// When `dda run` writes a checkpoint (the "checkpoint" section, or the
// --checkpoint-every / --checkpoint-wall flags); 0: not on that clock.
struct CheckpointSpec {
  double every = 0.0;       // s of simulated time
  double every_wall = 0.0;  // s of wall-clock time
};

struct SceneFile {
  dda::Scene scene;
  OutputSpec output;
  std::vector<GeneratedRegion> generated;  // empty if the file has no "generated" section
  // Largest step count a run may take: ReadOptions::max_steps if > 0, else the
  // file's `max_steps`, else kDefaultMaxSteps.
  std::int64_t max_steps = kDefaultMaxSteps;
  ContactModel model = ContactModel::kPenalty;
  CdemSettings cdem;          // with model kCdem
  int threads = 0;            // the file's "threads" (0: not given, 1 thread)
  CheckpointSpec checkpoint;  // the file's "checkpoint" (either model)
  // content_hash of the file's text (checkpoints name the scene by it).
  std::uint64_t text_hash = 0;
};

// The CDEM scene of a file with model kCdem: its blocks meshed as the file
// says, its materials, gravity, dt, duration and the "cdem" options.
cdem::CdemScene cdem_scene(const SceneFile& file);

struct ReadOptions {
  // > 0: overrides the file's `max_steps` (`dda run --max-steps N`).
  std::int64_t max_steps = 0;
};

// Any problem with a scene file: unreadable, not JSON, not the schema, or a
// scene dda::check_scene rejects. what() is
// "<file>:<line>:<col>: <field>: <reason>", where line and column (1-based,
// in bytes) point at the field in the file; without them ("<file>: <field>:
// <reason>") where the field is not in the file (a missing key, a generated
// block); "<file>:<line>:<col>: near <field>: ..." for JSON syntax errors.
struct SceneFileError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Reads and validates a scene file; `path` labels the messages.
// Files bigger than kMaxSceneFileBytes are refused before they are read.
SceneFile load_scene_file(const std::string& path, const ReadOptions& options = {});

// Parses and validates JSON text; `file_label` prefixes every message.
// Also runs dda::check_scene (its message gets the file label in front).
// With dt given, also refuses duration / dt > the step limit (max_steps).
SceneFile parse_scene(const std::string& json_text, const std::string& file_label, const ReadOptions& options = {});

// Refuses a run of more than file.max_steps steps of `dt` (the step the
// simulation uses: with dt_fraction > 0 only known once it is built); the
// message says how to allow it. `label` prefixes the message (the file).
void check_step_count(const SceneFile& file, double dt, const std::string& label);

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
