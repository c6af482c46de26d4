#pragma once
// The colour range of a series of field pictures, one for every frame drawn (so that a movie
// does not flicker and two frames compare by colour), and where it came from, in this order:
//  1. given (--range);
//  2. the coherence C: [-1, 1], its whole span;
//  3. velocity fields of a shear cell (V known, no --robust): the first bodies slide at +V/2
//     (top) and -V/2 (bottom) (docs/analysis.md, sign convention), so velocity_x and
//     velocity_y take [-V/2, V/2] and the speed [0, V/2]: the same colours mean the same
//     velocities in every run of a campaign, and the profile across the layer spans the map
//     instead of a few fast grains of the compaction setting it;
//  4. the coloured values of the frames drawn: min-max, or with --robust their 1st-99th
//     percentiles (with a hint when min-max is dominated by outliers).
// On a log scale (--log, fields >= 0 only) the top is the same (on the positive values; a
// shear cell's speed V/2) and the bottom kLogDecades decades below it.
#include <string>

#include "render/frame_style.h"
#include "render/series_extent.h"
#include "render/snapshot_renderer.h"

namespace sg {

// How far a default log range reaches below its top: 3 decades shows the strain rate of the
// slowly deforming grains beside their contacts' rates without turning round-off into colour.
inline constexpr double kLogDecades = 3.0;

// Sets style.lo, style.hi and the result's range, its source and a hint in result.note.
// Throws sg::Error when nothing is coloured by the field, or (log) no value is positive.
void choose_range(SeriesExtent& e, Style& style, const RenderOptions& options,
                  RenderResult& result);

}  // namespace sg
