// Atomic CSV files for run output.
//
// CsvFile writes to "<path>.tmp"; commit() flushes, closes and renames it to
// <path>, so a reader never sees a half-written file. Without commit() the
// destructor removes the tmp file. A row containing NaN or infinity is
// refused as a whole (NonFiniteValue, naming the column): a non-finite number
// is a failed computation, never data.
#pragma once
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace dda::io {

// An output file could not be created, written or renamed.
struct OutputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A row held a NaN or infinity; nothing of that row was written.
struct NonFiniteValue : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// One CSV field: a number (written in shortest round-trip form) or an
// integer (written exactly).
struct CsvValue {
  CsvValue(double v) : number(v) {}  // NOLINT: implicit on purpose
  CsvValue(int v) : integer(v), is_integer(true) {}
  CsvValue(long v) : integer(v), is_integer(true) {}
  CsvValue(long long v) : integer(v), is_integer(true) {}
  CsvValue(std::size_t v) : integer(static_cast<long long>(v)), is_integer(true) {}
  double number = 0.0;
  long long integer = 0;
  bool is_integer = false;
};

class CsvFile {
 public:
  // Opens "<path>.tmp" and writes the header line. The parent directory must
  // exist. Throws OutputError.
  CsvFile(std::string path, std::vector<std::string> header);
  ~CsvFile();
  CsvFile(const CsvFile&) = delete;
  CsvFile& operator=(const CsvFile&) = delete;

  // Writes one row; throws NonFiniteValue (row not written) or OutputError.
  // The width must match the header (std::logic_error otherwise).
  void row(const std::vector<CsvValue>& values);
  // Flushes, closes, renames into place. Throws OutputError (tmp removed).
  void commit();
  // Closes and removes the tmp file (what the destructor does).
  void discard();

  const std::string& path() const { return path_; }
  const std::vector<std::string>& header() const { return header_; }
  std::size_t rows() const { return rows_; }

 private:
  std::string path_, tmp_;
  std::vector<std::string> header_;
  std::FILE* file_ = nullptr;
  std::size_t rows_ = 0;
  bool done_ = false;
  std::string line_;
};

// Shortest decimal text that reads back to exactly `value` (finite values).
std::string format_number(double value);

// Writes `text` to `path` atomically (via "<path>.tmp"). Throws OutputError.
void write_file_atomic(const std::string& path, const std::string& text);

}  // namespace dda::io
