#include "campaign/toml_text_edit.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>

#include "core/error.h"

namespace sg::toml_edit {
namespace {

bool is_bare_key(std::string_view k) {
  return !k.empty() && std::all_of(k.begin(), k.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
  });
}

}  // namespace

// Shortest text that reads back to the same double (std::to_chars), so that a campaign value
// 0.1 is written 0.1 and not 0.10000000000000001 as toml++'s printer does.
std::string format_double(double v, bool as_toml_float) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, v);
  std::string s(buffer, result.ptr);
  if (as_toml_float && s.find_first_of(".e") == std::string::npos) s += ".0";
  return s;
}

std::string printed(const toml::node& n) {
  std::ostringstream s;
  n.visit([&](const auto& v) { s << v; });
  return s.str();
}

// The value as it is written in a TOML file.
std::string toml_text(const toml::node& n) {
  if (const auto* v = n.as_floating_point()) return format_double(v->get(), true);
  if (const auto* v = n.as_integer()) return std::to_string(v->get());
  if (const auto* v = n.as_boolean()) return v->get() ? "true" : "false";
  if (const auto* a = n.as_array()) {
    std::string s = "[";
    for (std::size_t i = 0; i < a->size(); ++i)
      s += (i ? ", " : "") + toml_text(*a->get(i));
    return s + "]";
  }
  if (const auto* t = n.as_table()) {
    std::string s = "{";
    bool first = true;
    for (const auto& [k, v] : *t) {
      const std::string key =
          is_bare_key(k.str()) ? std::string(k.str()) : printed(toml::value<std::string>(k.str()));
      s += std::string(first ? " " : ", ") + key + " = " + toml_text(v);
      first = false;
    }
    return s + " }";
  }
  return printed(n);  // strings (quoted and escaped by toml++), dates, times
}

// The value as it appears in a run id: numbers without a forced ".0", strings unquoted.
std::string display_text(const toml::node& n) {
  if (const auto* v = n.as_floating_point()) return format_double(v->get(), false);
  if (const auto* v = n.as_string()) return v->get();
  if (const auto* a = n.as_array()) {
    std::string s;
    for (std::size_t i = 0; i < a->size(); ++i)
      s += (i ? "," : "") + display_text(*a->get(i));
    return s;
  }
  return toml_text(n);
}

std::string kind(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::floating_point:
      return "a number";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::table:
      return "a table";
    default:
      return "a date or time";
  }
}

std::vector<std::string> split_key(const std::string& key) {
  std::vector<std::string> parts;
  std::string part;
  std::istringstream s(key);
  while (std::getline(s, part, '.'))
    parts.push_back(part);
  if (!key.empty() && key.back() == '.') parts.emplace_back();
  return parts;
}

Resolved resolve(const toml::table& root, const std::string& key) {
  const toml::node* node = &root;
  std::string walked;
  for (const std::string& part : split_key(key)) {
    if (part.empty()) return {nullptr, "is not a valid dotted key (empty component)"};
    const std::string here = walked.empty() ? part : walked + "." + part;
    if (const auto* t = node->as_table()) {
      node = t->get(part);
      if (!node) return {nullptr, "has no '" + here + "'"};
    } else if (const auto* a = node->as_array()) {
      if (!std::all_of(part.begin(), part.end(), [](char c) { return c >= '0' && c <= '9'; }))
        return {nullptr, "has an array at '" + walked + "': expected an index 0.." +
                             std::to_string(a->size()) + " after it, got '" + part + "'"};
      const std::size_t index = std::stoul(part);
      if (index >= a->size())
        return {nullptr, "has no '" + here + "' ('" + walked + "' has " +
                             std::to_string(a->size()) + " entries)"};
      node = a->get(index);
    } else {
      return {nullptr, "has " + kind(*node) + " at '" + walked + "', not a table or an array"};
    }
    walked = here;
  }
  return {node, ""};
}

// Sets `key` (which exists) to the value written `text`: the slow, layout-losing way, used
// only when the base scenario's layout defeats in-place editing (see patch_scenario).
void assign(toml::table& root, const std::string& key, const std::string& text) {
  toml::table parsed = toml::parse("v = " + text);
  const std::vector<std::string> parts = split_key(key);
  std::string parent_key;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i)
    parent_key += (i ? "." : "") + parts[i];
  toml::node* parent =
      parent_key.empty() ? &root : const_cast<toml::node*>(resolve(root, parent_key).node);
  SG_ASSERT(parent, "key '" << key << "' was resolved before");
  parsed.get("v")->visit([&](const auto& value) {
    if (auto* t = parent->as_table())
      t->insert_or_assign(parts.back(), value);
    else if (auto* a = parent->as_array())
      a->replace(a->cbegin() + static_cast<std::ptrdiff_t>(std::stoul(parts.back())), value);
  });
}

Edit replace_node(const TextPositions& positions, const toml::node& n, std::string text) {
  const auto& s = n.source();
  return {positions.offset(s.begin.line, s.begin.column),
          positions.offset(s.end.line, s.end.column), std::move(text)};
}

std::string apply_edits(const std::string& text, std::vector<Edit> edits) {
  std::sort(edits.begin(), edits.end(),
            [](const Edit& a, const Edit& b) { return a.begin > b.begin; });
  std::string out = text;
  std::size_t limit = text.size();
  for (const Edit& e : edits) {
    SG_VERIFY(e.end <= limit, "two varied keys overlap in the base scenario text");
    out.replace(e.begin, e.end - e.begin, e.text);
    limit = e.begin;
  }
  return out;
}

bool has_value(const toml::table& root, const std::string& key, const std::string& text) {
  const Resolved r = resolve(root, key);
  return r.node && toml_text(*r.node) == text;
}

// A TOML basic string; toml++'s printer prefers 'literal' strings, which would stand out in a
// scenario file written with "double quotes".
std::string quoted(const std::string& s) {
  const bool plain = std::all_of(s.begin(), s.end(), [](char c) {
    return c != '"' && c != '\\' && static_cast<unsigned char>(c) >= 0x20;
  });
  return plain ? "\"" + s + "\"" : printed(toml::value<std::string>(s));
}

}  // namespace sg::toml_edit
