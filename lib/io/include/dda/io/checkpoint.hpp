// Checkpoints of `dda run`: the state of a run, saved so that
// `dda run --resume DIR` continues it to the same bits as a run that was
// never stopped.
//
// The file (DIR/checkpoint.dda):
//   "DDACKPT\n"       8 bytes, the magic
//   format            u32, kCheckpointFormat (little-endian, as every field)
//   length            u64, bytes of the body
//   body              `length` bytes (below)
//   checksum          u64, content_hash of everything before it
// The body (dda/state_bytes.hpp encoding):
//   scene path        text: the scene file the run read (absolute)
//   scene hash        u64: content_hash of that file's text
//   model             text: the scene's "model" ("penalty", "cdem")
//   sections          u32 count, then per section its name (text) and its
//                     bytes (text): "run" (the run loop: step, output
//                     files' lengths and hashes, schedule) and the model's
//                     state: "penalty.simulation" (Simulation::save_state)
//                     or "cdem.model" (cdem::Model::save_state).
// Written through "<file>.tmp": flushed to the disk, then renamed over the
// previous checkpoint, which stays valid until the new one is complete.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace dda::io {

inline constexpr std::uint32_t kCheckpointFormat = 1;
inline constexpr const char* kCheckpointFileName = "checkpoint.dda";

// A checkpoint that cannot be used: missing, truncated, corrupted, of
// another format version or another scene. what() names the file and the
// reason; nothing was written.
struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct CheckpointSection {
  std::string name;
  std::string bytes;
};

struct Checkpoint {
  std::string scene_path;
  std::uint64_t scene_hash = 0;
  std::string model;
  std::vector<CheckpointSection> sections;

  // The section of that name, or null.
  const CheckpointSection* find(const std::string& name) const;
};

// The file's bytes, and back. decode_checkpoint throws CheckpointError
// (`label` first in the message) for a file that is not a checkpoint, is
// truncated, has another format version or fails its checksum.
std::string encode_checkpoint(const Checkpoint& c);
Checkpoint decode_checkpoint(const std::string& bytes, const std::string& label);

// Writes DIR/checkpoint.dda atomically and durably (tmp, fsync, rename).
// Throws OutputError.
void write_checkpoint(const std::string& dir, const Checkpoint& c);
// Reads DIR/checkpoint.dda; CheckpointError if DIR does not exist, holds no
// checkpoint, or it is not usable (decode_checkpoint).
Checkpoint read_checkpoint(const std::string& dir);

}  // namespace dda::io
