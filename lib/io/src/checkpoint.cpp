#include "dda/io/checkpoint.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

#include "dda/io/csv.hpp"
#include "dda/state_bytes.hpp"

namespace dda::io {

namespace {

namespace fs = std::filesystem;

constexpr char kMagic[8] = {'D', 'D', 'A', 'C', 'K', 'P', 'T', '\n'};
constexpr std::size_t kHeaderBytes = 8 + 4 + 8;  // magic, format, body length
constexpr std::size_t kChecksumBytes = 8;

std::uint64_t read_u64(const char* p) {
  std::uint64_t x = 0;
  for (int k = 0; k < 8; ++k) x |= static_cast<std::uint64_t>(static_cast<unsigned char>(p[k])) << (8 * k);
  return x;
}

std::uint32_t read_u32(const char* p) {
  std::uint32_t x = 0;
  for (int k = 0; k < 4; ++k) x |= static_cast<std::uint32_t>(static_cast<unsigned char>(p[k])) << (8 * k);
  return x;
}

}  // namespace

const CheckpointSection* Checkpoint::find(const std::string& name) const {
  for (const CheckpointSection& s : sections)
    if (s.name == name) return &s;
  return nullptr;
}

std::string encode_checkpoint(const Checkpoint& c) {
  ByteWriter body;
  body.text(c.scene_path);
  body.u64(c.scene_hash);
  body.text(c.model);
  body.u32(static_cast<std::uint32_t>(c.sections.size()));
  for (const CheckpointSection& s : c.sections) {
    body.text(s.name);
    body.text(s.bytes);
  }
  ByteWriter file;
  for (char ch : kMagic) file.u8(static_cast<std::uint8_t>(ch));
  file.u32(kCheckpointFormat);
  file.u64(body.bytes().size());
  std::string out = file.take();
  out += body.bytes();
  ByteWriter sum;
  sum.u64(content_hash(out.data(), out.size()));
  return out + sum.bytes();
}

Checkpoint decode_checkpoint(const std::string& bytes, const std::string& label) {
  auto fail = [&](const std::string& why) -> CheckpointError { return CheckpointError(label + ": " + why); };
  if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw fail(bytes.size() < sizeof kMagic && std::memcmp(bytes.data(), kMagic, bytes.size()) == 0
                   ? "truncated: " + std::to_string(bytes.size()) + " bytes, not even the header"
                   : "not a dda checkpoint (no DDACKPT header)");
  if (bytes.size() < kHeaderBytes) throw fail("truncated: " + std::to_string(bytes.size()) + " bytes, not even the header");
  const std::uint32_t format = read_u32(bytes.data() + 8);
  if (format != kCheckpointFormat)
    throw fail("checkpoint format version " + std::to_string(format) + "; this dda reads version " +
               std::to_string(kCheckpointFormat) + " (written by another version of dda)");
  const std::uint64_t length = read_u64(bytes.data() + 12);
  const std::uint64_t have = bytes.size() - kHeaderBytes;
  if (length > have || have - length < kChecksumBytes)
    throw fail("truncated: " + std::to_string(bytes.size()) + " bytes, the header announces " +
               std::to_string(length + kHeaderBytes + kChecksumBytes));
  if (have - length > kChecksumBytes)
    throw fail("corrupted: " + std::to_string(have - length - kChecksumBytes) + " bytes after the checksum");
  const std::size_t body_end = kHeaderBytes + static_cast<std::size_t>(length);
  if (read_u64(bytes.data() + body_end) != content_hash(bytes.data(), body_end))
    throw fail("corrupted: the checksum does not match the contents");
  Checkpoint c;
  try {
    ByteReader r(bytes.data() + kHeaderBytes, static_cast<std::size_t>(length), label);
    c.scene_path = r.text();
    c.scene_hash = r.u64();
    c.model = r.text();
    const std::uint32_t n = r.u32();
    for (std::uint32_t k = 0; k < n; ++k) {
      CheckpointSection s;
      s.name = r.text();
      s.bytes = r.text();
      c.sections.push_back(std::move(s));
    }
    r.expect_end();
  } catch (const StateError& e) {
    throw fail(std::string("corrupted: ") + e.what());
  }
  return c;
}

void write_checkpoint(const std::string& dir, const Checkpoint& c) {
  const std::string path = (fs::path(dir) / kCheckpointFileName).string();
  const std::string tmp = path + ".tmp";
  const std::string bytes = encode_checkpoint(c);
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw OutputError("cannot open " + tmp + " for writing: " + std::strerror(errno));
  // On the disk before the rename: a crash leaves the old checkpoint or the new one, never half of one.
  const bool ok = std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size() && std::fflush(f) == 0 &&
                  ::fsync(fileno(f)) == 0;
  const bool closed = std::fclose(f) == 0;
  std::error_code ec;
  if (!ok || !closed) {
    fs::remove(tmp, ec);
    throw OutputError("write error on " + tmp);
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw OutputError("cannot rename " + tmp + " to " + path + ": " + ec.message());
  }
}

Checkpoint read_checkpoint(const std::string& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) throw CheckpointError(dir + ": no such directory (nothing to resume)");
  if (!fs::is_directory(dir, ec)) throw CheckpointError(dir + ": not a directory (give the run's output directory)");
  const std::string path = (fs::path(dir) / kCheckpointFileName).string();
  if (!fs::exists(path, ec))
    throw CheckpointError(dir + ": holds no checkpoint (" + kCheckpointFileName +
                          "): the run wrote none, or it completed; start it again with dda run SCENE --out " + dir);
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CheckpointError(path + ": cannot open: " + std::strerror(errno));
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw CheckpointError(path + ": read error");
  return decode_checkpoint(bytes, path);
}

}  // namespace dda::io
