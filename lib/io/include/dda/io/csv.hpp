// Atomic CSV files: the one writer of the library's run output and of the
// reproduction drivers (repro/common/csv.hpp adapts it).
//
// CsvFile writes to "<path>.tmp"; commit() flushes, closes and renames it to
// <path>, so a reader never sees a half-written file. Without commit() the
// destructor removes the tmp file. A row containing NaN or infinity is
// refused as a whole (NonFiniteValue, naming the column): a non-finite number
// is a failed computation, never data.
//
// A file can be continued by a later process (`dda run --resume`): mark()
// flushes and returns how far it is written (bytes, rows and the hash of
// those bytes); a CsvFile opened from that mark continues from exactly there,
// from the tmp file or the committed one, whichever still holds those bytes.
//
// This target (dda_csv) depends on nothing else of the project.
#pragma once
#include <cstdint>
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

// 64-bit FNV-1a hash of `size` bytes, continuing from `hash` (the empty
// input's hash by default): checksums of checkpoints and of written output.
inline constexpr std::uint64_t kEmptyHash = 14695981039346656037ull;
std::uint64_t content_hash(const char* data, std::size_t size, std::uint64_t hash = kEmptyHash);

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

// How far a file is written: its first `bytes` bytes (with the header) hash
// to `hash`, and hold `rows` data rows.
struct CsvMark {
  std::uint64_t bytes = 0;
  std::uint64_t rows = 0;
  std::uint64_t hash = kEmptyHash;
};

class CsvFile {
 public:
  // Opens "<path>.tmp" and writes the optional comment lines (each as
  // "# <comment>"; no line breaks inside) and the header line. The parent
  // directory must exist. Throws OutputError.
  CsvFile(std::string path, std::vector<std::string> header, const std::vector<std::string>& comments = {});
  // Continues the file written up to `from` (resume_source says from which
  // file; it must hold those bytes). Throws OutputError.
  CsvFile(std::string path, std::vector<std::string> header, const CsvMark& from);
  ~CsvFile();
  CsvFile(const CsvFile&) = delete;
  CsvFile& operator=(const CsvFile&) = delete;

  // Writes one row; throws NonFiniteValue (row not written) or OutputError.
  // The width must match the header (std::logic_error otherwise).
  void row(const std::vector<CsvValue>& values);
  // One row of text fields, quoted per RFC 4180 where needed.
  void text_row(const std::vector<std::string>& fields);
  // Flushes; how far the file is written.
  CsvMark mark();
  // Flushes, closes, renames into place. Throws OutputError (tmp removed).
  void commit();
  // Closes and removes the tmp file (what the destructor does).
  void discard();

  // The file that holds the bytes of `mark` for output `path`: its tmp file
  // or the committed file (checked in that order: a run stopped without
  // committing left the tmp), or "" if neither does (missing, shorter, or
  // changed).
  static std::string resume_source(const std::string& path, const CsvMark& mark);

  const std::string& path() const { return path_; }
  const std::vector<std::string>& header() const { return header_; }
  std::size_t rows() const { return rows_; }

 private:
  void write_line();  // line_ (ending in a newline) to the file
  std::string path_, tmp_;
  std::vector<std::string> header_;
  std::FILE* file_ = nullptr;
  std::size_t rows_ = 0;
  std::uint64_t bytes_ = 0;
  std::uint64_t hash_ = kEmptyHash;
  bool done_ = false;
  std::string line_;
};

// Shortest decimal text that reads back to exactly `value` (finite values).
std::string format_number(double value);
// A CSV field, quoted per RFC 4180 if it holds a comma, quote, CR or LF.
std::string csv_quote(const std::string& field);

// Writes `text` to `path` atomically (via "<path>.tmp"). Throws OutputError.
void write_file_atomic(const std::string& path, const std::string& text);

}  // namespace dda::io
