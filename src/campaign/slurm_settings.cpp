#include "campaign/slurm_settings.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <set>
#include <sstream>

#include "campaign/slurm_settings_reader.h"
#include "core/error.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

bool all_digits(const std::string& s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

// Each check returns why `value` is not acceptable, or "" if it is. The callers add the key
// (file and line, or the option).

// A partition, account or QOS name: one word (it goes on an #SBATCH line).
std::string check_word(const std::string& value) {
  if (value.empty()) return "expected a name, got an empty string";
  for (char c : value)
    if (std::isspace(static_cast<unsigned char>(c)) || !std::isprint(static_cast<unsigned char>(c)))
      return "expected one word (no spaces or control characters), got \"" + value + "\"";
  return "";
}

std::string check_time(const std::string& value) {
  if (parse_slurm_time(value)) return "";
  return "expected a Slurm time limit (minutes, MM:SS, HH:MM:SS, D-HH, D-HH:MM or D-HH:MM:SS, "
         "e.g. \"12:00:00\" or \"2-00:00:00\"), got \"" +
         value + "\"";
}

std::string check_memory(const std::string& value) {
  std::string digits = value;
  if (!digits.empty() && std::string("KMGTkmgt").find(digits.back()) != std::string::npos)
    digits.pop_back();
  if (all_digits(digits) && std::stol(digits) > 0) return "";
  return "expected a memory size per task (a number of megabytes, or with a unit K, M, G or T, "
         "e.g. \"4G\"), got \"" +
         value + "\"";
}

std::string check_max_running(long value) {
  if (value >= 1) return "";
  return "expected at least 1 (tasks running at once), got " + std::to_string(value);
}

std::string check_margin(double value) {
  if (std::isfinite(value) && value >= 1.0) return "";
  std::ostringstream s;
  s << "expected a factor of at least 1 (time limit = margin x projected wall time), got " << value;
  return s.str();
}

// An extra #SBATCH line: an sbatch option ("--constraint=avx2", "-C avx2"), on one line.
// "#SBATCH " in front is accepted and removed.
std::string normalize_extra(std::string& value) {
  const std::string prefix = "#SBATCH";
  if (value.rfind(prefix, 0) == 0) value = value.substr(prefix.size());
  const auto first = value.find_first_not_of(" \t");
  value = first == std::string::npos
              ? ""
              : value.substr(first, value.find_last_not_of(" \t") - first + 1);
  if (value.find_first_of("\n\r") != std::string::npos)
    return "expected one sbatch option per entry, got a line break in \"" + value + "\"";
  if (value.empty() || value[0] != '-')
    return "expected sbatch options such as \"--constraint=avx2\", got \"" + value + "\"";
  if (value.rfind("--array", 0) == 0 || value.rfind("-a", 0) == 0 ||
      value.rfind("--cpus-per-task", 0) == 0 || value.rfind("-c", 0) == 0)
    return "\"" + value +
           "\": sweep sets --array (one task per unfinished run) and --cpus-per-task (the run's "
           "threads) itself; use max_running for the %K limit and the campaign's threads";
  return "";
}

// ---------------------------------------------------------------------------------------
// The [slurm] table

[[noreturn]] void fail(const fs::path& file, const toml::node& n, const std::string& key,
                       const std::string& message) {
  SG_THROW(file.string() << ":" << n.source().begin.line << ": key 'slurm." << key
                         << "': " << message);
}

std::string shown(const toml::node& n) {
  std::ostringstream s;
  n.visit([&](const auto& v) { s << v; });
  return s.str();
}

std::string string_of(const fs::path& file, const toml::node& n, const std::string& key) {
  if (const auto* s = n.as_string()) return s->get();
  fail(file, n, key, "expected a string, got " + shown(n));
}

void check(const fs::path& file, const toml::node& n, const std::string& key,
           const std::string& why) {
  if (!why.empty()) fail(file, n, key, why);
}

}  // namespace

std::optional<long> parse_slurm_time(const std::string& text) {
  if (text == "UNLIMITED" || text == "INFINITE" || text == "unlimited" || text == "infinite")
    return -1;
  long days = 0;
  std::string rest = text;
  const auto dash = text.find('-');
  if (dash != std::string::npos) {
    if (!all_digits(text.substr(0, dash))) return std::nullopt;
    days = std::stol(text.substr(0, dash));
    rest = text.substr(dash + 1);
  }
  std::vector<std::string> parts;
  std::istringstream in(rest);
  for (std::string p; std::getline(in, p, ':');)
    parts.push_back(p);
  if (!rest.empty() && rest.back() == ':') parts.emplace_back();
  if (parts.empty() || parts.size() > 3) return std::nullopt;
  for (const std::string& p : parts)
    if (!all_digits(p) || p.size() > 6) return std::nullopt;
  std::vector<long> v;
  for (const std::string& p : parts)
    v.push_back(std::stol(p));
  long seconds = 0;
  if (dash != std::string::npos) {
    // D-HH, D-HH:MM, D-HH:MM:SS
    seconds = v[0] * 3600 + (v.size() > 1 ? v[1] * 60 : 0) + (v.size() > 2 ? v[2] : 0);
  } else if (v.size() == 1) {
    seconds = v[0] * 60;  // minutes
  } else if (v.size() == 2) {
    seconds = v[0] * 60 + v[1];  // MM:SS
  } else {
    seconds = v[0] * 3600 + v[1] * 60 + v[2];  // HH:MM:SS
  }
  seconds += days * 86400;
  if (seconds <= 0) return std::nullopt;
  return seconds;
}

std::string format_slurm_time(double seconds) {
  const long minutes = std::max(1L, static_cast<long>(std::ceil(seconds / 60.0)));
  const long days = minutes / 1440, hours = minutes % 1440 / 60, mins = minutes % 60;
  char buffer[64];
  if (days > 0)
    std::snprintf(buffer, sizeof buffer, "%ld-%02ld:%02ld:00", days, hours, mins);
  else
    std::snprintf(buffer, sizeof buffer, "%02ld:%02ld:00", hours, mins);
  return buffer;
}

SlurmSettings read_slurm_settings(const fs::path& file, const toml::table& doc) {
  SlurmSettings s;
  const toml::node* node = doc.get("slurm");
  if (!node) return s;
  const toml::table* t = node->as_table();
  if (!t)
    SG_THROW(file.string() << ":" << node->source().begin.line
                           << ": key 'slurm': expected a table [slurm], got " << shown(*node));
  static const std::set<std::string> known = {"partition", "account", "qos",
                                              "time",      "memory",  "max_running",
                                              "requeue",   "extra",   "time_margin"};
  for (const auto& [k, v] : *t) {
    const std::string key(k.str());
    if (!known.count(key))
      fail(file, v, key,
           "unknown key; expected partition, account, qos, time, memory, max_running, requeue, "
           "time_margin or extra");
    if (key == "partition" || key == "account" || key == "qos") {
      const std::string value = string_of(file, v, key);
      check(file, v, key, check_word(value));
      (key == "partition" ? s.partition : key == "account" ? s.account : s.qos) = value;
    } else if (key == "time") {
      s.time = string_of(file, v, key);
      check(file, v, key, check_time(s.time));
    } else if (key == "memory") {
      if (const auto* i = v.as_integer())
        s.memory = std::to_string(i->get());
      else
        s.memory = string_of(file, v, key);
      check(file, v, key, check_memory(s.memory));
    } else if (key == "max_running") {
      const auto* i = v.as_integer();
      if (!i) fail(file, v, key, "expected an integer, got " + shown(v));
      check(file, v, key, check_max_running(i->get()));
      s.max_running = static_cast<int>(std::min<std::int64_t>(i->get(), 1000000));
    } else if (key == "requeue") {
      const auto* b = v.as_boolean();
      if (!b) fail(file, v, key, "expected true or false, got " + shown(v));
      s.requeue = b->get();
    } else if (key == "time_margin") {
      if (!v.is_number()) fail(file, v, key, "expected a number, got " + shown(v));
      s.time_margin = v.value<double>().value();
      check(file, v, key, check_margin(s.time_margin));
    } else {  // extra
      const auto* a = v.as_array();
      if (!a) fail(file, v, key, "expected an array of sbatch options, got " + shown(v));
      for (const auto& e : *a) {
        std::string line = string_of(file, e, key);
        check(file, e, key, normalize_extra(line));
        s.extra.push_back(line);
      }
    }
  }
  return s;
}

SlurmSettings apply_slurm_overrides(SlurmSettings s, const SlurmOverrides& o) {
  const auto check_option = [](const char* option, const std::string& why) {
    if (!why.empty()) SG_THROW("option " << option << ": " << why);
  };
  if (o.partition) {
    check_option("--partition", check_word(*o.partition));
    s.partition = *o.partition;
  }
  if (o.account) {
    check_option("--account", check_word(*o.account));
    s.account = *o.account;
  }
  if (o.qos) {
    check_option("--qos", check_word(*o.qos));
    s.qos = *o.qos;
  }
  if (o.time) {
    check_option("--time", check_time(*o.time));
    s.time = *o.time;
  }
  if (o.memory) {
    check_option("--mem", check_memory(*o.memory));
    s.memory = *o.memory;
  }
  if (o.max_running) {
    check_option("--max-running", check_max_running(*o.max_running));
    s.max_running = *o.max_running;
  }
  for (std::string line : o.extra) {
    check_option("--sbatch", normalize_extra(line));
    s.extra.push_back(line);
  }
  return s;
}

}  // namespace sg
