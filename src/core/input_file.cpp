#include "core/input_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>

#include "core/error.h"

namespace sg {

std::string shown_path(const std::filesystem::path& path) {
  constexpr std::size_t kShown = 200;
  const std::string& s = path.native();
  if (s.size() <= kShown) return "'" + s + "'";
  return "'" + s.substr(0, kShown) + "...' (" + std::to_string(s.size()) + " bytes)";
}

std::string input_file_problem(const std::filesystem::path& path) {
  const std::string& s = path.native();
  if (s.empty()) return "is empty: expected a file name";
  if (s.size() > kMaxPathBytes)
    return "is too long: " + std::to_string(s.size()) + " bytes, at most " +
           std::to_string(kMaxPathBytes) + " are allowed";
  for (const auto& part : path)
    if (part.native().size() > kMaxFileNameBytes)
      return "has a component of " + std::to_string(part.native().size()) +
             " bytes: a file name holds at most " + std::to_string(kMaxFileNameBytes);
  // stat follows symbolic links: a link to a regular file is a regular file.
  struct stat st {};
  if (::stat(s.c_str(), &st) != 0) {
    if (errno == ENOENT) return "does not exist";
    return std::string("cannot be read: ") + std::strerror(errno);
  }
  if (S_ISREG(st.st_mode)) return "";
  if (S_ISDIR(st.st_mode)) return "is a folder: expected a regular file";
  if (S_ISFIFO(st.st_mode)) return "is a FIFO (named pipe): expected a regular file";
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "is a device: expected a regular file";
  if (S_ISSOCK(st.st_mode)) return "is a socket: expected a regular file";
  return "is not a regular file";
}

void require_input_file(const std::filesystem::path& path, const std::string& what) {
  const std::string problem = input_file_problem(path);
  SG_VERIFY(problem.empty(), what << " " << shown_path(path) << " " << problem);
}

}  // namespace sg
