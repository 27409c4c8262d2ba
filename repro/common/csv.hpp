// Atomic CSV output for the reproduction drivers: the library's writer
// (dda::io::CsvFile, lib/io/include/dda/io/csv.hpp, target dda_csv, which
// depends on nothing else of the project) with the drivers' conventions.
//
// CsvWriter writes to "<path>.tmp" and only commit() renames it to <path>, so
// a reader (or make) never sees a half-written file: a driver that throws or
// exits early leaves no output at all (the destructor removes the tmp file).
// Non-finite numbers are refused with an exception naming the column: a NaN
// is a failed computation, never data.
#pragma once
#include <initializer_list>
#include <string>
#include <vector>

#include "dda/io/csv.hpp"

namespace repro {

class CsvWriter {
 public:
  // Opens "<path>.tmp" (creating parent directories) and writes the optional
  // comment lines, each prefixed by "# ", then the header line. Throws
  // std::runtime_error if the file cannot be opened.
  CsvWriter(std::string path, std::vector<std::string> header,
            const std::vector<std::string>& comments = {});
  // Without commit() the destructor closes and removes the tmp file.

  // One row of numbers (shortest round-trip decimal form, i.e. full
  // precision). Throws std::invalid_argument if the width differs from the
  // header or a value is NaN/inf (the message names the column and row).
  void row(const std::vector<double>& values);
  void row(std::initializer_list<double> values) { row(std::vector<double>(values)); }
  // One row of text fields, quoted per RFC 4180 where needed.
  void row(const std::vector<std::string>& fields);
  // The text of number `value` in column `column` of the next row, for a
  // text row that mixes numbers in: shortest round-trip form. Throws
  // std::invalid_argument for NaN/inf, as row(values) does.
  std::string number_field(double value, std::size_t column) const;

  // Flushes, closes and atomically renames the tmp file to the final path.
  // Throws std::runtime_error on any I/O error (the tmp file is then removed).
  void commit() { file_.commit(); }

  const std::string& path() const { return file_.path(); }
  std::size_t rows() const { return file_.rows(); }

 private:
  dda::io::CsvFile file_;
  std::vector<dda::io::CsvValue> values_;  // the row being written, reused from row to row
};

// Quotes a CSV field if it contains a comma, quote, CR or LF.
std::string csv_quote(const std::string& field);
// Shortest decimal text that reads back to exactly `value`.
std::string format_full(double value);
// Short human-readable number, `digits` significant digits ("%.*g").
std::string format_short(double value, int digits = 4);
// Fixed-point with `decimals` digits after the point ("%.*f"), e.g. a time in
// a file name or a caption: format_fixed(0.5, 1) == "0.5".
std::string format_fixed(double value, int decimals);
// Creates the parent directories of a file path (no-op if none).
void make_parent_dirs(const std::string& path);

}  // namespace repro
