#pragma once
// A whole text file as a string; "" when it cannot be read (an absent marker, a log not yet
// written): for the campaign's bookkeeping files, whose absence is a state, not an error.
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace sg {

inline std::string read_text_or_empty(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace sg
