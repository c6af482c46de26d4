#include "render/snapshot_renderer.h"

#include <cmath>
#include <limits>

#include "analysis/coherence_frames.h"
#include "core/error.h"
#include "core/file_name.h"
#include "render/contact_outlines.h"
#include "render/frame_picture.h"
#include "render/movie.h"
#include "render/picture_layout.h"
#include "render/series_extent.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

// Coherence at each grain's centre, per frame, indexed by body id (NaN for bodies without
// a grain row or where C is undefined): the numbers the "coherence" pictures show
// (analysis/coherence_frames.h), from the grain snapshots with the pictures' numbers.
std::vector<std::vector<double>> grain_coherence_by_frame(const fs::path& run_dir,
                                                          const std::vector<PvdEntry>& entries,
                                                          const RenderOptions& options,
                                                          std::string& note) {
  std::vector<GrainSnapshot> snaps;
  for (const PvdEntry& e : entries) {
    const fs::path csv = run_dir / "grains" / (e.file.stem().string() + ".csv");
    SG_VERIFY(fs::exists(csv), "render --field coherence: '"
                                   << csv.string() << "' is missing (the grain snapshot of '"
                                   << e.file.filename().string() << "')");
    snaps.push_back(
        without_bodies(read_grain_snapshot(csv.string(), e.time), options.non_grain_rows));
  }
  double diameter = options.mean_diameter;
  for (std::size_t k = 0; !(diameter > 0.0) && k < snaps.size(); ++k)
    diameter = mean_equivalent_diameter(snaps[k]);
  SG_VERIFY(diameter > 0.0,
            "render --field coherence: no grain in " << (run_dir / "grains").string());
  GrainCoherence coherence = grain_coherence(snaps, diameter, options.periodic);
  note = "coherence grid: " + coherence.note;
  return std::move(coherence.by_body);
}

// Adds the point array "coherence" to a mesh: each point gets its body's value.
void add_coherence_array(VtuMesh& m, const std::vector<double>& by_body) {
  const std::vector<double> body = point_scalar(m, "body_id");
  VtuArray a;
  a.name = "coherence";
  a.values.resize(m.points.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t p = 0; p < body.size(); ++p) {
    const long id = std::lround(body[p]);
    if (id >= 0 && static_cast<std::size_t>(id) < by_body.size())
      a.values[p] = by_body[static_cast<std::size_t>(id)];
  }
  m.point_data.push_back(std::move(a));
}

void add_note(RenderResult& result, const std::string& n) {
  result.note += (result.note.empty() ? "" : "; ") + n;
}

// The movie (render/movie.h), when asked for and there is more than one frame.
void make_movie(const std::vector<PvdEntry>& entries, const RenderOptions& options,
                const fs::path& out_dir, RenderResult& result) {
  if (!options.movie) return;
  if (result.images.size() < 2) {
    add_note(result, "one frame: no movie");
    return;
  }
  const Movie movie = encode_movie(out_dir, options.field, entries.front().file.stem().string());
  result.movie = movie.file;
  if (!movie.note.empty()) add_note(result, movie.note);
}

}  // namespace

const std::vector<std::string>& render_field_choices() {
  static const std::vector<std::string> choices = {"von_mises",
                                                   "velocity",
                                                   "velocity_x",
                                                   "velocity_y",
                                                   "body",
                                                   "coherence",
                                                   "green_lagrange_norm",
                                                   "strain_rate",
                                                   "strain_rate_instant",
                                                   "pressure",
                                                   "sigma_xx",
                                                   "sigma_yy",
                                                   "sigma_xy",
                                                   "displacement",
                                                   "displacement_x",
                                                   "displacement_y",
                                                   "body_id",
                                                   "material_id"};
  return choices;
}

bool field_defined_on_rigid(const std::string& field) {
  return field.rfind("velocity", 0) == 0 || field.rfind("displacement", 0) == 0 ||
         field == "body" || field == "body_id" || field == "coherence";
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
}

}  // namespace

RenderResult render_run(const fs::path& run_dir, const RenderOptions& options) {
  check_options(options);
  const fs::path pvd = run_dir / "fields.pvd";
  SG_VERIFY(fs::exists(pvd), "'" << run_dir.string() << "' has no fields.pvd: not a run folder, "
                                 << "or the run wrote no field snapshot");
  const std::vector<PvdEntry> entries = read_pvd(pvd);
  SG_VERIFY(!entries.empty(), pvd.string() << ": no snapshot listed");

  Style style;
  style.field = options.field;
  style.rate_unit = options.strain_rate_unit;
  style.categorical = options.field == "body" || options.field == "body_id";
  const bool coherence = options.field == "coherence";
  style.diverging = coherence;
  style.periodic = options.periodic;
  style.title = options.title;

  // Pass 1: the drawing box and the colour range, fixed for the series.
  SeriesExtent extent = measure_series(entries, style, options, pvd);
  RenderResult result;
  std::vector<std::vector<double>> coherence_by_frame;
  if (coherence)
    coherence_by_frame = grain_coherence_by_frame(run_dir, entries, options, result.note);
  if (!style.categorical) choose_range(extent, style, options, result);
  const Layout layout =
      make_layout(options.width, options.height,
                  with_margin(extent.world, options.periodic.has_value()), !style.categorical);

  // Pass 2: the pictures.
  require_plain_file_name(options.field, "render --field (names its pictures)");
  const fs::path out_dir = run_dir / "render";
  fs::create_directories(out_dir);
  const std::size_t first = options.last_frame_only ? entries.size() - 1 : 0;
  for (std::size_t i = first; i < entries.size(); ++i) {
    VtuMesh m = read_vtu(entries[i].file);
    if (coherence) add_coherence_array(m, coherence_by_frame[i]);
    const std::string number = entries[i].file.stem().string();
    Frame frame{&m, entries[i].time, number, {}};
    if (field_shows_contact_rates(options.field))
      frame.contact_value =
          contact_rates_on_points(entries[i].file, m.points.size(), extent.contact_note);
    const fs::path png = out_dir / (options.field + "_" + number + ".png");
    write_png(layout, style, frame, png);
    result.images.push_back(png);
  }
  if (!extent.contact_note.empty()) add_note(result, extent.contact_note);
  make_movie(entries, options, out_dir, result);
  return result;
}

}  // namespace sg
