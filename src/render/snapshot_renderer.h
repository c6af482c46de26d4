#pragma once
// PNG pictures of a run's field snapshots (fields/NNNNNN.vtu), drawn with Cairo.
//
// What a picture shows: every deformable grain as its triangulation in the current
// configuration, filled by a nodal field and interpolated linearly over each triangle
// (Gouraud shading: one Cairo mesh-pattern patch per triangle), outlined by its boundary
// edges; rigid bodies (rigid grains, walls, first bodies) as filled polygons, coloured by
// the field where the field is defined on them (velocity, displacement, body) and in
// neutral grey otherwise (the writer gives them zero stress, which is not a measurement);
// a colour bar with the field's name, unit and range; a length scale bar; the time.
//
// The colour range is one for the whole series (so that a movie does not flicker and two
// frames compare by colour): the one given, else min and max of the field over every
// frame, taken over the points of the cells that are coloured by it (or its 1st-99th
// percentiles with robust_range). Periodic runs are
// drawn over one period, bodies crossing the seam wrapped to both sides.
//
// The parts: series_extent.h (the box and the colour range), picture_layout.h (world to
// pixels), frame_drawing.h (the bodies), frame_decorations.h (title, scale and colour bars),
// frame_picture.h (the PNG file), colormap.h, movie.h (ffmpeg).
//
// field "coherence": each grain filled flat with the coherence C of paper 002 eq. 5 at its
// centre (bilinear between the grid nodes around it), computed from the grain snapshot
// grains/NNNNNN.csv that has the picture's number, with the grid and parameters of
// `softgrain analyze` (analysis/coherence_frames.h). Diverging colour map (Moreland's
// cool-warm), fixed range [-1, 1]: red counter-clockwise, blue clockwise (with the shear);
// dark grey where C is undefined (a pore, the layer's edge) and for non-grain bodies.
//
// fields "strain_rate" and "strain_rate_instant": the grains shaded by the nodal strain rate,
// and their outlines (grains and rigid bodies alike) coloured at each contact by the contact
// rate of contacts/NNNNNN.vtu with the same map (render/contact_outlines.h, io/contact_rate.h):
// deformation inside grains and between them in one picture. The contact rates count in the
// colour range. A run without contacts/ draws the grains only.
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "render/vtu_reader.h"

namespace sg {

struct RenderOptions {
  std::string field = "von_mises";                 // a point field of the .vtu, or velocity, body
  int width = 1200, height = 800;                  // pixels
  std::optional<std::pair<double, double>> range;  // colour range; unset: over all frames
  // Unset range: false = min and max over all frames; true = the 1st and 99th percentiles
  // of the coloured values over all frames (a few contact-node spikes otherwise squeeze
  // every grain into the bottom colour).
  bool robust_range = false;
  bool last_frame_only = false;
  std::optional<std::pair<double, double>> periodic;  // x span [x_min, x_max) if periodic
  std::string title;                                  // e.g. the run name
  bool movie = true;  // also an MP4 when ffmpeg is on PATH and every frame is drawn
  // For field "coherence": rows of grains/NNNNNN.csv that are not grains (report/analyze_run.h
  // non_grain_rows), and the mean grain diameter (NaN: from the first snapshot's areas).
  std::vector<std::string> non_grain_rows;
  double mean_diameter = std::numeric_limits<double>::quiet_NaN();
  // The unit of strain_rate and contact_rate, for the colour bar: "V/D" for a gap-loaded
  // shear cell, "1/time" otherwise (io/vtk_writer.h); empty: unknown.
  std::string strain_rate_unit;
};

struct RenderResult {
  bool has_range = false;  // false for the categorical "body" field
  double range_min = 0.0, range_max = 0.0;
  std::vector<std::filesystem::path> images;
  std::filesystem::path movie;  // empty if none was made
  std::string note;             // why there is no movie, etc.
};

// The fields `softgrain render --field` draws: the point arrays of our .vtu snapshots
// (io/vtk_writer.h; a vector array also by component, _x and _y), "body" and "coherence".
const std::vector<std::string>& render_field_choices();

// True for fields that are defined on rigid bodies too (velocity, displacement, body,
// coherence).
bool field_defined_on_rigid(const std::string& field);

// Reads RUN_DIR/fields.pvd and its snapshots; writes RUN_DIR/render/<field>_NNNNNN.png
// (NNNNNN the snapshot's number) and, if possible, RUN_DIR/render/<field>.mp4. Throws
// sg::Error naming the file for a missing or malformed input, or a bad option.
RenderResult render_run(const std::filesystem::path& run_dir, const RenderOptions& options);

}  // namespace sg
