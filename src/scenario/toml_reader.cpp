#include "scenario/toml_reader.h"

#include <toml++/toml.h>

#include <cmath>
#include <set>
#include <sstream>

#include "core/error.h"
#include "core/input_file.h"

namespace sg {

struct ParsedToml {
  toml::table table;
};

TomlDocument::TomlDocument(const std::filesystem::path& file) : file_(file), parsed_(nullptr) {
  // By type before opening: a FIFO would block open() forever, a folder or /dev/zero would
  // parse as an empty or endless document.
  require_input_file(file, "scenario file");
  try {
    parsed_ = new ParsedToml{toml::parse_file(file.string())};
  } catch (const toml::parse_error& e) {
    SG_THROW(file.string() << ":" << e.source().begin.line << ":" << e.source().begin.column
                           << ": TOML syntax error: " << e.description());
  }
}

TomlDocument::TomlDocument(std::string_view text, const std::filesystem::path& file)
    : file_(file), parsed_(nullptr) {
  try {
    parsed_ = new ParsedToml{toml::parse(text, file.string())};
  } catch (const toml::parse_error& e) {
    SG_THROW(file.string() << ":" << e.source().begin.line << ":" << e.source().begin.column
                           << ": TOML syntax error: " << e.description());
  }
}

TomlDocument::~TomlDocument() {
  delete parsed_;
}

TomlReader TomlDocument::root() const {
  return TomlReader(parsed_->table, file_, "");
}

TomlReader::TomlReader(const toml::table& table, std::filesystem::path file, std::string prefix)
    : table_(&table), file_(std::move(file)), prefix_(std::move(prefix)) {}

std::string TomlReader::full_key(const std::string& key) const {
  return prefix_.empty() ? key : prefix_ + "." + key;
}

const toml::node* TomlReader::find(const std::string& key) const {
  return table_->get(key);
}

void TomlReader::fail(const std::string& key, const std::string& message) const {
  const toml::node* n = find(key);
  const auto line = n ? n->source().begin.line : table_->source().begin.line;
  SG_THROW(file_.string() << ":" << line << ": key '" << full_key(key) << "': " << message);
}

bool TomlReader::has(const std::string& key) const {
  return find(key) != nullptr;
}

namespace {

// TOML spells inf and nan; no scenario number may be either (a duration of inf would run no
// step, a NaN velocity would fail late naming a node instead of the key), nor beyond what the
// run's arithmetic holds (core/input_file.h, kMaxInputMagnitude).
std::string number_problem(double v) {
  std::ostringstream s;
  if (!std::isfinite(v))
    s << "expected a finite number, got " << v;
  else if (std::abs(v) > kMaxInputMagnitude)
    s << "expected a number of magnitude at most " << kMaxInputMagnitude
      << " (products of such numbers must stay finite), got " << v;
  return s.str();
}

}  // namespace

double TomlReader::as_number(const std::string& key, const toml::node& n) const {
  if (auto v = n.value<double>()) {  // integers convert too
    if (const std::string problem = number_problem(*v); !problem.empty()) fail(key, problem);
    return *v;
  }
  std::ostringstream got;
  n.visit([&](const auto& value) { got << value; });
  fail(key, "expected a number, got " + got.str());
}

double TomlReader::number(const std::string& key) const {
  const toml::node* n = find(key);
  if (!n) fail(key, "required number is missing");
  return as_number(key, *n);
}

double TomlReader::number(const std::string& key, double fallback) const {
  const toml::node* n = find(key);
  return n ? as_number(key, *n) : fallback;
}

double TomlReader::positive(const std::string& key) const {
  const double v = number(key);
  if (!(v > 0.0)) fail(key, "expected a positive number, got " + std::to_string(v));
  if (v < kMinInputMagnitude) {
    std::ostringstream s;
    s << "expected a positive number of at least " << kMinInputMagnitude
      << " (products of such numbers must stay above zero), got " << v;
    fail(key, s.str());
  }
  return v;
}

double TomlReader::positive(const std::string& key, double fallback) const {
  return has(key) ? positive(key) : fallback;
}

double TomlReader::non_negative(const std::string& key, double fallback) const {
  const double v = number(key, fallback);
  if (!(v >= 0.0)) fail(key, "expected a number >= 0, got " + std::to_string(v));
  return v;
}

long TomlReader::integer(const std::string& key, long fallback) const {
  const toml::node* n = find(key);
  if (!n) return fallback;
  if (auto v = n->value_exact<int64_t>()) return static_cast<long>(*v);
  fail(key, "expected an integer");
}

long TomlReader::integer_in(const std::string& key, long fallback, long min, long max) const {
  const long v = integer(key, fallback);
  if (v < min || v > max)
    fail(key, "expected an integer in [" + std::to_string(min) + ", " + std::to_string(max) +
                  "], got " + std::to_string(v));
  return v;
}

std::string TomlReader::string(const std::string& key) const {
  const toml::node* n = find(key);
  if (!n) fail(key, "required string is missing");
  if (auto v = n->value_exact<std::string>()) return *v;
  fail(key, "expected a string");
}

std::string TomlReader::string(const std::string& key, const std::string& fallback) const {
  return has(key) ? string(key) : fallback;
}

std::string TomlReader::one_of(const std::string& key, std::initializer_list<const char*> choices,
                               const char* fallback) const {
  return one_of(key, std::vector<std::string>(choices.begin(), choices.end()), fallback);
}

std::string TomlReader::one_of(const std::string& key, const std::vector<std::string>& choices,
                               const std::string& fallback) const {
  const std::string v = has(key) ? string(key) : fallback;
  std::string list;
  for (const std::string& c : choices) {
    if (v == c) return v;
    list += std::string(list.empty() ? "" : ", ") + "\"" + c + "\"";
  }
  fail(key, "expected one of " + list + ", got \"" + v + "\"");
}

std::pair<std::string, std::string> TomlReader::string_pair(const std::string& key) const {
  const toml::node* n = find(key);
  if (!n) fail(key, "required pair of names [\"a\", \"b\"] is missing");
  const toml::array* a = n->as_array();
  if (!a || a->size() != 2 || !(*a)[0].value_exact<std::string>() ||
      !(*a)[1].value_exact<std::string>())
    fail(key, "expected a pair of names [\"a\", \"b\"]");
  return {*(*a)[0].value_exact<std::string>(), *(*a)[1].value_exact<std::string>()};
}

Vec2 TomlReader::vec2(const std::string& key) const {
  const toml::node* n = find(key);
  if (!n) fail(key, "required pair [x, y] is missing");
  const toml::array* a = n->as_array();
  if (!a || a->size() != 2 || !(*a)[0].value<double>() || !(*a)[1].value<double>())
    fail(key, "expected a pair of numbers [x, y]");
  const Vec2 v(*(*a)[0].value<double>(), *(*a)[1].value<double>());
  for (double c : {v.x(), v.y()})
    if (const std::string problem = number_problem(c); !problem.empty())
      fail(key, "[x, y]: " + problem);
  return v;
}

Vec2 TomlReader::vec2(const std::string& key, const Vec2& fallback) const {
  return has(key) ? vec2(key) : fallback;
}

bool TomlReader::boolean(const std::string& key, bool fallback) const {
  const toml::node* n = find(key);
  if (!n) return fallback;
  if (auto v = n->value_exact<bool>()) return *v;
  fail(key, "expected true or false");
}

std::vector<Vec2> TomlReader::pairs(const std::string& key, std::size_t min_count) const {
  const toml::node* n = find(key);
  const std::string expected =
      "expected a list of pairs [[a, b], ...] (at least " + std::to_string(min_count) + ")";
  if (!n) fail(key, "required " + expected.substr(9) + " is missing");
  const toml::array* a = n->as_array();
  if (!a || a->size() < min_count) fail(key, expected);
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::array* p = (*a)[i].as_array();
    if (!p || p->size() != 2 || !(*p)[0].value<double>() || !(*p)[1].value<double>())
      fail(key, expected + "; entry " + std::to_string(i + 1) + " is not a pair of numbers");
    out.emplace_back(*(*p)[0].value<double>(), *(*p)[1].value<double>());
    for (double c : {out.back().x(), out.back().y()})
      if (const std::string problem = number_problem(c); !problem.empty())
        fail(key, "entry " + std::to_string(i + 1) + ": " + problem);
  }
  return out;
}

std::filesystem::path TomlReader::file_path(const std::string& key) const {
  const std::filesystem::path name = string(key);
  const std::filesystem::path path = name.is_absolute() ? name : file_.parent_path() / name;
  // By type before anything opens it (core/input_file.h).
  const std::string problem = input_file_problem(path);
  if (!problem.empty()) fail(key, "file " + shown_path(path) + " " + problem);
  return path;
}

bool TomlReader::is_table(const std::string& key) const {
  const toml::node* n = find(key);
  return n && n->is_table();
}

bool TomlReader::is_array(const std::string& key) const {
  const toml::node* n = find(key);
  return n && n->is_array();
}

std::optional<TomlReader> TomlReader::table(const std::string& key) const {
  const toml::node* n = find(key);
  if (!n) return std::nullopt;
  const toml::table* t = n->as_table();
  if (!t) fail(key, "expected a table [" + full_key(key) + "]");
  return TomlReader(*t, file_, full_key(key));
}

std::vector<TomlReader> TomlReader::array_of_tables(const std::string& key) const {
  std::vector<TomlReader> out;
  const toml::node* n = find(key);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a) fail(key, "expected an array of tables [[" + full_key(key) + "]]");
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::table* t = (*a)[i].as_table();
    if (!t) fail(key, "expected an array of tables [[" + full_key(key) + "]]");
    out.emplace_back(*t, file_, full_key(key) + "[" + std::to_string(i) + "]");
  }
  return out;
}

void TomlReader::reject_unknown_keys(std::initializer_list<const char*> known) const {
  reject_unknown_keys(std::vector<std::string>(known.begin(), known.end()));
}

void TomlReader::reject_unknown_keys(const std::vector<std::string>& known) const {
  const std::set<std::string> allowed(known.begin(), known.end());
  for (const auto& [k, v] : *table_) {
    const std::string key(k.str());
    if (!allowed.count(key)) {
      std::string list;
      for (const auto& a : allowed)
        list += (list.empty() ? "" : ", ") + a;
      fail(key, "unknown key (known keys here: " + list + ")");
    }
  }
}

}  // namespace sg
