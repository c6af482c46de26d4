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
// Which frames: every snapshot, or those in a time window (given, or the steady window of
// analysis/summary.json), and of those all or the last (render/frame_selection.h). The
// drawing box and the colour range follow the frames drawn, not every frame of the run: a
// picture of the steady layer is not shrunk to leave room for the loose initial state, nor
// coloured by the transients of the compaction. The colour range is one for the series drawn
// (so that a movie does not flicker and two frames compare by colour): given, else by the
// rules of render/colour_range.h (min-max of the coloured values, 1st-99th percentiles with
// robust_range, +-V/2 for the velocity of a shear cell, [-1, 1] for the coherence), on a
// linear or (log_scale) a logarithmic scale. The box fills the picture in its limiting
// direction; a periodic run is drawn over one period, bodies crossing the seam wrapped to both
// sides, and repeated beyond it when the picture is wider than the period
// (render/picture_layout.h).
//
// field "coherence": each grain filled flat with the coherence C of paper 002 eq. 5 at its
// centre (bilinear between the grid nodes around it), computed from the grain snapshot
// grains/NNNNNN.csv that has the picture's number, with the grid and parameters of
// `softgrain analyze` (analysis/coherence_frames.h). Diverging colour map (Moreland's
// cool-warm), fixed range [-1, 1]: red counter-clockwise, blue clockwise (with the shear);
// dark grey where C is undefined (a pore, the layer's edge) and for non-grain bodies.
//
// field "agglomerates": the filtered coherence of paper 002 Fig. 8B, from the same C: grains
// with C > threshold red (counter-clockwise), C < -threshold blue (clockwise), every other
// grain light grey, non-grain bodies dark grey; a legend instead of a colour bar.
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

#include "geometry/bounding_box.h"
#include "render/run_folder.h"
#include "render/vtu_reader.h"

namespace sg {

struct RenderOptions {
  std::string field = "von_mises";                 // a point field of the .vtu, or velocity, body
  int width = 1200, height = 800;                  // pixels
  std::optional<std::pair<double, double>> range;  // colour range; unset: colour_range.h
  // Unset range: false = min and max over the frames drawn; true = the 1st and 99th
  // percentiles of the coloured values over them (a few contact-node spikes otherwise squeeze
  // every grain into the bottom colour).
  bool robust_range = false;
  bool last_frame_only = false;
  // Draw only the snapshots whose time lies in [t0, t1] (with last_frame_only: the last of
  // them); steady_window: the window of RUN_DIR/analysis/summary.json (not with time_window).
  std::optional<std::pair<double, double>> time_window;
  bool steady_window = false;
  // Logarithmic colour scale, for fields >= 0 (field_is_nonnegative); values <= 0 or below the
  // range take the bottom colour.
  bool log_scale = false;
  // V of a shear cell (the first bodies slide at +-V/2): the default range of the velocity
  // fields (colour_range.h). Unset: not a shear cell, or V unknown.
  std::optional<double> shear_velocity;
  // For field "agglomerates": the |C| above which a grain is coloured (0 < threshold < 1; the
  // default of `softgrain analyze`, paper 002).
  double agglomerate_threshold = 0.8;
  std::optional<std::pair<double, double>> periodic;  // x span [x_min, x_max) if periodic
  std::string title;                                  // e.g. the run name
  bool movie = true;  // also an MP4 when ffmpeg is on PATH and more than one frame is drawn
  // For fields "coherence" and "agglomerates": rows of grains/NNNNNN.csv that are not grains
  // (report/analyze_run.h non_grain_rows), and the mean grain diameter (NaN: from the first
  // snapshot's areas).
  std::vector<std::string> non_grain_rows;
  double mean_diameter = std::numeric_limits<double>::quiet_NaN();
  // The unit of strain_rate and contact_rate, for the colour bar: "V/D" for a gap-loaded
  // shear cell, "1/time" otherwise (io/vtk_writer.h); empty: unknown.
  std::string strain_rate_unit;
};

struct RenderResult {
  bool has_range = false;  // false for the categorical "body" field and "agglomerates"
  double range_min = 0.0, range_max = 0.0;
  std::string range_source;  // where the range came from: "given", "min-max over ..."
  double first_time = 0.0, last_time = 0.0;  // of the frames drawn
  // The part of the world the pictures show (their box with its margin; a periodic layer's box
  // widened to fill the picture: render/picture_layout.h).
  BoundingBox world;
  std::vector<std::filesystem::path> images;
  std::filesystem::path movie;  // empty if none was made
  std::string note;             // why there is no movie, etc.
};

// The fields `softgrain render --field` draws: the point arrays of our .vtu snapshots
// (io/vtk_writer.h; a vector array also by component, _x and _y), "body", "coherence" and
// "agglomerates".
const std::vector<std::string>& render_field_choices();

// True for fields that are defined on rigid bodies too (velocity, displacement, body,
// coherence, agglomerates).
bool field_defined_on_rigid(const std::string& field);

// True for the fields that are never negative (the magnitudes, norms, rates and von Mises):
// those a log colour scale can draw.
bool field_is_nonnegative(const std::string& field);

// What the run's scenario tells the pictures (run.has_scenario): the periodic span, the title,
// the strain rate's unit as the run normalized it (io/vtk_writer.h global_strain_rate) and,
// for a shear cell, V (its first bodies slide at +-V/2: the velocity fields' default range).
void set_from_run(RenderOptions& options, const RunInfo& run);

// Reads RUN_DIR/fields.pvd and the snapshots drawn; writes RUN_DIR/render/<field>_NNNNNN.png
// (NNNNNN the snapshot's number) and, if possible, RUN_DIR/render/<field>.mp4. Throws
// sg::Error naming the file for a missing or malformed input, or a bad option.
RenderResult render_run(const std::filesystem::path& run_dir, const RenderOptions& options);

}  // namespace sg
