#include "dda/io/csv.hpp"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <system_error>

namespace dda::io {

namespace fs = std::filesystem;

std::string format_number(double value) {
  char buf[64];
  const auto res = std::to_chars(buf, buf + sizeof buf, value);
  if (res.ec != std::errc()) throw std::logic_error("format_number: to_chars failed");
  return std::string(buf, res.ptr);
}

namespace {

std::string quote(const std::string& field) {
  if (field.find_first_of(",\"\r\n") == std::string::npos) return field;
  std::string q = "\"";
  for (char c : field) {
    if (c == '"') q += '"';
    q += c;
  }
  return q + '"';
}

void rename_into_place(const std::string& tmp, const std::string& path) {
  std::error_code ec;
  fs::rename(tmp, path, ec);
  if (ec) {
    fs::remove(tmp, ec);
    throw OutputError("cannot rename " + tmp + " to " + path + ": " + ec.message());
  }
}

}  // namespace

CsvFile::CsvFile(std::string path, std::vector<std::string> header)
    : path_(std::move(path)), tmp_(path_ + ".tmp"), header_(std::move(header)) {
  if (header_.empty()) throw std::logic_error("CsvFile(" + path_ + "): empty header");
  file_ = std::fopen(tmp_.c_str(), "wb");
  if (!file_) throw OutputError("cannot open " + tmp_ + " for writing: " + std::strerror(errno));
  line_.clear();
  for (std::size_t i = 0; i < header_.size(); ++i) {
    if (i) line_ += ',';
    line_ += quote(header_[i]);
  }
  line_ += '\n';
  if (std::fwrite(line_.data(), 1, line_.size(), file_) != line_.size()) {
    discard();
    throw OutputError("write error on " + tmp_);
  }
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
      line_ += format_number(v.number);
    }
  }
  line_ += '\n';
  if (std::fwrite(line_.data(), 1, line_.size(), file_) != line_.size())
    throw OutputError("write error on " + tmp_ + ": " + std::strerror(errno));
  ++rows_;
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
