#include "render/movie.h"

#include <cstdlib>
#include <sstream>

namespace sg {

namespace fs = std::filesystem;

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    std::error_code ec;
    const fs::path candidate = fs::path(dir) / program;
    if (fs::is_regular_file(candidate, ec) &&
        (fs::status(candidate, ec).permissions() & fs::perms::owner_exec) != fs::perms::none)
      return true;
  }
  return false;
}

Movie encode_movie(const fs::path& out_dir, const std::string& field,
                   const std::string& first_frame, std::size_t frames) {
  if (!on_path("ffmpeg"))
    return {{}, "ffmpeg not found on PATH: no movie (the PNG frames are written)"};
  const fs::path mp4 = out_dir / (field + ".mp4");
  std::ostringstream cmd;
  cmd << "ffmpeg -y -loglevel error -framerate 8 -start_number " << std::stoi(first_frame)
      << " -i '" << (out_dir / (field + "_%06d.png")).string() << "' -frames:v " << frames
      << " -vf 'scale=trunc(iw/2)*2:trunc(ih/2)*2' -pix_fmt yuv420p -vcodec libx264 '"
      << mp4.string() << "' < /dev/null";
  if (std::system(cmd.str().c_str()) == 0) return {mp4, ""};
  return {{}, "ffmpeg failed: no movie (command: " + cmd.str() + ")"};
}

}  // namespace sg
