#pragma once
// Reading the pictures of `softgrain render` for tests: which pixels hold drawn matter, the
// drawing area of a picture size, the extent of a snapshot.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "geometry/bounding_box.h"
#include "render/colormap.h"
#include "render/png_reader.h"
#include "render/vtu_reader.h"

namespace sg::test {

inline int channel(std::uint32_t v, int shift) {
  return static_cast<int>((v >> shift) & 0xff);
}

// Whether pixel v is within `tolerance` of colour c in every channel.
inline bool pixel_is(std::uint32_t v, const Rgb& c, int tolerance) {
  const auto near = [&](int shift, double value) {
    return std::abs(channel(v, shift) - static_cast<int>(std::lround(255 * value))) <= tolerance;
  };
  return near(16, c.r) && near(8, c.g) && near(0, c.b);
}

// Drawn matter: anything but the white background and the light band of the period (both
// lighter than 240 in no channel).
inline bool is_matter(std::uint32_t v) {
  return channel(v, 16) < 240 || channel(v, 8) < 240 || channel(v, 0) < 240;
}

// The fraction of the pixel columns x0 <= x < x1 with drawn matter between rows y0 and y1.
inline double matter_column_fraction(const PngPixels& png, int x0, int x1, int y0, int y1) {
  int filled = 0;
  for (int x = x0; x < x1; ++x) {
    bool any = false;
    for (int y = y0; y < y1 && !any; ++y)
      any = is_matter(png.at(x, y));
    filled += any ? 1 : 0;
  }
  return static_cast<double>(filled) / (x1 - x0);
}

// The box of a snapshot's points.
inline BoundingBox snapshot_box(const std::filesystem::path& vtu) {
  BoundingBox box;
  for (const Vec2& p : read_vtu(vtu).points)
    box.add(p);
  return box;
}

}  // namespace sg::test
