#include "core/file_name.h"

#include <cctype>

#include "core/error.h"

namespace sg {

namespace {

bool allowed(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) ||
         std::string_view("._-+=,").find(c) != std::string_view::npos;
}

std::string shown(char c) {
  if (std::isprint(static_cast<unsigned char>(c))) return std::string("'") + c + "'";
  static const char* digits = "0123456789abcdef";
  const auto u = static_cast<unsigned char>(c);
  return std::string("byte 0x") + digits[u >> 4] + digits[u & 15];
}

}  // namespace

bool is_plain_file_name(std::string_view name) {
  return plain_file_name_problem(name).empty();
}

std::string plain_file_name_problem(std::string_view name) {
  std::string why;
  if (name.empty()) {
    why = "it is empty";
  } else if (name.size() > 255) {  // NAME_MAX: the file system would refuse it
    why = "it is " + std::to_string(name.size()) + " bytes long, a file name holds at most 255";
  } else if (name == "." || name == "..") {
    why = "it names a folder itself or its parent";
  } else {
    for (char c : name)
      if (!allowed(c)) {
        why = shown(c) + (c == '/' || c == '\\' ? " is a path separator" : " is not allowed");
        break;
      }
  }
  if (why.empty()) return why;
  std::string quoted;
  for (char c : name.substr(0, 80))
    quoted += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  return "expected a plain file name (letters, digits, '.', '_', '-', '+', '=', ','), got \"" +
         quoted + (name.size() > 80 ? "...\"" : "\"") + ": " + why;
}

void require_plain_file_name(std::string_view name, const std::string& what) {
  const std::string problem = plain_file_name_problem(name);
  SG_VERIFY(problem.empty(), what << ": " << problem);
}

}  // namespace sg
