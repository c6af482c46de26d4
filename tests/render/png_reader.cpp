#include "render/png_reader.h"

#include <cairo.h>

#include <cstring>

#include "core/error.h"

namespace sg {
namespace {

// The image surface of a PNG file; throws sg::Error naming the file if it cannot be read.
cairo_surface_t* read_png(const std::filesystem::path& png) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(png.c_str());
  const cairo_status_t status = cairo_surface_status(s);
  if (status != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(s);
    SG_THROW("cannot read PNG '" << png.string() << "': " << cairo_status_to_string(status));
  }
  return s;
}

}  // namespace

PngPixels png_pixels(const std::filesystem::path& png) {
  cairo_surface_t* s = read_png(png);
  cairo_surface_t* rgb = cairo_image_surface_create(
      CAIRO_FORMAT_RGB24, cairo_image_surface_get_width(s), cairo_image_surface_get_height(s));
  cairo_t* cr = cairo_create(rgb);  // whatever the file's format: drawn onto RGB24
  cairo_set_source_surface(cr, s, 0, 0);
  cairo_paint(cr);
  cairo_destroy(cr);
  cairo_surface_flush(rgb);
  PngPixels out;
  out.width = cairo_image_surface_get_width(rgb);
  out.height = cairo_image_surface_get_height(rgb);
  const int stride = cairo_image_surface_get_stride(rgb);
  const unsigned char* data = cairo_image_surface_get_data(rgb);
  out.rgb.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height));
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      std::uint32_t v = 0;
      std::memcpy(&v, data + static_cast<std::ptrdiff_t>(y) * stride + 4 * x, 4);
      out.rgb[static_cast<std::size_t>(y * out.width + x)] = v & 0xffffffu;  // native-endian word
    }
  cairo_surface_destroy(rgb);
  cairo_surface_destroy(s);
  return out;
}

std::pair<int, int> png_size(const std::filesystem::path& png) {
  cairo_surface_t* s = read_png(png);
  const std::pair<int, int> size(cairo_image_surface_get_width(s),
                                 cairo_image_surface_get_height(s));
  cairo_surface_destroy(s);
  return size;
}

}  // namespace sg
