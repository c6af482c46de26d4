#include "render/coherence_arrays.h"

#include <cmath>
#include <cstdio>
#include <limits>

#include "analysis/coherence_frames.h"
#include "core/error.h"

namespace sg {

namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Which body numbers are grains in a snapshot (its rows, the non-grain rows removed);
// grain_coherence has checked that every row's body is a number.
std::vector<char> grain_bodies(const GrainSnapshot& snap) {
  std::vector<char> grain;
  for (const std::string& body : snap.body) {
    const auto id = static_cast<std::size_t>(std::stol(body));
    if (grain.size() <= id) grain.resize(id + 1, 0);
    grain[id] = 1;
  }
  return grain;
}

// The agglomerate view's class of a grain with coherence C (coherence_arrays.h).
double agglomerate_class(double c, double threshold) {
  if (c > threshold) return 1.0;
  if (c < -threshold) return -1.0;
  return 0.0;
}

template <class T>
T at_or(const std::vector<T>& v, long id, T otherwise) {
  return id >= 0 && static_cast<std::size_t>(id) < v.size() ? v[static_cast<std::size_t>(id)]
                                                            : otherwise;
}

}  // namespace

bool field_from_grain_snapshots(const std::string& field) {
  return field == "coherence" || field == "agglomerates";
}

GrainCoherenceFrames grain_coherence_frames(const fs::path& run_dir,
                                            const std::vector<PvdEntry>& frames,
                                            const RenderOptions& options) {
  std::vector<GrainSnapshot> snaps;
  for (const PvdEntry& e : frames) {
    const fs::path csv = run_dir / "grains" / (e.file.stem().string() + ".csv");
    SG_VERIFY(fs::exists(csv), "render --field " << options.field << ": '" << csv.string()
                                                 << "' is missing (the grain snapshot of '"
                                                 << e.file.filename().string() << "')");
    snaps.push_back(
        without_bodies(read_grain_snapshot(csv.string(), e.time), options.non_grain_rows));
  }
  double diameter = options.mean_diameter;
  for (std::size_t k = 0; !(diameter > 0.0) && k < snaps.size(); ++k)
    diameter = mean_equivalent_diameter(snaps[k]);
  SG_VERIFY(diameter > 0.0, "render --field " << options.field << ": no grain in "
                                              << (run_dir / "grains").string());
  GrainCoherence coherence = grain_coherence(snaps, diameter, options.periodic);
  GrainCoherenceFrames out;
  out.by_body = std::move(coherence.by_body);
  for (const GrainSnapshot& s : snaps)
    out.grain.push_back(grain_bodies(s));
  out.note = "coherence grid: " + coherence.note;
  return out;
}

void add_grain_array(VtuMesh& mesh, const GrainCoherenceFrames& c, std::size_t frame,
                     const RenderOptions& options) {
  const bool classes = options.field == "agglomerates";
  const std::vector<double> body = point_scalar(mesh, "body_id");
  VtuArray a;
  a.name = options.field;
  a.values.resize(mesh.points.size(), kNaN);
  for (std::size_t p = 0; p < body.size(); ++p) {
    const long id = std::lround(body[p]);
    const double coherence = at_or(c.by_body[frame], id, kNaN);
    if (!classes)
      a.values[p] = coherence;
    else if (at_or<char>(c.grain[frame], id, 0))
      a.values[p] = agglomerate_class(coherence, options.agglomerate_threshold);
  }
  mesh.point_data.push_back(std::move(a));
}

std::string agglomerate_share_note(const GrainCoherenceFrames& c, double threshold) {
  std::size_t grains = 0, marked = 0;
  for (std::size_t f = 0; f < c.grain.size(); ++f)
    for (std::size_t id = 0; id < c.grain[f].size(); ++id) {
      if (!c.grain[f][id]) continue;
      ++grains;
      const double coherence = at_or(c.by_body[f], static_cast<long>(id), kNaN);
      if (agglomerate_class(coherence, threshold) != 0.0) ++marked;
    }
  char text[200];
  std::snprintf(text, sizeof text,
                "grains with |C| > %g: %zu of %zu over the %zu frame%s drawn (%.1f%%)", threshold,
                marked, grains, c.grain.size(), c.grain.size() == 1 ? "" : "s",
                grains ? 100.0 * static_cast<double>(marked) / static_cast<double>(grains) : 0.0);
  return text;
}

}  // namespace sg
