#include "campaign/campaign_def.h"

#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>

#include "campaign/paper_coordinates.h"
#include "campaign/slurm_settings_reader.h"
#include "campaign/toml_text_edit.h"
#include "core/error.h"
#include "core/file_name.h"
#include "core/input_file.h"

namespace sg {
namespace {

namespace fs = std::filesystem;
using namespace toml_edit;  // NOLINT: the campaign reader is written in its vocabulary

// Run ids are folder names and appear in shell commands: keep them to a safe alphabet.
std::string file_safe(std::string s) {
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c)) &&
        std::string_view("._+-,").find(c) == std::string_view::npos)
      c = '-';
  return s;
}

// ---------------------------------------------------------------------------------------
// Errors: "<file>:<line>: key '<key>'<where>: <message>"

[[noreturn]] void fail(const fs::path& file, std::size_t line, const std::string& key,
                       const std::string& where, const std::string& message) {
  SG_THROW(file.string() << ":" << line << ": key '" << key << "'" << where << ": " << message);
}

std::size_t line_of(const toml::node& n) {
  return n.source().begin.line;
}

// The text of `replacement` to put where the base scenario has `base`, after checking that
// the types agree (an integer is accepted for a number, and written as one).
std::string replacement_text(const toml::node& base, const toml::node& replacement,
                             const std::function<void(const std::string&)>& error) {
  if (replacement.is_table()) error("a table cannot be a value; vary its keys one by one");
  if (base.is_floating_point() && replacement.is_integer())
    return format_double(static_cast<double>(replacement.as_integer()->get()), true);
  if (base.type() != replacement.type())
    error("expected " + kind(base) + " like the base scenario's " + toml_text(base) + ", got " +
          toml_text(replacement));
  return toml_text(replacement);
}

// ---------------------------------------------------------------------------------------
// Writing a run's scenario

struct ScenarioBase {
  fs::path file;
  std::string text;
  toml::table table;
  // As the campaign names it: the run's text must not depend on the working directory (a
  // resumed campaign compares it with the run folder's scenario.toml).
  std::string as_written;
};

// The (key, TOML text) pairs a run sets in the scenario: its varied keys, and for varied
// paper coordinates the physical keys they set (campaign/paper_coordinates.h).
std::vector<std::pair<std::string, std::string>> scenario_values(const CampaignDef& campaign,
                                                                 const CampaignRun& run) {
  std::vector<std::pair<std::string, std::string>> out;
  for (std::size_t p = 0; p < campaign.parameters.size(); ++p)
    if (!campaign.parameters[p].paper_coordinate)
      out.emplace_back(campaign.parameters[p].key, run.values[p]);
  out.insert(out.end(), run.derived.begin(), run.derived.end());
  return out;
}

// The base scenario with the run's values, name and output folder. Edits the text in place
// (comments and layout kept); if the result does not read back with exactly the intended
// values (an unusual layout, e.g. an inline [output] table without `directory`), the table
// is rebuilt and printed by toml++ instead.
std::string patch_scenario(const ScenarioBase& base, const CampaignDef& campaign,
                           const CampaignRun& run) {
  const TextPositions positions(base.text);
  std::vector<Edit> edits;
  bool layout_ok = true;
  const auto values = scenario_values(campaign, run);
  for (const auto& [key, text] : values)
    edits.push_back(replace_node(positions, *resolve(base.table, key).node, text));
  if (const toml::node* name = base.table.get("name")) {
    edits.push_back(replace_node(positions, *name, quoted(run.id)));
  } else {
    // Before the first line that is not blank or a comment: still the root table.
    std::size_t line = 1;
    for (; line < positions.line_count(); ++line) {
      const std::size_t a = positions.offset(line, 1), b = positions.line_end(line);
      const std::string l = base.text.substr(a, b - a);
      const auto first = l.find_first_not_of(" \t\r\n");
      if (first != std::string::npos && l[first] != '#') break;
    }
    const std::size_t at = positions.offset(line, 1);
    edits.push_back({at, at, "name = " + quoted(run.id) + "\n"});
  }
  const std::string runs = quoted(kCampaignRunsFolder);
  if (const toml::node* output = base.table.get("output")) {
    const toml::table* t = output->as_table();
    if (t && t->get("directory")) {
      edits.push_back(replace_node(positions, *t->get("directory"), runs));
    } else if (t && !t->is_inline()) {
      const std::size_t at = positions.line_end(t->source().begin.line);
      edits.push_back({at, at, "directory = " + runs + "\n"});
    } else {
      layout_ok = false;
    }
  } else {
    const bool newline = base.text.empty() || base.text.back() == '\n';
    edits.push_back({base.text.size(), base.text.size(),
                     std::string(newline ? "" : "\n") + "\n[output]\ndirectory = " + runs + "\n"});
  }

  std::ostringstream header;
  header << "# Run " << run.id << " of campaign '" << campaign.name << "' ("
         << campaign.file.filename().string() << "), written by softgrain sweep: the base\n# "
         << "scenario " << base.as_written << " with";
  for (std::size_t p = 0; p < campaign.parameters.size(); ++p)
    header << (p ? ", " : " ") << campaign.parameters[p].key << " = " << run.values[p];
  for (const auto& [key, text] : run.derived)
    header << ",\n#   so " << key << " = " << text;
  header << ".\n";

  const auto reads_back = [&](const std::string& text) {
    try {
      const toml::table t = toml::parse(text);
      for (const auto& [key, value] : values)
        if (!has_value(t, key, value)) return false;
      const auto output = t["output"]["directory"].value<std::string>();
      return t["name"].value<std::string>() == run.id && output == kCampaignRunsFolder;
    } catch (const toml::parse_error&) {
      return false;
    }
  };
  if (layout_ok) {
    std::string text = header.str() + apply_edits(base.text, edits);
    if (reads_back(text)) return text;
  }
  toml::table table = base.table;
  for (const auto& [key, text] : values)
    assign(table, key, text);
  table.insert_or_assign("name", run.id);
  if (!table.get("output") || !table.get("output")->is_table())
    table.insert_or_assign("output", toml::table{});
  table.get("output")->as_table()->insert_or_assign("directory", kCampaignRunsFolder);
  std::ostringstream text;
  text << header.str() << "# (printed from the parsed base scenario: its layout is not kept)\n"
       << toml::toml_formatter{table};
  SG_VERIFY(reads_back(text.str()), "internal: could not write the scenario of run " << run.id);
  return text.str();
}

// ---------------------------------------------------------------------------------------
// Reading the campaign file

// A table's leaves with their dotted keys, in file order ("a.b" = 1 and [a] b = 1 alike).
struct Leaf {
  std::string key;
  const toml::node* node = nullptr;
};

void collect_leaves(const toml::table& t, const std::string& prefix, std::vector<Leaf>& out) {
  for (const auto& [k, v] : t) {
    const std::string key =
        prefix.empty() ? std::string(k.str()) : prefix + "." + std::string(k.str());
    if (const auto* sub = v.as_table())
      collect_leaves(*sub, key, out);
    else
      out.push_back({key, &v});
  }
}

std::vector<Leaf> leaves(const toml::table& t) {
  std::vector<Leaf> out;
  collect_leaves(t, "", out);
  std::sort(out.begin(), out.end(), [](const Leaf& a, const Leaf& b) {
    const auto &pa = a.node->source().begin, &pb = b.node->source().begin;
    return pa.line != pb.line ? pa.line < pb.line : pa.column < pb.column;
  });
  return out;
}

// The shortest tails of the keys ("young", "0.young") that tell the parameters apart.
void assign_labels(std::vector<CampaignParameter>& parameters) {
  std::vector<std::vector<std::string>> parts;
  std::vector<std::size_t> taken(parameters.size(), 1);
  for (const auto& p : parameters)
    parts.push_back(split_key(p.key));
  const auto label = [&](std::size_t i) {
    std::string s;
    const std::size_t n = std::min(taken[i], parts[i].size());
    for (std::size_t j = parts[i].size() - n; j < parts[i].size(); ++j)
      s += (s.empty() ? "" : ".") + parts[i][j];
    return s;
  };
  for (bool changed = true; changed;) {
    changed = false;
    std::map<std::string, int> uses;
    for (std::size_t i = 0; i < parameters.size(); ++i)
      ++uses[label(i)];
    for (std::size_t i = 0; i < parameters.size(); ++i)
      if (uses[label(i)] > 1 && taken[i] < parts[i].size()) {
        ++taken[i];
        changed = true;
      }
  }
  for (std::size_t i = 0; i < parameters.size(); ++i)
    parameters[i].label = file_safe(label(i));
}

std::string string_value(const fs::path& file, const toml::table& doc, const char* key,
                         const std::string& fallback) {
  const toml::node* n = doc.get(key);
  if (!n) return fallback;
  if (const auto* s = n->as_string()) return s->get();
  fail(file, line_of(*n), key, "", "expected a string, got " + toml_text(*n));
}

long integer_value(const fs::path& file, const toml::table& doc, const char* key, long fallback,
                   long minimum) {
  const toml::node* n = doc.get(key);
  if (!n) return fallback;
  const auto* v = n->as_integer();
  if (!v || v->get() < minimum)
    fail(file, line_of(*n), key, "",
         "expected an integer >= " + std::to_string(minimum) + ", got " + toml_text(*n));
  return static_cast<long>(v->get());
}

// One varied parameter as read from the campaign: its key, where, and its values.
struct Varied {
  std::string key;
  std::string where;  // " in [grid]" or " in [[list]]"
  std::size_t line = 0;
  std::vector<const toml::node*> values;
};

// The campaign's own settings: name, base scenario, output, parallel, threads, analyze_options.
void read_settings(const fs::path& file, const toml::table& doc, CampaignDef& c) {
  static const std::set<std::string> known = {"name",     "scenario", "output",
                                              "parallel", "threads",  "analyze_options",
                                              "grid",     "list",     "slurm"};
  for (const auto& [k, v] : doc)
    if (!known.count(std::string(k.str())))
      fail(file, line_of(v), std::string(k.str()), "",
           "unknown key; expected name, scenario, output, parallel, threads, analyze_options, "
           "[grid], [[list]] or [slurm]");

  c.name = string_value(file, doc, "name", file.stem().string());
  if (!is_plain_file_name(c.name) || file_safe(c.name) != c.name || c.name[0] == '.')
    fail(file, doc.get("name") ? line_of(*doc.get("name")) : 1, "name", "",
         "expected a folder name (letters, digits, '.', '_', '+', '-', ','), got \"" + c.name +
             "\"");
  const std::string scenario = string_value(file, doc, "scenario", "");
  if (scenario.empty()) fail(file, 1, "scenario", "", "required: the base scenario file");
  c.scenario =
      fs::path(scenario).is_absolute() ? fs::path(scenario) : file.parent_path() / scenario;
  if (const std::string problem = input_file_problem(c.scenario); !problem.empty())
    fail(file, line_of(*doc.get("scenario")), "scenario", "",
         "the base scenario " + shown_path(c.scenario) + " " + problem);
  // Relative to the campaign file, like `scenario`: the campaign folder must not depend on
  // where the command is typed, or a resumed or gathered campaign would start a new one.
  const fs::path output = string_value(file, doc, "output", c.output_root.string());
  c.output_root = output.is_absolute() ? output : file.parent_path() / output;
  c.parallel = static_cast<int>(integer_value(file, doc, "parallel", 1, 1));
  c.threads = static_cast<int>(integer_value(file, doc, "threads", 0, 0));
  if (const toml::node* n = doc.get("analyze_options")) {
    const auto* a = n->as_array();
    if (!a) fail(file, line_of(*n), "analyze_options", "", "expected an array of strings");
    c.analyze_options_line = line_of(*n);
    for (const auto& e : *a) {
      if (!e.is_string())
        fail(file, line_of(e), "analyze_options", "",
             "expected an array of strings, got " + toml_text(e));
      c.analyze_options.push_back(e.as_string()->get());
    }
  }
  c.slurm = read_slurm_settings(file, doc);
}

// The [[list]] keys in file order, each with its value per entry; the number of entries.
std::vector<Varied> read_list(const fs::path& file, const toml::table& doc,
                              std::size_t& list_runs) {
  std::vector<Varied> varied;
  list_runs = 1;
  if (const toml::node* n = doc.get("list")) {
    const auto* a = n->as_array();
    if (!a || !a->is_array_of_tables() || a->empty())
      fail(file, line_of(*n), "list", "", "expected [[list]] tables, one per run");
    list_runs = a->size();
    const std::vector<Leaf> first = leaves(*a->get(0)->as_table());
    if (first.empty()) fail(file, line_of(*a->get(0)), "list", "", "the first [[list]] is empty");
    for (const Leaf& l : first)
      varied.push_back({l.key, " in [[list]]", line_of(*l.node), {}});
    for (std::size_t e = 0; e < a->size(); ++e) {
      const toml::table& entry = *a->get(e)->as_table();
      const std::vector<Leaf> these = leaves(entry);
      std::map<std::string, const toml::node*> by_key;
      for (const Leaf& l : these)
        by_key[l.key] = l.node;
      const bool same_keys = these.size() == first.size() &&
                             std::all_of(first.begin(), first.end(),
                                         [&](const Leaf& l) { return by_key.count(l.key); });
      if (!same_keys)
        SG_THROW(file.string() << ":" << line_of(entry) << ": [[list]] entry " << e
                               << ": every entry must set the same keys as the first one");
      for (Varied& v : varied)
        v.values.push_back(by_key.at(v.key));
    }
  }
  return varied;
}

// The [grid] keys in file order, each with its values.
void read_grid(const fs::path& file, const toml::table& doc, std::vector<Varied>& varied) {
  if (const toml::node* n = doc.get("grid")) {
    const auto* t = n->as_table();
    if (!t) fail(file, line_of(*n), "grid", "", "expected a [grid] table of key = [values]");
    for (const Leaf& l : leaves(*t)) {
      const auto* values = l.node->as_array();
      if (!values || values->empty())
        fail(file, line_of(*l.node), l.key, " in [grid]",
             "expected a non-empty array of values, got " + toml_text(*l.node));
      Varied v{l.key, " in [grid]", line_of(*l.node), {}};
      for (const auto& value : *values)
        v.values.push_back(&value);
      varied.push_back(std::move(v));
    }
  }
}

// Something to vary; no key set by sweep itself; no key varied twice (or inside another).
void check_varied(const fs::path& file, const std::vector<Varied>& varied) {
  if (varied.empty()) SG_THROW(file.string() << ": no [grid] and no [[list]]: nothing to vary");
  for (std::size_t i = 0; i < varied.size(); ++i) {
    const std::string& key = varied[i].key;
    if (key == "name" || key == "output.directory" || key == "output")
      fail(file, varied[i].line, key, varied[i].where,
           "set by softgrain sweep for every run (the run id, the campaign's runs/ folder)");
    for (std::size_t j = 0; j < varied.size(); ++j)
      if (i != j && (key == varied[j].key || varied[j].key.rfind(key + ".", 0) == 0))
        fail(file, varied[j].line, varied[j].key, varied[j].where,
             "also varied as '" + key + "' (line " + std::to_string(varied[i].line) + ")");
  }
}

ScenarioBase read_base_scenario(const CampaignDef& c, const std::string& as_written) {
  ScenarioBase base;
  base.file = c.scenario;
  base.as_written = as_written;
  {
    std::ifstream in(c.scenario, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    base.text = text.str();
  }
  try {
    base.table = toml::parse(base.text, c.scenario.string());
  } catch (const toml::parse_error& e) {
    SG_THROW(c.scenario.string() << ":" << e.source().begin.line << ":" << e.source().begin.column
                                 << ": TOML syntax error: " << e.description());
  }
  return base;
}

// Each varied key checked against the base scenario; its values as TOML text (for the
// scenario) and as shown in run ids. Fills c.parameters.
void value_texts(const fs::path& file, const std::vector<Varied>& varied, const ScenarioBase& base,
                 CampaignDef& c, std::vector<std::vector<std::string>>& texts,
                 std::vector<std::vector<std::string>>& shown) {
  texts.assign(varied.size(), {});
  shown.assign(varied.size(), {});
  for (std::size_t p = 0; p < varied.size(); ++p) {
    const Varied& v = varied[p];
    if (is_paper_coordinate(v.key)) {
      for (const toml::node* value : v.values) {
        if (!value->is_number())
          fail(
              file, line_of(*value), v.key, v.where,
              "expected a number (a paper coordinate, log10 of a ratio), got " + toml_text(*value));
        texts[p].push_back(format_double(value->value<double>().value(), true));
        shown[p].push_back(file_safe(display_text(*value)));
      }
      c.parameters.push_back({v.key, "", v.line, true});
      continue;
    }
    const Resolved r = resolve(base.table, v.key);
    if (!r.node)
      fail(file, v.line, v.key, v.where,
           "the base scenario '" + c.scenario.string() + "' " + r.error +
               (r.error.rfind("has no", 0) == 0
                    ? " (to vary a key, the base scenario must set it, e.g. to its default)"
                    : ""));
    if (r.node->is_table() || (r.node->is_array() && r.node->as_array()->is_array_of_tables()))
      fail(file, v.line, v.key, v.where,
           "is " + std::string(r.node->is_table() ? "a table" : "an array of tables") +
               " in the base scenario; vary the keys inside it, e.g. '" + v.key +
               (r.node->is_table() ? ".<key>'" : ".0.<key>'"));
    for (const toml::node* value : v.values) {
      texts[p].push_back(replacement_text(*r.node, *value, [&](const std::string& message) {
        fail(file, line_of(*value), v.key, v.where, message);
      }));
      shown[p].push_back(file_safe(display_text(*value)));
    }
    c.parameters.push_back({v.key, "", v.line, false});
  }
}

// The paper coordinates' mapping (campaign/paper_coordinates.h), checked against the other
// varied keys: a physical key may not be varied both ways.
PaperFrame read_frame(const fs::path& file, const std::vector<Varied>& varied,
                      const ScenarioBase& base, const CampaignDef& c) {
  std::vector<std::string> used;
  for (const Varied& v : varied)
    if (is_paper_coordinate(v.key)) used.push_back(v.key);
  if (used.empty()) return {};
  const auto line_of_key = [&](const std::string& key) {
    for (const Varied& v : varied)
      if (v.key == key) return v;
    return varied.front();
  };
  const PaperFrame frame = read_paper_frame(base.table, c.scenario, used,
                                            [&](const std::string& key, const std::string& m) {
                                              const Varied v = line_of_key(key);
                                              fail(file, v.line, v.key, v.where, m);
                                            });
  for (const std::string& key : used)
    for (const auto& [derived, value] : paper_values(frame, key, 0.0)) {
      if (!resolve(base.table, derived).node) {
        const Varied v = line_of_key(key);
        fail(file, v.line, v.key, v.where,
             "sets '" + derived + "', which the base scenario must write (e.g. at its default)");
      }
      for (const Varied& v : varied)
        if (v.key == derived || derived.rfind(v.key + ".", 0) == 0)
          fail(file, v.line, v.key, v.where,
               "also set by '" + key + "' (line " + std::to_string(line_of_key(key).line) + ")");
    }
  return frame;
}

// The runs: each [[list]] entry times the [grid] product, the first grid key slowest.
void expand_runs(const fs::path& file, const std::vector<Varied>& varied, std::size_t list_runs,
                 const std::vector<std::vector<std::string>>& texts,
                 const std::vector<std::vector<std::string>>& shown, const PaperFrame& frame,
                 CampaignDef& c) {
  std::size_t grid_runs = 1;
  for (const Varied& v : varied)
    if (v.where == " in [grid]") grid_runs *= v.values.size();
  const std::size_t total = list_runs * grid_runs;
  SG_VERIFY(total <= 100000, file.string()
                                 << ": " << total << " runs: more than 100000, surely a mistake");
  const std::size_t width = std::max<std::size_t>(3, std::to_string(total - 1).size());
  for (std::size_t index = 0; index < total; ++index) {
    CampaignRun run;
    run.index = index;
    std::string digits = std::to_string(index);
    run.id = "run-" + std::string(width - digits.size(), '0') + digits;
    std::size_t rest = index % grid_runs;
    std::vector<std::size_t> choice(varied.size());
    for (std::size_t p = varied.size(); p-- > 0;) {
      if (varied[p].where == " in [grid]") {
        choice[p] = rest % varied[p].values.size();
        rest /= varied[p].values.size();
      } else {
        choice[p] = index / grid_runs;
      }
    }
    for (std::size_t p = 0; p < varied.size(); ++p) {
      run.values.push_back(texts[p][choice[p]]);
      run.id += "_" + c.parameters[p].label + "=" + shown[p][choice[p]];
      if (c.parameters[p].paper_coordinate)
        for (const auto& [key, value] :
             paper_values(frame, varied[p].key, std::stod(texts[p][choice[p]])))
          run.derived.emplace_back(key, format_double(value, true));
    }
    require_plain_file_name(run.id, file.string() + ": run id (its folder name)");
    c.runs.push_back(std::move(run));
  }
}

}  // namespace

CampaignDef load_campaign(const fs::path& file) {
  require_input_file(file, "campaign file");  // by type before opening (a FIFO would block)
  toml::table doc;
  try {
    doc = toml::parse_file(file.string());
  } catch (const toml::parse_error& e) {
    SG_THROW(file.string() << ":" << e.source().begin.line << ":" << e.source().begin.column
                           << ": TOML syntax error: " << e.description());
  }
  CampaignDef c;
  c.file = file;
  read_settings(file, doc, c);

  // The varied parameters: [[list]] keys first, then [grid] keys, each in file order.
  std::size_t list_runs = 1;
  std::vector<Varied> varied = read_list(file, doc, list_runs);
  read_grid(file, doc, varied);
  check_varied(file, varied);

  // The base scenario: every key must exist there, with a value of the same type.
  const ScenarioBase base = read_base_scenario(c, string_value(file, doc, "scenario", ""));
  std::vector<std::vector<std::string>> texts, shown;
  value_texts(file, varied, base, c, texts, shown);
  const PaperFrame frame = read_frame(file, varied, base, c);
  assign_labels(c.parameters);
  expand_runs(file, varied, list_runs, texts, shown, frame, c);
  for (CampaignRun& run : c.runs)
    run.scenario_text = patch_scenario(base, c, run);
  return c;
}

}  // namespace sg
