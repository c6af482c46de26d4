#include "analysis/agglomerates.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "core/error.h"

namespace sg {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

// Nearest grid node of a point, x periodic; -1 if y is outside the grid by more than half
// a cell (a grain in a roughness valley, beyond the analysed layer).
long nearest_node(const RegularGrid& g, const Vec2& p) {
  const double fi = (p.x() - g.x0) / g.hx;
  const double fj = (p.y() - g.y0) / g.hy;
  const int j = static_cast<int>(std::lround(fj));
  if (j < 0 || j >= g.ny) return -1;
  const int i = g.wrap_i(static_cast<int>(std::lround(std::fmod(fi, static_cast<double>(g.nx)))));
  return static_cast<long>(g.index(i, j));
}

}  // namespace

double cluster_angular_velocity(std::span<const Vec2> positions, std::span<const Vec2> velocities,
                                std::span<const double> areas, std::vector<double>* samples) {
  SG_VERIFY(positions.size() == velocities.size() && positions.size() == areas.size(),
            "angular velocity: " << positions.size() << " positions, " << velocities.size()
                                 << " velocities, " << areas.size() << " areas");
  if (positions.empty()) return kNan;
  // Barycentre and mean velocity with the same (area) weights: then for a rigid motion
  // v_i - v_bar = omega e_z x (x_i - x_bar) exactly, and every sample equals omega.
  double total = 0.0;
  Vec2 centre = Vec2::Zero(), mean_velocity = Vec2::Zero();
  for (std::size_t i = 0; i < positions.size(); ++i) {
    total += areas[i];
    centre += areas[i] * positions[i];
    mean_velocity += areas[i] * velocities[i];
  }
  centre /= total;
  mean_velocity /= total;
  double size = 0.0;
  for (const auto& p : positions)
    size = std::max(size, (p - centre).norm());
  double sum = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < positions.size(); ++i) {
    const Vec2 r = positions[i] - centre;
    const double radius = r.norm();
    if (radius <= 1e-12 * size || radius == 0.0) continue;
    // Circumferential component of the relative velocity: along e_z x r / |r|.
    const double v_circ = cross(r, velocities[i] - mean_velocity) / radius;
    const double sample = v_circ / radius;  // paper 002 eq. 6, one term
    sum += sample;
    ++n;
    if (samples) samples->push_back(sample);
  }
  return n > 0 ? sum / static_cast<double>(n) : kNan;
}

double WeightedPdf::mode() const {
  if (density.empty()) return kNan;
  const auto it = std::max_element(density.begin(), density.end());
  if (!(*it > 0.0)) return kNan;
  return centre[static_cast<std::size_t>(it - density.begin())];
}

WeightedPdf weighted_pdf(std::span<const double> values, std::span<const double> weights,
                         int bin_count, double lo, double hi) {
  SG_VERIFY(values.size() == weights.size(),
            "pdf: " << values.size() << " values, " << weights.size() << " weights");
  SG_VERIFY(bin_count >= 1 && hi > lo,
            "pdf: " << bin_count << " bins over [" << lo << ", " << hi << "]");
  WeightedPdf pdf;
  pdf.lo = lo;
  pdf.hi = hi;
  const auto nb = static_cast<std::size_t>(bin_count);
  const double width = (hi - lo) / bin_count;
  pdf.centre.resize(nb);
  pdf.density.assign(nb, 0.0);
  for (std::size_t b = 0; b < nb; ++b)
    pdf.centre[b] = lo + (static_cast<double>(b) + 0.5) * width;
  double inside = 0.0;
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (!std::isfinite(values[k]) || weights[k] <= 0.0) continue;
    if (values[k] < lo || values[k] > hi) {
      pdf.outside += weights[k];
      continue;
    }
    const auto b = std::min(nb - 1, static_cast<std::size_t>((values[k] - lo) / width));
    pdf.density[b] += weights[k];
    inside += weights[k];
  }
  if (inside > 0.0)
    for (auto& d : pdf.density)
      d /= inside * width;
  return pdf;
}

std::vector<Structure> measure_structure_extents(const SpaceTimeLabels& labels,
                                                 const std::vector<signed char>& sign,
                                                 const RegularGrid& grid, double frame_period) {
  SG_VERIFY(labels.nx == grid.nx && labels.ny == grid.ny && sign.size() == labels.label.size(),
            "structure extents: labels " << labels.nx << " x " << labels.ny << " for grid "
                                         << grid.nx << " x " << grid.ny);
  const std::size_t per_frame = grid.size();
  const int nt = labels.nt;
  std::vector<Structure> structures(static_cast<std::size_t>(labels.count));
  // Node counts per (structure, frame).
  std::vector<std::vector<std::size_t>> nodes_in_frame(
      structures.size(), std::vector<std::size_t>(static_cast<std::size_t>(nt), 0));
  for (std::size_t k = 0; k < labels.label.size(); ++k) {
    const int l = labels.label[k];
    if (l < 0) continue;
    const auto s = static_cast<std::size_t>(l);
    ++nodes_in_frame[s][k / per_frame];
    structures[s].sign = sign[k];
  }
  const double cell_area = grid.hx * grid.hy;
  for (std::size_t s = 0; s < structures.size(); ++s) {
    Structure& st = structures[s];
    st.first_frame = nt;
    st.last_frame = -1;
    std::size_t nodes = 0;
    for (int t = 0; t < nt; ++t) {
      const std::size_t count = nodes_in_frame[s][static_cast<std::size_t>(t)];
      if (count == 0) continue;
      st.first_frame = std::min(st.first_frame, t);
      st.last_frame = std::max(st.last_frame, t);
      ++st.frame_count;
      nodes += count;
    }
    st.lifetime = st.frame_count * frame_period;
    st.mean_area = static_cast<double>(nodes) * cell_area / st.frame_count;
    st.diameter = 2.0 * std::sqrt(st.mean_area / std::numbers::pi);  // paper 002 §3.4
  }
  return structures;
}

AgglomerateResult detect_agglomerates(std::span<const GrainSnapshot> snapshots,
                                      const RegularGrid& grid, const AgglomerateParams& params,
                                      double velocity, double gap) {
  SG_VERIFY(params.threshold > 0.0 && params.threshold < 1.0,
            "agglomerates: coherence threshold " << params.threshold << " outside (0, 1)");
  AgglomerateResult out;
  out.grid = grid;
  const int nt = static_cast<int>(snapshots.size());
  out.frame_period = nt >= 2 ? (snapshots.back().time - snapshots.front().time) / (nt - 1) : 1.0;
  SG_VERIFY(out.frame_period > 0.0, "agglomerates: snapshot times do not increase");

  // Coherence per frame, and its sign mask (paper 002 §2.2, |C| > 0.8).
  const std::size_t per_frame = grid.size();
  std::vector<signed char> sign(per_frame * static_cast<std::size_t>(nt), 0);
  out.coherence.reserve(snapshots.size());
  for (int t = 0; t < nt; ++t) {
    const VelocityGrid v = interpolate_velocity_grid(snapshots[static_cast<std::size_t>(t)], grid,
                                                     params.interpolation);
    out.coherence.push_back(compute_coherence(v, params.coherence));
    const CoherenceField& c = out.coherence.back();
    for (std::size_t n = 0; n < per_frame; ++n) {
      if (!c.defined[n]) continue;
      const std::size_t k = static_cast<std::size_t>(t) * per_frame + n;
      if (c.value[n] > params.threshold) sign[k] = 1;
      if (c.value[n] < -params.threshold) sign[k] = -1;
    }
  }
  out.labels = label_space_time(sign, grid.nx, grid.ny, nt);

  out.structures = measure_structure_extents(out.labels, sign, grid, out.frame_period);

  // Grains of each structure, frame by frame; angular velocity samples (eq. 6).
  std::vector<std::vector<double>> omega_samples(out.structures.size());
  for (int t = 0; t < nt; ++t) {
    const GrainSnapshot& snap = snapshots[static_cast<std::size_t>(t)];
    out.grain_samples += snap.size();
    std::vector<std::vector<std::size_t>> members(out.structures.size());
    for (std::size_t g = 0; g < snap.size(); ++g) {
      const long node = nearest_node(grid, snap.position[g]);
      if (node < 0) continue;
      const int l =
          out.labels
              .label[static_cast<std::size_t>(t) * per_frame + static_cast<std::size_t>(node)];
      if (l >= 0) members[static_cast<std::size_t>(l)].push_back(g);
    }
    for (std::size_t s = 0; s < members.size(); ++s) {
      if (members[s].empty()) continue;
      out.grain_samples_in_structures += members[s].size();
      out.structures[s].grain_samples += members[s].size();
      // Unwrap across the periodic seam relative to the first member, so that a structure
      // straddling x = x0 keeps a compact set of positions and a true barycentre.
      std::vector<Vec2> pos, vel;
      std::vector<double> area;
      const double x_ref = snap.position[members[s].front()].x();
      for (const std::size_t g : members[s]) {
        Vec2 p = snap.position[g];
        p.x() -= grid.length * std::round((p.x() - x_ref) / grid.length);
        pos.push_back(p);
        vel.push_back(snap.velocity[g]);
        area.push_back(snap.area[g]);
      }
      cluster_angular_velocity(pos, vel, area, &omega_samples[s]);
    }
  }
  const double shear_rate = -velocity / gap;  // paper 002 eq. 7, signed: the cell turns clockwise
  for (std::size_t s = 0; s < out.structures.size(); ++s) {
    Structure& st = out.structures[s];
    const auto& w = omega_samples[s];
    if (w.empty()) {
      st.omega = kNan;
    } else {
      double sum = 0.0;
      for (const double x : w)
        sum += x;
      st.omega = sum / static_cast<double>(w.size());
    }
    st.omega_normalized =
        std::isfinite(shear_rate) && shear_rate != 0.0 ? st.omega / shear_rate : kNan;
  }
  out.grain_share = out.grain_samples > 0 ? static_cast<double>(out.grain_samples_in_structures) /
                                                static_cast<double>(out.grain_samples)
                                          : 0.0;
  return out;
}

}  // namespace sg
