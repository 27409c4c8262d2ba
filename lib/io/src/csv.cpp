#include "dda/io/csv.hpp"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace dda::io {

namespace fs = std::filesystem;

std::uint64_t content_hash(const char* data, std::size_t size, std::uint64_t hash) {
  constexpr std::uint64_t kPrime = 1099511628211ull;  // FNV-1a 64
  for (std::size_t i = 0; i < size; ++i) {
    hash ^= static_cast<unsigned char>(data[i]);
    hash *= kPrime;
  }
  return hash;
}

std::string format_number(double value) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, value);
  if (res.ec != std::errc()) throw std::logic_error("format_number: to_chars failed");
  return std::string(buf, res.ptr);
}

std::string csv_quote(const std::string& field) {
  if (field.find_first_of(",\"\r\n") == std::string::npos) return field;
  std::string q = "\"";
  for (char c : field) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + '"';
}

namespace {

// `line` = `fields` quoted as needed, comma-separated, ended by a newline.
void quoted_line(const std::vector<std::string>& fields, std::string& line) {
  line.clear();
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) line += ',';
    line += csv_quote(fields[i]);
  }
  line += '\n';
}

void rename_into_place(const std::string& tmp, const std::string& path) {
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw OutputError("cannot rename " + tmp + " to " + path + ": " + ec.message());
  }
}

// Whether the first mark.bytes bytes of `file` hash to mark.hash.
bool holds_prefix(const std::string& file, const CsvMark& mark) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(file, ec);
  if (ec || size < mark.bytes) return false;
  std::FILE* f = std::fopen(file.c_str(), "rb");
  if (!f) return false;
  std::uint64_t hash = kEmptyHash, left = mark.bytes;
  char buf[1 << 16];
  while (left > 0) {
    const std::size_t want = left < sizeof buf ? static_cast<std::size_t>(left) : sizeof buf;
    if (std::fread(buf, 1, want, f) != want) break;
    hash = content_hash(buf, want, hash);
    left -= want;
  }
  std::fclose(f);
  return left == 0 && hash == mark.hash;
}

}  // namespace

CsvFile::CsvFile(std::string path, std::vector<std::string> header, const std::vector<std::string>& comments)
    : path_(std::move(path)), tmp_(path_ + ".tmp"), header_(std::move(header)) {
  if (header_.empty()) throw std::logic_error("CsvFile(" + path_ + "): empty header");
  for (const std::string& c : comments)
    if (c.find_first_of("\r\n") != std::string::npos)
      throw std::logic_error("CsvFile(" + path_ + "): comment with a line break");
  file_ = std::fopen(tmp_.c_str(), "wb");
  if (!file_) throw OutputError("cannot open " + tmp_ + " for writing: " + std::strerror(errno));
  try {
    for (const std::string& c : comments) {
      line_ = "# " + c + "\n";
      write_line();
    }
    quoted_line(header_, line_);
    write_line();
  } catch (...) {
    discard();
    throw;
  }
}

CsvFile::CsvFile(std::string path, std::vector<std::string> header, const CsvMark& from)
    : path_(std::move(path)), tmp_(path_ + ".tmp"), header_(std::move(header)) {
  const std::string source = resume_source(path_, from);
  if (source.empty())
    throw OutputError(path_ + ": does not hold the " + std::to_string(from.bytes) +
                      " bytes the checkpoint recorded (changed or removed since)");
  std::error_code ec;
  if (source == tmp_) {
    // The run that stopped left the tmp file: cut what it wrote after the mark.
    fs::resize_file(tmp_, from.bytes, ec);
    if (ec) throw OutputError("cannot truncate " + tmp_ + ": " + ec.message());
    file_ = std::fopen(tmp_.c_str(), "ab");
    if (!file_) throw OutputError("cannot open " + tmp_ + " for appending: " + std::strerror(errno));
  } else {
    // The committed file stays as it is until commit() replaces it.
    std::FILE* in = std::fopen(source.c_str(), "rb");
    if (!in) throw OutputError("cannot open " + source + ": " + std::strerror(errno));
    file_ = std::fopen(tmp_.c_str(), "wb");
    if (!file_) {
      std::fclose(in);
      throw OutputError("cannot open " + tmp_ + " for writing: " + std::strerror(errno));
    }
    std::uint64_t left = from.bytes;
    char buf[1 << 16];
    while (left > 0) {
      const std::size_t want = left < sizeof buf ? static_cast<std::size_t>(left) : sizeof buf;
      if (std::fread(buf, 1, want, in) != want || std::fwrite(buf, 1, want, file_) != want) break;
      left -= want;
    }
    std::fclose(in);
    if (left > 0) {
      discard();
      throw OutputError("cannot copy " + source + " to " + tmp_);
    }
  }
  bytes_ = from.bytes;
  hash_ = from.hash;
  rows_ = static_cast<std::size_t>(from.rows);
}

CsvFile::~CsvFile() { discard(); }

void CsvFile::discard() {
  if (file_) {
    std::fclose(file_);
    file_ = nullptr;
  }
  if (!done_) {
    done_ = true;
    std::error_code ec;
    fs::remove(tmp_, ec);  // best effort; never throws
  }
}

void CsvFile::write_line() {
  if (std::fwrite(line_.data(), 1, line_.size(), file_) != line_.size())
    throw OutputError("write error on " + tmp_ + ": " + std::strerror(errno));
  bytes_ += line_.size();
  hash_ = content_hash(line_.data(), line_.size(), hash_);
}

void CsvFile::row(const std::vector<CsvValue>& values) {
  if (done_ || !file_) throw std::logic_error("CsvFile(" + path_ + "): write after commit or discard");
  if (values.size() != header_.size())
    throw std::logic_error("CsvFile(" + path_ + "): row has " + std::to_string(values.size()) + " values, header has " +
                           std::to_string(header_.size()));
  line_.clear();
  for (std::size_t i = 0; i < values.size(); ++i) {
    const CsvValue& v = values[i];
    if (i) line_ += ',';
    if (v.is_integer) {
      line_ += std::to_string(v.integer);
    } else {
      if (!std::isfinite(v.number))
        throw NonFiniteValue(path_ + ": row " + std::to_string(rows_ + 1) + ", column " + header_[i] + ": " +
                             (std::isnan(v.number) ? "NaN" : "infinite value") + " (not written)");
      char buf[64];
      const auto res = std::to_chars(buf, buf + sizeof buf, v.number);
      line_.append(buf, res.ptr);
    }
  }
  line_ += '\n';
  write_line();
  ++rows_;
}

void CsvFile::text_row(const std::vector<std::string>& fields) {
  if (done_ || !file_) throw std::logic_error("CsvFile(" + path_ + "): write after commit or discard");
  if (fields.size() != header_.size())
    throw std::logic_error("CsvFile(" + path_ + "): row has " + std::to_string(fields.size()) + " fields, header has " +
                           std::to_string(header_.size()));
  quoted_line(fields, line_);
  write_line();
  ++rows_;
}

CsvMark CsvFile::mark() {
  if (done_ || !file_) throw std::logic_error("CsvFile(" + path_ + "): mark after commit or discard");
  // On the disk, not only in the system's cache: a checkpoint that names
  // these bytes must find them after a crash.
  if (std::fflush(file_) != 0 || ::fsync(fileno(file_)) != 0)
    throw OutputError("write error on " + tmp_ + ": " + std::strerror(errno));
  return {bytes_, rows_, hash_};
}

void CsvFile::commit() {
  if (done_ || !file_) throw std::logic_error("CsvFile(" + path_ + "): commit twice or after discard");
  const bool ok = std::fflush(file_) == 0 && !std::ferror(file_);
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!ok || !closed) {
    discard();
    throw OutputError("write error on " + tmp_);
  }
  done_ = true;
  rename_into_place(tmp_, path_);
}

std::string CsvFile::resume_source(const std::string& path, const CsvMark& mark) {
  const std::string tmp = path + ".tmp";
  if (holds_prefix(tmp, mark)) return tmp;
  if (holds_prefix(path, mark)) return path;
  return "";
}

void write_file_atomic(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) throw OutputError("cannot open " + tmp + " for writing: " + std::strerror(errno));
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size() && std::fflush(f) == 0;
  const bool closed = std::fclose(f) == 0;
  if (!ok || !closed) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw OutputError("write error on " + tmp);
  }
  rename_into_place(tmp, path);
}

}  // namespace dda::io
