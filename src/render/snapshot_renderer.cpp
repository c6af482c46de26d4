#include "render/snapshot_renderer.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "core/file_name.h"
#include "render/coherence_arrays.h"
#include "render/colour_range.h"
#include "render/contact_outlines.h"
#include "render/frame_picture.h"
#include "render/frame_selection.h"
#include "render/movie.h"
#include "render/picture_layout.h"
#include "render/series_extent.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

void add_note(RenderResult& result, const std::string& n) {
  result.note += (result.note.empty() ? "" : "; ") + n;
}

// The movie (render/movie.h), when asked for and there is more than one frame.
void make_movie(const std::vector<PvdEntry>& frames, const RenderOptions& options,
                const fs::path& out_dir, RenderResult& result) {
  if (!options.movie) return;
  if (result.images.size() < 2) {
    add_note(result, "one frame: no movie");
    return;
  }
  const Movie movie =
      encode_movie(out_dir, options.field, frames.front().file.stem().string(), frames.size());
  result.movie = movie.file;
  if (!movie.note.empty()) add_note(result, movie.note);
}

}  // namespace

const std::vector<std::string>& render_field_choices() {
  static const std::vector<std::string> choices = {"von_mises",      "velocity",
                                                   "velocity_x",     "velocity_y",
                                                   "body",           "coherence",
                                                   "agglomerates",   "green_lagrange_norm",
                                                   "strain_rate",    "strain_rate_instant",
                                                   "pressure",       "sigma_xx",
                                                   "sigma_yy",       "sigma_xy",
                                                   "displacement",   "displacement_x",
                                                   "displacement_y", "body_id",
                                                   "material_id"};
  return choices;
}

bool field_defined_on_rigid(const std::string& field) {
  return field.rfind("velocity", 0) == 0 || field.rfind("displacement", 0) == 0 ||
         field == "body" || field == "body_id" || field_from_grain_snapshots(field);
}

bool field_is_nonnegative(const std::string& field) {
  static const std::vector<std::string> fields = {"von_mises",    "velocity",
                                                  "strain_rate",  "strain_rate_instant",
                                                  "displacement", "green_lagrange_norm"};
  return std::find(fields.begin(), fields.end(), field) != fields.end();
}

namespace {

void check_options(const RenderOptions& options) {
  SG_VERIFY(options.width >= 64 && options.height >= 64 && options.width <= 16384 &&
                options.height <= 16384,
            "render: picture size " << options.width << "x" << options.height
                                    << " outside 64..16384 pixels");
  if (options.range)
    SG_VERIFY(options.range->second > options.range->first,
              "render: --range " << options.range->first << " " << options.range->second
                                 << ": MAX must exceed MIN");
  if (options.log_scale) {
    std::string fields;
    for (const std::string& f : render_field_choices())
      if (field_is_nonnegative(f)) fields += (fields.empty() ? "" : ", ") + f;
    SG_VERIFY(field_is_nonnegative(options.field),
              "render --log: field '" << options.field
                                      << "' is signed or categorical; a log scale draws fields "
                                         "that are never negative: "
                                      << fields);
    if (options.range)
      SG_VERIFY(options.range->first > 0.0,
                "render --log: --range " << options.range->first << " " << options.range->second
                                         << ": MIN must be positive on a log scale");
  }
  if (options.field == "agglomerates")
    SG_VERIFY(options.agglomerate_threshold > 0.0 && options.agglomerate_threshold < 1.0,
              "render --threshold " << options.agglomerate_threshold
                                    << ": expected a |C| strictly between 0 and 1");
  SG_VERIFY(!(options.steady_window && options.time_window),
            "render: the analysed window and a given time window exclude each other");
  if (options.time_window)
    SG_VERIFY(options.time_window->second >= options.time_window->first,
              "render: time window [" << options.time_window->first << ", "
                                      << options.time_window->second << "]: the end is before "
                                      << "the start");
}

Style style_for(const RenderOptions& options) {
  Style style;
  style.field = options.field;
  style.rate_unit = options.strain_rate_unit;
  style.categorical = options.field == "body" || options.field == "body_id";
  style.diverging = options.field == "coherence";
  style.agglomerates = options.field == "agglomerates";
  style.threshold = options.agglomerate_threshold;
  style.periodic = options.periodic;
  style.title = options.title;
  return style;
}

}  // namespace

void set_from_run(RenderOptions& options, const RunInfo& run) {
  options.periodic = run.periodic;
  options.title = run.name;
  const double velocity = run.parameters.velocity;
  const bool gap_loaded_shear =
      run.shear_cell && std::isfinite(run.parameters.gap) && velocity > 0.0;
  options.strain_rate_unit = gap_loaded_shear ? "V/D" : "1/time";
  if (run.shear_cell && velocity > 0.0) options.shear_velocity = velocity;
}

RenderResult render_run(const fs::path& run_dir, const RenderOptions& options) {
  check_options(options);
  const fs::path pvd = run_dir / "fields.pvd";
  SG_VERIFY(fs::exists(pvd), "'" << run_dir.string() << "' has no fields.pvd: not a run folder, "
                                 << "or the run wrote no field snapshot");
  const std::vector<PvdEntry> entries = read_pvd(pvd);
  SG_VERIFY(!entries.empty(), pvd.string() << ": no snapshot listed");
  const std::vector<PvdEntry> frames =
      select_frames(entries, options.steady_window ? analysed_window(run_dir) : options.time_window,
                    options.last_frame_only, pvd);

  Style style = style_for(options);
  // Pass 1: the drawing box and the colour range of the frames drawn.
  SeriesExtent extent = measure_series(frames, style, options, pvd);
  RenderResult result;
  result.first_time = frames.front().time;
  result.last_time = frames.back().time;
  GrainCoherenceFrames grain_values;
  if (field_from_grain_snapshots(options.field)) {
    grain_values = grain_coherence_frames(run_dir, frames, options);
    add_note(result, grain_values.note);
    if (style.agglomerates)
      add_note(result, agglomerate_share_note(grain_values, options.agglomerate_threshold));
  }
  if (!style.categorical && !style.agglomerates) choose_range(extent, style, options, result);
  const bool periodic = options.periodic.has_value();
  const Layout layout =
      make_layout(options.width, options.height, with_margin(extent.world, periodic),
                  !style.categorical, periodic);
  result.world = layout.world;

  // Pass 2: the pictures.
  require_plain_file_name(options.field, "render --field (names its pictures)");
  const fs::path out_dir = run_dir / "render";
  fs::create_directories(out_dir);
  for (std::size_t i = 0; i < frames.size(); ++i) {
    VtuMesh m = read_vtu(frames[i].file);
    if (field_from_grain_snapshots(options.field)) add_grain_array(m, grain_values, i, options);
    const std::string number = frames[i].file.stem().string();
    Frame frame{&m, frames[i].time, number, {}};
    if (field_shows_contact_rates(options.field))
      frame.contact_value =
          contact_rates_on_points(frames[i].file, m.points.size(), extent.contact_note);
    const fs::path png = out_dir / (options.field + "_" + number + ".png");
    write_png(layout, style, frame, png);
    result.images.push_back(png);
  }
  if (!extent.contact_note.empty()) add_note(result, extent.contact_note);
  make_movie(frames, options, out_dir, result);
  return result;
}

}  // namespace sg
