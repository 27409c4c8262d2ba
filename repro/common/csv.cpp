#include "repro/common/csv.hpp"

#include <cstdio>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace repro {

namespace fs = std::filesystem;

std::string csv_quote(const std::string& field) { return dda::io::csv_quote(field); }

std::string format_full(double value) { return dda::io::format_number(value); }

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

namespace {

// The parent directories exist before the file is opened.
const std::string& with_parent_dirs(const std::string& path) {
  make_parent_dirs(path);
  return path;
}

std::vector<std::string> checked_header(std::vector<std::string> header, const std::string& path) {
  if (header.empty()) throw std::invalid_argument("CsvWriter(" + path + "): empty header");
  return header;
}

}  // namespace

CsvWriter::CsvWriter(std::string path, std::vector<std::string> header, const std::vector<std::string>& comments)
    : file_(with_parent_dirs(path), checked_header(std::move(header), path), comments) {}

void CsvWriter::row(const std::vector<double>& values) {
  const std::vector<std::string>& header = file_.header();
  if (values.size() != header.size())
    throw std::invalid_argument("CsvWriter(" + path() + "): row " + std::to_string(rows() + 1) + " has " +
                                std::to_string(values.size()) + " values, header has " +
                                std::to_string(header.size()));
  for (std::size_t i = 0; i < values.size(); ++i) number_field(values[i], i);
  values_.assign(values.begin(), values.end());
  file_.row(values_);
}

std::string CsvWriter::number_field(double value, std::size_t column) const {
  const std::string text = format_full(value);
  if (!std::isfinite(value))
    throw std::invalid_argument("CsvWriter(" + path() + "): non-finite value " + text + " in column '" +
                                file_.header().at(column) + "' (data row " + std::to_string(rows() + 1) + ")");
  return text;
}

void CsvWriter::row(const std::vector<std::string>& fields) {
  if (fields.size() != file_.header().size())
    throw std::invalid_argument("CsvWriter(" + path() + "): row " + std::to_string(rows() + 1) + " has " +
                                std::to_string(fields.size()) + " fields, header has " +
                                std::to_string(file_.header().size()));
  file_.text_row(fields);
}

}  // namespace repro
