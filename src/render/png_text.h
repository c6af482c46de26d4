#pragma once
// Text metadata in a PNG file: a tEXt chunk (PNG specification, ISO/IEC 15948 §11.3.4.3)
// inserted after the IHDR chunk. Cairo writes PNGs without metadata and offers no way to add
// any, so the pictures are written to memory, given their chunk here, and saved; `softgrain
// render` records the softgrain version and commit under the keyword "Software" (read with
// `identify -verbose`, `exiftool`, or Pillow's Image.open(...).text).
#include <string>
#include <string_view>

namespace sg {

// `png` with a tEXt chunk keyword = text placed after IHDR. Throws sg::Error if `png` does not
// start with the PNG signature and an IHDR chunk, or if the keyword is not 1-79 printable
// Latin-1 characters (the specification's rule).
std::string with_png_text(std::string_view png, std::string_view keyword, std::string_view text);

// The text of the first tEXt chunk with this keyword; empty if there is none.
std::string png_text(std::string_view png, std::string_view keyword);

}  // namespace sg
