#pragma once
// Where a series of pictures puts the world: one box (the extent of every frame, with a small
// margin) mapped to the pixels of the drawing area, with bands for the title, the scale bar and
// the colour bar, fixed for the whole series so that the frames of a movie line up.
#include "geometry/bounding_box.h"

namespace sg {

// Picture geometry, fixed for the whole series: world box -> pixels.
struct Layout {
  int width = 0, height = 0;
  double font = 12.0;
  double plot_x0 = 0, plot_y0 = 0, plot_x1 = 0, plot_y1 = 0;  // pixel box of the drawing
  double scale = 1.0;                                         // pixels per length
  double offset_x = 0, offset_y = 0;                          // pixel of world (0, 0)
  BoundingBox world;
  bool colour_bar = true;

  double px(double x) const { return offset_x + scale * x; }
  double py(double y) const { return offset_y - scale * y; }
};

Layout make_layout(int width, int height, const BoundingBox& world, bool colour_bar);

// A small margin so that outlines on the box's edge are not cut.
BoundingBox with_margin(BoundingBox world, bool periodic);

}  // namespace sg
