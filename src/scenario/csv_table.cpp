#include "scenario/csv_table.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>

#include "core/error.h"
#include "core/input_file.h"

namespace sg {

namespace {

std::string trimmed(const std::string& s) {
  const auto begin = s.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return "";
  const auto end = s.find_last_not_of(" \t\r");
  return s.substr(begin, end - begin + 1);
}

std::vector<std::string> split_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    cells.push_back(trimmed(line.substr(start, comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return cells;
}

}  // namespace

CsvTable::CsvTable(const std::filesystem::path& file, std::initializer_list<const char*> known,
                   std::initializer_list<const char*> required)
    : file_(file) {
  require_input_file(file, "CSV file");  // by type before opening (a FIFO would block)
  std::ifstream in(file);
  SG_VERIFY(in, file.string() << ": cannot open the file");
  std::string line, header;
  int number = 0, header_line = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::string t = trimmed(line);
    if (t.empty() || t[0] == '#') continue;
    if (columns_.empty()) {
      columns_ = split_cells(t);
      header = t;
      header_line = number;
      continue;
    }
    Row row{number, split_cells(t), 0};
    row.cells_given = row.cells.size();
    if (row.cells.size() > columns_.size())
      SG_THROW(file.string() << ":" << number << ": column " << columns_.size() + 1 << ": expected "
                             << columns_.size() << " cells (the header's columns), got "
                             << row.cells.size());
    row.cells.resize(columns_.size());
    rows_.push_back(std::move(row));
  }
  SG_VERIFY(!columns_.empty(), file.string() << ":1: expected a header row of column names");
  const std::set<std::string> allowed(known.begin(), known.end());
  std::set<std::string> seen;
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    std::string list;
    for (const auto& a : allowed)
      list += (list.empty() ? "" : ", ") + a;
    if (!allowed.count(columns_[c]))
      SG_THROW(file.string() << ":" << header_line << ": column " << c + 1 << " '" << columns_[c]
                             << "': unknown column (known columns: " << list << ")");
    if (!seen.insert(columns_[c]).second)
      SG_THROW(file.string() << ":" << header_line << ": column " << c + 1 << " '" << columns_[c]
                             << "': the column is given twice");
  }
  for (const char* r : required)
    SG_VERIFY(seen.count(r), file.string() << ":" << header_line << ": column '" << r
                                           << "' is required (header: " << header << ")");
  SG_VERIFY(!rows_.empty(), file.string() << ": no data rows after the header");
}

int CsvTable::column_index(const std::string& name) const {
  const auto it = std::find(columns_.begin(), columns_.end(), name);
  return it == columns_.end() ? -1 : static_cast<int>(it - columns_.begin());
}

const std::string& CsvTable::cell(const Row& row, const std::string& name) const {
  static const std::string empty;
  const int c = column_index(name);
  return c < 0 ? empty : row.cells[static_cast<std::size_t>(c)];
}

void CsvTable::fail(const Row& row, const std::string& name, const std::string& message) const {
  const int c = column_index(name);
  if (c < 0)
    SG_THROW(file_.string() << ":" << row.line << ": column '" << name << "': " << message);
  SG_THROW(file_.string() << ":" << row.line << ": column " << c + 1 << " '" << name
                          << "': " << message);
}

std::string CsvTable::short_row_note(const Row& row) const {
  if (row.cells_given >= columns_.size()) return "";
  return " (the row has " + std::to_string(row.cells_given) +
         (row.cells_given == 1 ? " cell" : " cells") + ", the header " +
         std::to_string(columns_.size()) + " columns)";
}

bool CsvTable::has(const Row& row, const std::string& name) const {
  return !cell(row, name).empty();
}

double CsvTable::number(const Row& row, const std::string& name) const {
  const std::string& s = cell(row, name);
  if (s.empty()) fail(row, name, "required number is missing" + short_row_note(row));
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (end != s.c_str() + s.size()) fail(row, name, "expected a number, got '" + s + "'");
  if (!std::isfinite(v)) fail(row, name, "expected a finite number, got '" + s + "'");
  if (std::abs(v) > kMaxInputMagnitude)
    fail(row, name, "expected a number of magnitude at most 1e+100, got '" + s + "'");
  return v;
}

double CsvTable::number(const Row& row, const std::string& name, double fallback) const {
  return has(row, name) ? number(row, name) : fallback;
}

double CsvTable::positive(const Row& row, const std::string& name) const {
  const double v = number(row, name);
  if (!(v > 0.0)) fail(row, name, "expected a positive number, got '" + cell(row, name) + "'");
  if (v < kMinInputMagnitude)
    fail(row, name, "expected a positive number of at least 1e-100, got '" + cell(row, name) + "'");
  return v;
}

std::string CsvTable::text(const Row& row, const std::string& name,
                           const std::string& fallback) const {
  return has(row, name) ? cell(row, name) : fallback;
}

bool CsvTable::boolean(const Row& row, const std::string& name, bool fallback) const {
  const std::string& s = cell(row, name);
  if (s.empty()) return fallback;
  if (s == "1" || s == "true") return true;
  if (s == "0" || s == "false") return false;
  fail(row, name, "expected 0, 1, true or false, got '" + s + "'");
}

}  // namespace sg
