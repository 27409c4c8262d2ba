// Atomic CSV output for the reproduction drivers.
//
// CsvWriter writes to "<path>.tmp" and only commit() renames it to <path>, so
// a reader (or make) never sees a half-written file: a driver that throws or
// exits early leaves no output at all (the destructor removes the tmp file).
// Non-finite numbers are refused with an exception naming the column: a NaN
// is a failed computation, never data.
#pragma once
#include <cstdio>
#include <initializer_list>
#include <string>
#include <vector>

namespace repro {

class CsvWriter {
 public:
  // Opens "<path>.tmp" (creating parent directories) and writes the optional
  // comment lines, each prefixed by "# ", then the header line. Throws
  // std::runtime_error if the file cannot be opened.
  CsvWriter(std::string path, std::vector<std::string> header,
            const std::vector<std::string>& comments = {});
  ~CsvWriter();  // without commit(): closes and removes the tmp file
  CsvWriter(const CsvWriter&) = delete;
  CsvWriter& operator=(const CsvWriter&) = delete;

  // One row of numbers (shortest round-trip decimal form, i.e. full
  // precision). Throws std::invalid_argument if the width differs from the
  // header or a value is NaN/inf (the message names the column and row).
  void row(const std::vector<double>& values);
  void row(std::initializer_list<double> values) { row(std::vector<double>(values)); }
  // One row of text fields, quoted per RFC 4180 where needed.
  void row(const std::vector<std::string>& fields);

  // Flushes, closes and atomically renames the tmp file to the final path.
  // Throws std::runtime_error on any I/O error (the tmp file is then removed).
  void commit();

  const std::string& path() const { return path_; }
  std::size_t rows() const { return rows_; }

 private:
  void check_open() const;
  void write_fields(const std::vector<std::string>& fields);
  void write_line();  // line_ and a newline to the file

  std::string path_, tmp_;
  std::vector<std::string> header_;
  std::FILE* file_ = nullptr;
  std::size_t rows_ = 0;
  bool committed_ = false;
  std::string line_;  // the row being written, reused from row to row
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
