#pragma once
// A small CSV reader shared by the run-folder readers (series.csv, grain snapshots). Its name
// differs from the scenario reader's (scenario/csv_table.h, sg::CsvTable) on purpose: two classes
// of one qualified name break the one-definition rule (the CI's -Wodr link checks for it).
//
// The engine writes plain numeric CSV: one header row of column names, then rows of
// comma-separated fields. Lines starting with '#' are comments (room for a format-version
// line later). Every error names the file, the 1-based line and the column, because a
// user looking at a broken run folder needs exactly that to find the bad value.
#include <string>
#include <string_view>
#include <vector>

namespace sg {

struct RunCsvTable {
  std::string path;                            // for error messages
  std::vector<std::string> columns;            // header, in file order
  std::vector<std::vector<std::string>> rows;  // fields, as text
  std::vector<int> row_lines;                  // 1-based file line of each row

  // Index of a column; throws sg::Error naming the file if it is absent.
  int column_index(std::string_view name) const;
  bool has_column(std::string_view name) const;

  // Field (row, column) parsed as a finite double; throws sg::Error naming the file,
  // line and column if it is not one.
  double number(std::size_t row, int column) const;
};

// Reads the whole file. Throws sg::Error if it cannot be opened, has no header, has a
// duplicated or empty column name, or a row whose field count differs from the header.
RunCsvTable read_run_csv_table(const std::string& path);

}  // namespace sg
