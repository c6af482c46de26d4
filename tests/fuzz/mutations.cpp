#include "fuzz/mutations.h"

#include <cctype>
#include <sstream>

namespace sg::fuzz {

namespace {

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

std::string join_lines(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& l : lines)
    text += l + "\n";
  return text;
}

std::string trimmed(const std::string& s) {
  const auto b = s.find_first_not_of(" \t");
  return b == std::string::npos ? "" : s.substr(b);
}

bool is_header(const std::string& line) {
  return trimmed(line).rfind('[', 0) == 0;
}

// The '=' of a "key = value" line, or npos.
std::size_t key_end(const std::string& line) {
  const std::string t = trimmed(line);
  if (t.empty() || t[0] == '#' || t[0] == '[') return std::string::npos;
  const std::size_t eq = line.find('=');
  if (eq == std::string::npos) return eq;
  for (std::size_t i = 0; i < eq; ++i)
    if (line[i] == '"' || line[i] == '#') return std::string::npos;
  return eq;
}

// A value token of a key line: [begin, end) in the line and its kind.
struct Token {
  std::size_t begin, end;
  char kind;  // 'n' number, 's' string, 'b' boolean
};

bool number_char(char c) {
  return std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == 'e' || c == 'E' ||
         c == '_' || c == '+' || c == '-';
}

std::vector<Token> value_tokens(const std::string& line, std::size_t from) {
  std::vector<Token> tokens;
  std::size_t i = from;
  while (i < line.size()) {
    const char c = line[i];
    if (c == '#') break;
    if (c == '"') {
      const std::size_t close = line.find('"', i + 1);
      if (close == std::string::npos) break;
      tokens.push_back({i, close + 1, 's'});
      i = close + 1;
    } else if (std::isdigit(static_cast<unsigned char>(c)) ||
               ((c == '-' || c == '+' || c == '.') && i + 1 < line.size() &&
                std::isdigit(static_cast<unsigned char>(line[i + 1])))) {
      std::size_t j = i + 1;
      while (j < line.size() && number_char(line[j]))
        ++j;
      tokens.push_back({i, j, 'n'});
      i = j;
    } else if (line.compare(i, 4, "true") == 0 || line.compare(i, 5, "false") == 0) {
      const std::size_t j = i + (line[i] == 't' ? 4 : 5);
      tokens.push_back({i, j, 'b'});
      i = j;
    } else {
      ++i;
    }
  }
  return tokens;
}

}  // namespace

std::vector<Mutation> mutations_of(const std::string& text, const std::string& absolute_escape) {
  const std::vector<std::string> lines = split_lines(text);
  std::vector<Mutation> out;
  auto with_line = [&](std::size_t k, const std::vector<std::string>& replacement) {
    std::vector<std::string> l(lines.begin(), lines.begin() + static_cast<long>(k));
    l.insert(l.end(), replacement.begin(), replacement.end());
    l.insert(l.end(), lines.begin() + static_cast<long>(k) + 1, lines.end());
    return join_lines(l);
  };
  const std::vector<std::string> number_values = {"0", "-1", "1e300", "nan", "\"x\""};
  const std::vector<std::string> string_values = {"\"\"", "\"../escape\"",
                                                  "\"" + absolute_escape + "\""};
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const std::string& line = lines[k];
    const std::string where = "line " + std::to_string(k + 1) + ": ";
    const std::size_t eq = key_end(line);
    if (eq == std::string::npos) continue;
    for (const Token& t : value_tokens(line, eq + 1)) {
      const std::string old = line.substr(t.begin, t.end - t.begin);
      const std::vector<std::string>& values = t.kind == 'n'   ? number_values
                                               : t.kind == 's' ? string_values
                                                               : std::vector<std::string>{"1"};
      for (const std::string& v : values)
        out.push_back({where + old + " -> " + v,
                       with_line(k, {line.substr(0, t.begin) + v + line.substr(t.end)})});
    }
    const std::string key = trimmed(line.substr(0, eq));
    out.push_back({where + "key dropped", with_line(k, {})});
    out.push_back({where + "key duplicated", with_line(k, {line, line})});
    const std::size_t key_at = line.find_first_not_of(" \t");
    std::string misspelled = line;
    misspelled.insert(
        key_at +
            (key.find_first_of(" \t") == std::string::npos ? key.size() : key.find_first_of(" \t")),
        "x");
    out.push_back({where + "key misspelled", with_line(k, {misspelled})});
  }
  for (std::size_t k = 0; k < lines.size(); ++k) {
    if (!is_header(lines[k])) continue;
    std::vector<std::string> l(lines.begin(), lines.begin() + static_cast<long>(k) + 1);
    std::size_t next = k + 1;
    while (next < lines.size() && !is_header(lines[next]))
      ++next;
    l.insert(l.end(), lines.begin() + static_cast<long>(next), lines.end());
    out.push_back({"line " + std::to_string(k + 1) + ": table " + trimmed(lines[k]) + " emptied",
                   join_lines(l)});
  }
  constexpr int kTruncations = 8;
  for (int c = 1; c <= kTruncations; ++c) {
    const std::size_t at = text.size() * static_cast<std::size_t>(c) / (kTruncations + 1);
    out.push_back({"truncated at byte " + std::to_string(at), text.substr(0, at)});
  }
  return out;
}

std::vector<Mutation> csv_mutations_of(const std::string& text) {
  const std::vector<std::string> lines = split_lines(text);
  std::vector<Mutation> out;
  auto with_line = [&](std::size_t k, const std::vector<std::string>& replacement) {
    std::vector<std::string> l(lines.begin(), lines.begin() + static_cast<long>(k));
    l.insert(l.end(), replacement.begin(), replacement.end());
    l.insert(l.end(), lines.begin() + static_cast<long>(k) + 1, lines.end());
    return join_lines(l);
  };
  auto cells_of = [](const std::string& line) {
    std::vector<std::string> cells(1);
    for (char c : line)
      if (c == ',')
        cells.emplace_back();
      else
        cells.back() += c;
    return cells;
  };
  auto joined = [](const std::vector<std::string>& cells) {
    std::string line;
    for (std::size_t i = 0; i < cells.size(); ++i)
      line += (i ? "," : "") + cells[i];
    return line;
  };
  const std::vector<std::string> cell_values = {"-0.2", "0", "nan", "inf", "1e400", "abc", ""};
  // The header and the first three data rows (comments and blank lines are not rows): every
  // row has the same columns, so later rows add nothing but time.
  int rows = 0;
  for (std::size_t k = 0; k < lines.size() && rows < 4; ++k) {
    const std::string t = trimmed(lines[k]);
    if (t.empty() || t[0] == '#') continue;
    ++rows;
    const std::string where = "csv line " + std::to_string(k + 1) + ": ";
    const std::vector<std::string> cells = cells_of(lines[k]);
    for (std::size_t c = 0; c < cells.size(); ++c)
      for (const std::string& v : cell_values) {
        std::vector<std::string> changed = cells;
        changed[c] = v;
        out.push_back({where + "cell " + std::to_string(c + 1) + " '" + trimmed(cells[c]) +
                           "' -> '" + v + "'",
                       with_line(k, {joined(changed)})});
      }
    std::vector<std::string> shorter(cells.begin(), cells.end() - 1);
    out.push_back({where + "last cell dropped", with_line(k, {joined(shorter)})});
    out.push_back({where + "a cell too many", with_line(k, {lines[k] + ",1"})});
    out.push_back({where + "row doubled", with_line(k, {lines[k], lines[k]})});
    out.push_back({where + "row blanked",
                   with_line(k, {std::string(cells.size() > 0 ? cells.size() - 1 : 0, ',')})});
    if (rows == 1) out.push_back({where + "header dropped", with_line(k, {})});
  }
  out.push_back({"csv emptied", ""});
  constexpr int kTruncations = 4;
  for (int c = 1; c <= kTruncations; ++c) {
    const std::size_t at = text.size() * static_cast<std::size_t>(c) / (kTruncations + 1);
    out.push_back({"csv truncated at byte " + std::to_string(at), text.substr(0, at)});
  }
  return out;
}

}  // namespace sg::fuzz
