#pragma once
// Where a series of pictures puts the world: one box (the extent of the frames drawn, with a
// small margin) mapped to the pixels of the drawing area, with bands for the title, the scale
// bar and the colour bar, fixed for the whole series so that the frames of a movie line up.
//
// The box fills the drawing area in the direction that limits its scale and is centred in the
// other, except for a periodic run whose drawing is limited by the height: the box then grows
// in x (the period stays centred) until it fills the width, and the drawing repeats the
// periodic images into it, so that a wide picture of a periodic layer shows the layer, not
// white bands (render/frame_drawing.h marks the period).
#include "geometry/bounding_box.h"

namespace sg {

// Picture geometry, fixed for the whole series: world box -> pixels.
struct Layout {
  int width = 0, height = 0;
  double font = 12.0;
  double plot_x0 = 0, plot_y0 = 0, plot_x1 = 0, plot_y1 = 0;  // pixel box of the drawing area
  double scale = 1.0;                                         // pixels per length
  double offset_x = 0, offset_y = 0;                          // pixel of world (0, 0)
  BoundingBox world;  // the part of the world drawn (periodic: may hold more than a period)
  bool colour_bar = true;

  double px(double x) const { return offset_x + scale * x; }
  double py(double y) const { return offset_y - scale * y; }
};

// `periodic`: the box's x span is one period, which may be repeated to fill the width.
Layout make_layout(int width, int height, const BoundingBox& world, bool colour_bar,
                   bool periodic = false);

// A small margin so that outlines on the box's edge are not cut.
BoundingBox with_margin(BoundingBox world, bool periodic);

}  // namespace sg
