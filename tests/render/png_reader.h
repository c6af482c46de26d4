#pragma once
// Reading back the PNG pictures the renderer writes, for tests: the size and the pixels of a
// file, with Cairo.
#include <cstdint>
#include <filesystem>
#include <utility>
#include <vector>

namespace sg {

// Width and height of a PNG file. Throws sg::Error naming the file if it cannot be read.
std::pair<int, int> png_size(const std::filesystem::path& png);

// The pixels of a PNG file, row after row from the top, each 0xRRGGBB.
struct PngPixels {
  int width = 0, height = 0;
  std::vector<std::uint32_t> rgb;
  std::uint32_t at(int x, int y) const {
    return rgb[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
               static_cast<std::size_t>(x)];
  }
};
PngPixels png_pixels(const std::filesystem::path& png);

}  // namespace sg
