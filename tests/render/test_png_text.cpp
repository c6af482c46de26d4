// The pictures name the softgrain that drew them: a tEXt chunk "Software" in every PNG
// (render/png_text.h), in a file that stays a valid PNG (every chunk's CRC checks).
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.h"
#include "core/version.h"
#include "render/png_text.h"
#include "render/snapshot_renderer.h"
#include "tiny_run.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::uint32_t be32(const std::string& s, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t k = 0; k < 4; ++k)
    v = (v << 8) | static_cast<unsigned char>(s[at + k]);
  return v;
}

// CRC-32 bit by bit (no table): an implementation apart from the one under test, itself
// checked by agreeing with the CRCs Cairo (libpng) wrote.
std::uint32_t bitwise_crc32(const std::string& bytes) {
  std::uint32_t c = 0xffffffffu;
  for (unsigned char b : bytes) {
    c ^= b;
    for (int k = 0; k < 8; ++k)
      c = (c >> 1) ^ (0xedb88320u & (0u - (c & 1u)));
  }
  return ~c;
}

// The chunk types in order; every CRC must check.
std::vector<std::string> chunk_types(const std::string& png) {
  std::vector<std::string> types;
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  for (std::size_t at = 8; at + 12 <= png.size();) {
    const std::size_t length = be32(png, at);
    const std::string body = png.substr(at + 4, 4 + length);
    EXPECT_EQ(be32(png, at + 8 + length), bitwise_crc32(body)) << "chunk " << body.substr(0, 4);
    types.push_back(body.substr(0, 4));
    at += 12 + length;
  }
  return types;
}

TEST(PngText, EveryPictureNamesTheSoftgrainThatDrewIt) {
  RenderOptions o;
  o.field = "velocity";
  o.width = 200;
  o.height = 150;
  o.movie = false;
  const RenderResult r = render_run(test::tiny_run_dir(), o);
  ASSERT_FALSE(r.images.empty());
  for (const fs::path& file : r.images) {
    const std::string png = read_bytes(file);
    EXPECT_EQ(png_text(png, "Software"), softgrain_version_line()) << file;
    const auto types = chunk_types(png);
    ASSERT_GE(types.size(), 4u);
    EXPECT_EQ(types[0], "IHDR");
    EXPECT_EQ(types[1], "tEXt");  // right after the header, as the specification allows
    EXPECT_EQ(types.back(), "IEND");
  }
}

TEST(PngText, RefusesWhatIsNotAPngAndABadKeyword) {
  EXPECT_THROW(with_png_text("not a png at all, not a png at all", "Software", "x"), Error);
  RenderOptions o;
  o.field = "body";
  o.width = 100;
  o.height = 80;
  o.movie = false;
  o.last_frame_only = true;
  const std::string png = read_bytes(render_run(test::tiny_run_dir(), o).images.front());
  EXPECT_THROW(with_png_text(png, "", "x"), Error);
  EXPECT_THROW(with_png_text(png, std::string(80, 'k'), "x"), Error);
  EXPECT_EQ(png_text(png, "Comment"), "");
  EXPECT_EQ(png_text(with_png_text(png, "Comment", "two words"), "Comment"), "two words");
}

}  // namespace
}  // namespace sg
