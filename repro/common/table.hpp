// CSV files declared as column tables: each column a name and how to read
// its cell from one row, so that the header and the rows cannot drift apart.
//
//   const std::vector<repro::Column<Run>> columns = {
//       {"b_height", [](const Run& r) { return r.b_height; }},
//       {"rule", [](const Run& r) { return r.rule_name; }},   // a text cell
//   };
//   repro::write_table(dir + "/runs.csv", columns, runs, {"a comment line"});
//
// TableWriter writes rows one at a time (a series written while it runs).
// Written through repro::CsvWriter: atomic (nothing until commit), numbers in
// shortest round-trip form, a NaN or infinity refused naming its column.
#pragma once
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "repro/common/csv.hpp"

namespace repro {

// One cell: a number or a text (quoted per RFC 4180 where needed).
struct Cell {
  Cell(double v) : number(v) {}  // NOLINT: implicit on purpose, like the cells' values
  Cell(int v) : number(v) {}     // NOLINT
  Cell(long v) : number(static_cast<double>(v)) {}  // NOLINT
  Cell(std::size_t v) : number(static_cast<double>(v)) {}  // NOLINT
  Cell(bool v) : number(v ? 1.0 : 0.0) {}  // NOLINT
  Cell(std::string t) : text(std::move(t)), is_text(true) {}  // NOLINT
  Cell(const char* t) : text(t), is_text(true) {}  // NOLINT
  double number = 0.0;
  std::string text;
  bool is_text = false;
};

// A number cell where the row has the value, an empty cell where it has
// none (a stopped run's fields are no data): present ? value : "".
inline Cell cell_if(bool present, double value) { return present ? Cell(value) : Cell(""); }

template <class Row>
struct Column {
  std::string name;
  std::function<Cell(const Row&)> cell;
};

// The column of a member of the row: field("dt", &Run::dt) reads run.dt.
template <class Row, class T>
Column<Row> field(std::string name, T Row::*member) {
  return {std::move(name), [member](const Row& r) { return Cell(r.*member); }};
}

template <class Row>
std::vector<std::string> column_names(const std::vector<Column<Row>>& columns) {
  std::vector<std::string> names;
  names.reserve(columns.size());
  for (const Column<Row>& c : columns) names.push_back(c.name);
  return names;
}

template <class Row>
class TableWriter {
 public:
  // Opens "<path>.tmp" with the comment lines and the columns' names.
  TableWriter(std::string path, std::vector<Column<Row>> columns, const std::vector<std::string>& comments = {})
      : columns_(std::move(columns)), csv_(std::move(path), column_names(columns_), comments) {}

  // One row: all numbers are written as numbers; a row with a text cell is
  // written as text, its numbers in the same shortest round-trip form.
  // Throws std::invalid_argument for a NaN or infinity, naming the column.
  void row(const Row& r) {
    cells_.clear();
    bool text = false;
    for (const Column<Row>& c : columns_) {
      cells_.push_back(c.cell(r));
      text = text || cells_.back().is_text;
    }
    if (!text) {
      numbers_.clear();
      for (const Cell& c : cells_) numbers_.push_back(c.number);
      csv_.row(numbers_);
      return;
    }
    fields_.clear();
    for (std::size_t i = 0; i < cells_.size(); ++i)
      fields_.push_back(cells_[i].is_text ? cells_[i].text : csv_.number_field(cells_[i].number, i));
    csv_.row(fields_);
  }
  template <class Rows>
  void rows(const Rows& rs) {
    for (const Row& r : rs) row(r);
  }
  void commit() { csv_.commit(); }
  const std::string& path() const { return csv_.path(); }
  std::size_t row_count() const { return csv_.rows(); }

 private:
  std::vector<Column<Row>> columns_;
  CsvWriter csv_;
  std::vector<Cell> cells_;
  std::vector<double> numbers_;
  std::vector<std::string> fields_;
};

// The whole table at once: header, every row, committed.
template <class Row, class Rows>
void write_table(const std::string& path, const std::vector<Column<Row>>& columns, const Rows& rows,
                 const std::vector<std::string>& comments = {}) {
  TableWriter<Row> table(path, columns, comments);
  table.rows(rows);
  table.commit();
}

}  // namespace repro
