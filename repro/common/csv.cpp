#include "repro/common/csv.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace repro {

namespace fs = std::filesystem;

std::string csv_quote(const std::string& field) {
  if (field.find_first_of(",\"\r\n") == std::string::npos) return field;
  std::string q = "\"";
  for (char c : field) {
    if (c == '"') q += '"';
    q += c;
  }
  q += '"';
  return q;
}

namespace {

// The shortest round-trip text of value into buf; returns its end.
char* write_full(double value, char (&buf)[64]) {
  const auto res = std::to_chars(buf, buf + sizeof buf, value);
  if (res.ec != std::errc()) throw std::runtime_error("to_chars failed");
  return res.ptr;
}

}  // namespace

std::string format_full(double value) {
  char buf[64];
  return std::string(buf, write_full(value, buf));
}

std::string format_short(double value, int digits) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, value);
  return buf;
}

std::string format_fixed(double value, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  return buf;
}

void make_parent_dirs(const std::string& path) {
  const fs::path parent = fs::path(path).parent_path();
  if (parent.empty()) return;
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) throw std::runtime_error("cannot create directory " + parent.string() + ": " + ec.message());
}

CsvWriter::CsvWriter(std::string path, std::vector<std::string> header,
                     const std::vector<std::string>& comments)
    : path_(std::move(path)), tmp_(path_ + ".tmp"), header_(std::move(header)) {
  if (header_.empty()) throw std::invalid_argument("CsvWriter(" + path_ + "): empty header");
  make_parent_dirs(path_);
  file_ = std::fopen(tmp_.c_str(), "w");
  if (!file_) throw std::runtime_error("CsvWriter: cannot open " + tmp_ + " for writing");
  for (const std::string& c : comments) {
    if (c.find_first_of("\r\n") != std::string::npos)
      throw std::invalid_argument("CsvWriter(" + path_ + "): comment with a line break");
    std::fprintf(file_, "# %s\n", c.c_str());
  }
  write_fields(header_);
}

CsvWriter::~CsvWriter() {
  if (file_) std::fclose(file_);
  if (!committed_) {
    std::error_code ec;
    fs::remove(tmp_, ec);  // best effort; never throw from a destructor
  }
}

void CsvWriter::check_open() const {
  if (committed_) throw std::logic_error("CsvWriter(" + path_ + "): write after commit");
  if (!file_) throw std::logic_error("CsvWriter(" + path_ + "): file not open");
}

void CsvWriter::write_fields(const std::vector<std::string>& fields) {
  line_.clear();
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) line_ += ',';
    line_ += csv_quote(fields[i]);
  }
  write_line();
}

void CsvWriter::write_line() {
  line_ += '\n';
  if (std::fwrite(line_.data(), 1, line_.size(), file_) != line_.size())
    throw std::runtime_error("CsvWriter: write error on " + tmp_);
}

void CsvWriter::row(const std::vector<double>& values) {
  check_open();
  if (values.size() != header_.size())
    throw std::invalid_argument("CsvWriter(" + path_ + "): row " + std::to_string(rows_ + 1) + " has " +
                                std::to_string(values.size()) + " values, header has " +
                                std::to_string(header_.size()));
  // Numbers need no quoting: each is written with to_chars straight into
  // one reused line (the drivers write thousands of rows per frame).
  line_.clear();
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!std::isfinite(values[i]))
      throw std::invalid_argument("CsvWriter(" + path_ + "): non-finite value " + format_full(values[i]) +
                                  " in column '" + header_[i] + "' (data row " + std::to_string(rows_ + 1) +
                                  ")");
    char buf[64];
    if (i) line_ += ',';
    line_.append(buf, write_full(values[i], buf));
  }
  write_line();
  ++rows_;
}

void CsvWriter::row(const std::vector<std::string>& fields) {
  check_open();
  if (fields.size() != header_.size())
    throw std::invalid_argument("CsvWriter(" + path_ + "): row " + std::to_string(rows_ + 1) + " has " +
                                std::to_string(fields.size()) + " fields, header has " +
                                std::to_string(header_.size()));
  write_fields(fields);
  ++rows_;
}

void CsvWriter::commit() {
  check_open();
  const bool flush_failed = std::fflush(file_) != 0 || std::ferror(file_) != 0;
  const bool close_failed = std::fclose(file_) != 0;
  file_ = nullptr;
  if (flush_failed || close_failed) throw std::runtime_error("CsvWriter: I/O error writing " + tmp_);
  std::error_code ec;
  fs::rename(tmp_, path_, ec);  // rename(2): atomic within one file system
  if (ec) throw std::runtime_error("CsvWriter: cannot rename " + tmp_ + " to " + path_ + ": " + ec.message());
  committed_ = true;
}

}  // namespace repro
