#pragma once
// Editing a TOML file as text: values printed as a TOML file writes them, dotted paths
// ("materials.0.young") resolved in a parsed document, and replacements of values at their
// place in the text, so that comments and layout are kept (how `softgrain sweep` writes each
// run's scenario from the base scenario, campaign/campaign_def.h). toml++ reads; nothing here
// knows the scenario's keys.
#include <toml++/toml.h>

#include <cstddef>
#include <string>
#include <vector>

namespace sg::toml_edit {

// ---- TOML values as text

// Shortest text that reads back to the same double (std::to_chars), so that a campaign value
// 0.1 is written 0.1 and not 0.10000000000000001 as toml++'s printer does; as_toml_float adds
// ".0" to an integral value.
std::string format_double(double v, bool as_toml_float);
// toml++'s printing of a value.
std::string printed(const toml::node& n);
// The value as it is written in a TOML file.
std::string toml_text(const toml::node& n);
// The value as it appears in a run id: numbers without a forced ".0", strings unquoted.
std::string display_text(const toml::node& n);
// "a number", "an integer", "a string", ...: for messages.
std::string kind(const toml::node& n);
// A TOML basic string ("double quotes"); toml++'s printer prefers 'literal' strings.
std::string quoted(const std::string& s);

// ---- Dotted paths into a TOML document

std::vector<std::string> split_key(const std::string& key);

struct Resolved {
  const toml::node* node = nullptr;
  std::string error;  // why the key does not exist
};

// The node at a dotted key ("materials.0.young": array indices as numbers), or why there is
// none ("has no 'materials.2' ('materials' has 2 entries)").
Resolved resolve(const toml::table& root, const std::string& key);

// Sets `key` (which exists) to the value written `text`: the slow, layout-losing way, used
// only when a document's layout defeats editing its text in place.
void assign(toml::table& root, const std::string& key, const std::string& text);

// Whether `key` holds the value written `text`.
bool has_value(const toml::table& root, const std::string& key, const std::string& text);

// ---- Edits of the text

struct Edit {
  std::size_t begin = 0, end = 0;  // byte offsets in the base text, [begin, end)
  std::string text;
};

// Byte offsets of (line, column) positions, both 1-based, columns counted in code points as
// toml++ counts them.
class TextPositions {
 public:
  explicit TextPositions(const std::string& text) : text_(text) {
    line_starts_.push_back(0);
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n') line_starts_.push_back(i + 1);
  }
  std::size_t offset(std::size_t line, std::size_t column) const {
    std::size_t at = line_starts_.at(line - 1);
    for (std::size_t c = 1; c < column && at < text_.size(); ++c) {
      ++at;  // past the lead byte, then past the UTF-8 continuation bytes
      while (at < text_.size() && (static_cast<unsigned char>(text_[at]) & 0xC0) == 0x80)
        ++at;
    }
    return at;
  }
  std::size_t line_end(std::size_t line) const {
    return line < line_starts_.size() ? line_starts_[line] : text_.size();
  }
  std::size_t line_count() const { return line_starts_.size(); }

 private:
  const std::string& text_;
  std::vector<std::size_t> line_starts_;
};

// The edit that replaces node n (parsed from the text) by `text`.
Edit replace_node(const TextPositions& positions, const toml::node& n, std::string text);

// The text with the edits applied (they must not overlap; throws sg::Error if they do).
std::string apply_edits(const std::string& text, std::vector<Edit> edits);

}  // namespace sg::toml_edit
