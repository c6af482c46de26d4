#include "render/png_text.h"

#include <array>
#include <cstdint>

#include "core/error.h"

namespace sg {
namespace {

constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);

// CRC-32 of the PNG specification (Annex D: polynomial 0xedb88320, reflected, initial and
// final XOR with 0xffffffff), over the chunk type and data.
std::uint32_t crc32(std::string_view bytes) {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k)
        c = (c & 1u) ? 0xedb88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xffffffffu;
  for (char b : bytes)
    c = table[(c ^ static_cast<unsigned char>(b)) & 0xffu] ^ (c >> 8);
  return c ^ 0xffffffffu;
}

void append_u32(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8)
    out += static_cast<char>((v >> shift) & 0xffu);
}

std::uint32_t read_u32(std::string_view s, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t k = 0; k < 4; ++k)
    v = (v << 8) | static_cast<unsigned char>(s[at + k]);
  return v;
}

}  // namespace

std::string with_png_text(std::string_view png, std::string_view keyword, std::string_view text) {
  SG_VERIFY(png.size() >= 8 + 25 && png.substr(0, 8) == kSignature && png.substr(12, 4) == "IHDR" &&
                read_u32(png, 8) == 13,
            "PNG text: not a PNG image (no signature and IHDR chunk)");
  SG_VERIFY(!keyword.empty() && keyword.size() <= 79, "PNG text: keyword of 1-79 characters");
  for (char c : keyword)
    SG_VERIFY(c >= 32 && c <= 126, "PNG text: keyword '" << keyword << "' is not printable");
  std::string body = "tEXt";
  body.append(keyword).push_back('\0');
  body.append(text);
  std::string chunk;
  append_u32(chunk, static_cast<std::uint32_t>(body.size() - 4));
  chunk += body;
  append_u32(chunk, crc32(body));
  const std::size_t after_ihdr = 8 + 4 + 4 + 13 + 4;  // signature, length, type, data, CRC
  std::string out(png.substr(0, after_ihdr));
  out += chunk;
  out.append(png.substr(after_ihdr));
  return out;
}

std::string png_text(std::string_view png, std::string_view keyword) {
  if (png.size() < 8 || png.substr(0, 8) != kSignature) return "";
  std::size_t at = 8;
  while (at + 12 <= png.size()) {
    const std::size_t length = read_u32(png, at);
    if (at + 12 + length > png.size()) break;
    const std::string_view type = png.substr(at + 4, 4), data = png.substr(at + 8, length);
    if (type == "tEXt") {
      const std::size_t nul = data.find('\0');
      if (nul != std::string_view::npos && data.substr(0, nul) == keyword)
        return std::string(data.substr(nul + 1));
    }
    if (type == "IEND") break;
    at += 12 + length;
  }
  return "";
}

}  // namespace sg
