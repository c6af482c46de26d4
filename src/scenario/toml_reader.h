#pragma once
// Typed, checked access to a TOML table, for scenario files. Every error names the file,
// the line, the full key and what was expected:
//   shear.toml:12: key 'materials[1].poisson': expected a number in (-1, 0.5), got 0.5
// Unknown keys are errors too (a typo must not silently fall back to a default).
#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "geometry/vec2.h"

namespace toml {
inline namespace v3 {
class table;
class node;
}  // namespace v3
}  // namespace toml

namespace sg {

class TomlReader {
 public:
  TomlReader(const toml::table& table, std::filesystem::path file, std::string prefix);

  double number(const std::string& key) const;  // required
  double number(const std::string& key, double fallback) const;
  // Required/optional number with a check: `ok` tells whether the value is acceptable and
  // `expected` describes it ("a positive number").
  double positive(const std::string& key) const;
  double positive(const std::string& key, double fallback) const;
  double non_negative(const std::string& key, double fallback) const;
  long integer(const std::string& key, long fallback) const;
  // An integer in [min, max] (a count: a grain count of 1e11 overflowed an int and ended in
  // bad_alloc or a hang).
  long integer_in(const std::string& key, long fallback, long min, long max) const;
  std::string string(const std::string& key) const;
  std::string string(const std::string& key, const std::string& fallback) const;
  std::string one_of(const std::string& key, std::initializer_list<const char*> choices,
                     const char* fallback) const;
  std::string one_of(const std::string& key, const std::vector<std::string>& choices,
                     const std::string& fallback) const;
  // One of `values` (an enum's list of every value), by the name to_string gives it: the
  // enum's one table of names serves both the reader and the writers (run.log).
  template <class Enum, std::size_t N>
  Enum named_value(const std::string& key, const Enum (&values)[N], Enum fallback) const {
    std::vector<std::string> names;
    for (const Enum v : values)
      names.emplace_back(to_string(v));
    const std::string name = one_of(key, names, to_string(fallback));
    for (const Enum v : values)
      if (name == to_string(v)) return v;
    return fallback;  // not reached: one_of refused any other name
  }
  // A required pair of strings ["a", "b"].
  std::pair<std::string, std::string> string_pair(const std::string& key) const;
  Vec2 vec2(const std::string& key) const;
  Vec2 vec2(const std::string& key, const Vec2& fallback) const;
  bool boolean(const std::string& key, bool fallback) const;
  // A required list of pairs [[a, b], ...] (points, (t, v) tables), at least `min_count`.
  std::vector<Vec2> pairs(const std::string& key, std::size_t min_count) const;
  // A required file name, relative to the scenario file's folder (or absolute); the file
  // must exist.
  std::filesystem::path file_path(const std::string& key) const;
  bool has(const std::string& key) const;
  bool is_table(const std::string& key) const;
  bool is_array(const std::string& key) const;

  std::optional<TomlReader> table(const std::string& key) const;
  std::vector<TomlReader> array_of_tables(const std::string& key) const;

  // Throws if the table holds a key not in `known`.
  void reject_unknown_keys(std::initializer_list<const char*> known) const;
  void reject_unknown_keys(const std::vector<std::string>& known) const;

  [[noreturn]] void fail(const std::string& key, const std::string& message) const;
  const std::filesystem::path& file() const { return file_; }

 private:
  const toml::table* table_;
  std::filesystem::path file_;
  std::string prefix_;
  std::string full_key(const std::string& key) const;
  const toml::node* find(const std::string& key) const;
  double as_number(const std::string& key, const toml::node& n) const;
};

// Parses a TOML file; syntax errors are reported as file:line:column: message.
struct ParsedToml;
class TomlDocument {
 public:
  explicit TomlDocument(const std::filesystem::path& file);
  // The TOML text `text`, named `file` in messages (relative file keys resolve against its
  // folder): a scenario built in memory (the Python module's Scenario.from_dict).
  TomlDocument(std::string_view text, const std::filesystem::path& file);
  ~TomlDocument();
  TomlDocument(const TomlDocument&) = delete;
  TomlDocument& operator=(const TomlDocument&) = delete;
  TomlReader root() const;

 private:
  std::filesystem::path file_;
  ParsedToml* parsed_;
};

}  // namespace sg
