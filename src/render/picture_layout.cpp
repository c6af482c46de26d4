#include "render/picture_layout.h"

#include <algorithm>

namespace sg {

Layout make_layout(int width, int height, const BoundingBox& world, bool colour_bar,
                   bool periodic) {
  Layout l;
  l.width = width;
  l.height = height;
  l.world = world;
  l.colour_bar = colour_bar;
  l.font = std::clamp(height / 42.0, 9.0, 26.0);
  const double title_band = 2.2 * l.font, bottom_band = 2.8 * l.font;
  const double right_band = colour_bar ? 8.5 * l.font : l.font;
  l.plot_x0 = l.font;
  l.plot_y0 = title_band;
  l.plot_x1 = std::max(l.plot_x0 + 1.0, width - right_band);
  l.plot_y1 = std::max(l.plot_y0 + 1.0, height - bottom_band);
  const double plot_w = l.plot_x1 - l.plot_x0, plot_h = l.plot_y1 - l.plot_y0;
  const double wx = std::max(world.hi.x() - world.lo.x(), 1e-12);
  const double wy = std::max(world.hi.y() - world.lo.y(), 1e-12);
  l.scale = std::min(plot_w / wx, plot_h / wy);
  if (periodic && plot_w / l.scale > wx) {
    // Limited by the height: more of the periodic layer fills the width, the period centred.
    const double grow = 0.5 * (plot_w / l.scale - wx);
    l.world.lo.x() -= grow;
    l.world.hi.x() += grow;
  }
  // Centre the world box in the drawing area.
  const double cx = 0.5 * (l.plot_x0 + l.plot_x1), cy = 0.5 * (l.plot_y0 + l.plot_y1);
  l.offset_x = cx - l.scale * 0.5 * (l.world.lo.x() + l.world.hi.x());
  l.offset_y = cy + l.scale * 0.5 * (l.world.lo.y() + l.world.hi.y());
  return l;
}

BoundingBox with_margin(BoundingBox world, bool periodic) {
  const double margin = 0.01 * std::max(world.hi.x() - world.lo.x(), world.hi.y() - world.lo.y());
  if (!periodic) {
    world.lo.x() -= margin;
    world.hi.x() += margin;
  }
  world.lo.y() -= margin;
  world.hi.y() += margin;
  return world;
}

}  // namespace sg
