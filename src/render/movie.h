#pragma once
// The frames of a series joined into an MP4 movie by ffmpeg, when ffmpeg is on PATH: the only
// external program the renderer runs.
#include <cstddef>
#include <filesystem>
#include <string>

namespace sg {

// Whether an executable file `program` is in one of PATH's folders.
bool on_path(const std::string& program);

struct Movie {
  std::filesystem::path file;  // empty if none was made
  std::string note;            // why there is none
};

// Joins `frames` pictures <out_dir>/<field>_NNNNNN.png, numbered consecutively from the number
// `first_frame` (a snapshot's file stem, "000000"), at 8 frames per second into
// <out_dir>/<field>.mp4 (pictures of an earlier render after them are left out).
Movie encode_movie(const std::filesystem::path& out_dir, const std::string& field,
                   const std::string& first_frame, std::size_t frames);

}  // namespace sg
