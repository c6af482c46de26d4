#pragma once
// The name rule for everything a user gives that becomes a path component: a scenario's
// `name` (its run folder), a campaign's name and run ids, render and analysis output names.
// A plain file name: letters, digits and . _ - + = , only; not empty, not "." or "..", no
// path separator. Nothing named this way can reach outside the folder it is put in
// (docs/scenario.md, "Safety").
#include <string>
#include <string_view>

namespace sg {

// True if `name` follows the rule above.
bool is_plain_file_name(std::string_view name);

// Why `name` breaks the rule ("" if it does not): for messages, e.g.
//   "expected a plain file name (letters, digits, '.', '_', '-', '+', '=', ','), got
//    \"../x\": '/' is a path separator".
std::string plain_file_name_problem(std::string_view name);

// Throws sg::Error "<what>: <problem>" if `name` breaks the rule.
void require_plain_file_name(std::string_view name, const std::string& what);

}  // namespace sg
