#include "core/error.h"

namespace sg {

void throw_error(const std::string& message, const char* file, int line, bool with_location) {
  if (!with_location) throw Error(message);
  std::ostringstream s;
  s << message << " [" << file << ":" << line << "]";
  throw Error(s.str());
}

}  // namespace sg
