#include "render/frame_picture.h"

#include <cairo.h>

#include <string>

#include "core/error.h"
#include "core/version.h"
#include "io/atomic_file.h"
#include "render/frame_decorations.h"
#include "render/frame_drawing.h"
#include "render/png_text.h"

namespace sg {

void write_png(const Layout& l, const Style& s, const Frame& f, const std::filesystem::path& path) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, l.width, l.height);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  draw_frame(cr, l, s, f);
  draw_decorations(cr, l, s, f);
  cairo_destroy(cr);
  cairo_surface_flush(surface);
  // To memory first, to add the version of softgrain that drew it (render/png_text.h); then
  // atomically: a reader never sees half a picture.
  std::string png;
  const cairo_status_t status = cairo_surface_write_to_png_stream(
      surface,
      [](void* closure, const unsigned char* data, unsigned int length) {
        static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
        return CAIRO_STATUS_SUCCESS;
      },
      &png);
  cairo_surface_destroy(surface);
  SG_VERIFY(status == CAIRO_STATUS_SUCCESS,
            "cannot write '" << path.string() << "': " << cairo_status_to_string(status));
  write_file_atomically(path, with_png_text(png, "Software", softgrain_version_line()));
}

}  // namespace sg
