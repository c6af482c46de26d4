#include "analysis/run_csv_table.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <system_error>

#include "core/error.h"

namespace sg {
namespace {

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t\r");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t\r");
  return s.substr(first, last - first + 1);
}

std::vector<std::string> split_fields(std::string_view line) {
  std::vector<std::string> fields;
  std::size_t start = 0;
  while (true) {
    const auto comma = line.find(',', start);
    const auto end = comma == std::string_view::npos ? line.size() : comma;
    fields.emplace_back(trim(line.substr(start, end - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return fields;
}

}  // namespace

int RunCsvTable::column_index(std::string_view name) const {
  for (std::size_t c = 0; c < columns.size(); ++c)
    if (columns[c] == name) return static_cast<int>(c);
  SG_THROW(path << ": missing column '" << name << "'");
}

bool RunCsvTable::has_column(std::string_view name) const {
  for (const auto& c : columns)
    if (c == name) return true;
  return false;
}

double RunCsvTable::number(std::size_t row, int column) const {
  const std::string& text = rows[row][static_cast<std::size_t>(column)];
  double value = 0.0;
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  // from_chars does not accept a leading '+'; the C++ and Python writers never emit one,
  // but a hand-edited file might, so skip it.
  if (begin != end && *begin == '+') ++begin;
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  SG_VERIFY(ec == std::errc() && ptr == end && begin != end,
            path << ":" << row_lines[row] << ": column '" << columns[column] << "': cannot parse '"
                 << text << "' as a number");
  // A NaN or infinity means the run diverged or the writer is broken; averaging it would
  // silently poison every result, so refuse it where the user can see it.
  SG_VERIFY(std::isfinite(value), path << ":" << row_lines[row] << ": column '" << columns[column]
                                       << "': non-finite value '" << text << "'");
  return value;
}

RunCsvTable read_run_csv_table(const std::string& path) {
  std::ifstream in(path);
  SG_VERIFY(in, path << ": cannot open for reading");
  RunCsvTable table;
  table.path = path;
  std::string line;
  int line_number = 0;
  bool have_header = false;
  while (std::getline(in, line)) {
    ++line_number;
    const std::string_view content = trim(line);
    if (content.empty() || content.front() == '#') continue;
    std::vector<std::string> fields = split_fields(content);
    if (!have_header) {
      for (std::size_t c = 0; c < fields.size(); ++c) {
        SG_VERIFY(!fields[c].empty(),
                  path << ":" << line_number << ": empty column name at position " << c + 1);
        for (std::size_t d = 0; d < c; ++d)
          SG_VERIFY(fields[d] != fields[c],
                    path << ":" << line_number << ": duplicated column '" << fields[c] << "'");
      }
      table.columns = std::move(fields);
      have_header = true;
      continue;
    }
    SG_VERIFY(fields.size() == table.columns.size(), path << ":" << line_number << ": "
                                                          << fields.size() << " fields, header has "
                                                          << table.columns.size());
    table.rows.push_back(std::move(fields));
    table.row_lines.push_back(line_number);
  }
  SG_VERIFY(have_header, path << ": empty file (no header row)");
  return table;
}

}  // namespace sg
