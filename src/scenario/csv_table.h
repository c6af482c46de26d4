#pragma once
// A CSV data file named by a scenario (grain lists, contours, surface profiles): a header row
// of column names, then one row per record; cells are separated by commas and trimmed; blank
// lines and lines starting with '#' are skipped. Every error names the file, the line and
// the column, as the TOML errors do (toml_reader.h):
//   grains.csv:7: column 3 'diameter': expected a positive number, got '-0.2'
#include <filesystem>
#include <initializer_list>
#include <string>
#include <vector>

namespace sg {

class CsvTable {
 public:
  struct Row {
    int line = 0;                    // 1-based line in the file
    std::vector<std::string> cells;  // one per column (a missing trailing cell is "")
    std::size_t cells_given = 0;     // as written: fewer than the columns in a short row
  };

  // Reads `file` (a regular file: core/input_file.h); the header must name only `known`
  // columns, each once, and hold every column of `required`.
  CsvTable(const std::filesystem::path& file, std::initializer_list<const char*> known,
           std::initializer_list<const char*> required);

  const std::vector<Row>& rows() const { return rows_; }
  bool has_column(const std::string& name) const { return column_index(name) >= 0; }
  // Whether the row has a non-empty cell in `name` (false when the column is absent).
  bool has(const Row& row, const std::string& name) const;
  // A finite number (nan and inf are refused, naming the cell); required unless a fallback
  // is given. A missing one in a short row says how many cells the row has.
  double number(const Row& row, const std::string& name) const;
  double number(const Row& row, const std::string& name, double fallback) const;
  double positive(const Row& row, const std::string& name) const;
  std::string text(const Row& row, const std::string& name, const std::string& fallback) const;
  bool boolean(const Row& row, const std::string& name, bool fallback) const;  // 0/1/true/false
  [[noreturn]] void fail(const Row& row, const std::string& name, const std::string& message) const;
  // " (the row has 2 cells, the header 3 columns)" for a short row, else "".
  std::string short_row_note(const Row& row) const;
  const std::filesystem::path& file() const { return file_; }

 private:
  std::filesystem::path file_;
  std::vector<std::string> columns_;
  std::vector<Row> rows_;
  int column_index(const std::string& name) const;
  const std::string& cell(const Row& row, const std::string& name) const;
};

}  // namespace sg
