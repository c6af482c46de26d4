#pragma once
// What a series of pictures shares (render/snapshot_renderer.h): the box that holds every
// frame, and the colour range of the field: given, else min and max of the coloured values
// over every frame (or their 1st-99th percentiles), the contact rates on the outlines
// included; [-1, 1] for the coherence.
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "geometry/bounding_box.h"
#include "render/frame_style.h"
#include "render/snapshot_renderer.h"
#include "render/vtu_reader.h"

namespace sg {

// Pass 1, over every frame: the drawing box, and (for a field read from the .vtu with no
// given range) the range of the coloured values with every value for the robust range.
struct SeriesExtent {
  BoundingBox world;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::vector<double> values;
  std::string contact_note;  // why the contact rates are not drawn (render/contact_outlines.h)
};

SeriesExtent measure_series(const std::vector<PvdEntry>& entries, const Style& style,
                            const RenderOptions& options, const std::filesystem::path& pvd);

// The colour range: given, else robust, else full (with a hint when it is dominated by
// outliers); C is always [-1, 1].
void choose_range(SeriesExtent& e, Style& style, const RenderOptions& options,
                  RenderResult& result);

}  // namespace sg
