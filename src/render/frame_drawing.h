#pragma once
// The bodies of one picture, drawn with Cairo into the layout's drawing area: every deformable
// grain as its triangulation shaded by the field (one mesh-pattern patch per triangle) or
// filled flat by body, rigid bodies as filled polygons, the outlines, and the contact rates on
// the outlines (render/contact_outlines.h); periodic runs over the layout's box (one period,
// or more repeated to fill the width: render/picture_layout.h) on a light band marking the
// period, cells crossing the seam drawn on both sides (render/snapshot_renderer.h says what
// each field shows).
#include <cairo.h>

#include "render/frame_style.h"
#include "render/picture_layout.h"

namespace sg {

void draw_frame(cairo_t* cr, const Layout& l, const Style& s, const Frame& f);

}  // namespace sg
