#include "report/sample_report.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>

#include "contact/contact_system.h"
#include "core/error.h"
#include "geometry/bounding_box.h"
#include "geometry/contour_gap.h"
#include "geometry/packing.h"
#include "geometry/rough_surface.h"
#include "geometry/size_distribution.h"
#include "io/atomic_file.h"
#include "io/vtk_writer.h"
#include "model/kinematics.h"
#include "solver/mass_scaling.h"
#include "solver/stable_time_step.h"

namespace sg {

namespace {

// The contour of body b at t = 0, from the current contour positions.
Polygon body_contour(const Model& model, const std::vector<Vec2>& positions, std::size_t b) {
  const Body& body = model.bodies[b];
  return Polygon(positions.begin() + body.contour_begin, positions.begin() + body.contour_end);
}

// The grains a builder generated, regenerated with its mixture and seed (generate_grains is
// deterministic), so their drawn sizes and components are known; empty for explicit grains.
std::vector<GrainDef> regenerated_grains(const ScenarioDef& s, MixtureDef& mixture) {
  const double h = s.discretization.mesh.spacing;
  if (const auto& box = s.compaction_box) {
    mixture = compaction_box_mixture(*box, h);
    return generate_grains(mixture, box->grains, box->seed);
  }
  if (const auto& cell = s.shear_cell) {
    mixture = shear_cell_mixture(*cell, h);
    return generate_grains(mixture, cell->grains, cell->seed);
  }
  return {};
}

double mean_of(const std::vector<double>& v) {
  double sum = 0.0;
  for (double x : v)
    sum += x;
  return v.empty() ? 0.0 : sum / static_cast<double>(v.size());
}

// Population standard deviation (the law's std is a population quantity).
double std_of(const std::vector<double>& v) {
  const double m = mean_of(v);
  double sum = 0.0;
  for (double x : v)
    sum += (x - m) * (x - m);
  return v.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(v.size()));
}

// The spectral slope of a first body's rough surface (its open contour, one period [x0,
// x0 + L) of evenly spaced points in some order): periodogram of the heights in x order, fit
// over every mode the generator fills (1 .. N/2 - 1: shear_cell builds its surfaces with the
// default band of geometry/rough_surface.h).
void measure_spectral_slope(const Polygon& surface, double period, double hurst,
                            SurfaceRoughness& g) {
  g.requested_hurst = hurst;
  g.expected_slope = -(1.0 + 2.0 * hurst);
  g.spectral_slope = g.measured_hurst = std::numeric_limits<double>::quiet_NaN();
  std::vector<Vec2> points(surface.begin(), surface.end());
  std::sort(points.begin(), points.end(),
            [](const Vec2& a, const Vec2& b) { return a.x() < b.x(); });
  const std::size_t n = points.size();
  g.points = static_cast<int>(n);
  if (n < 8) {
    g.slope_note = "fewer than 8 surface points: no spectrum";
    return;
  }
  const double dx = period / static_cast<double>(n);
  for (std::size_t j = 0; j < n; ++j)
    if (!(std::abs(points[j].x() - points[0].x() - static_cast<double>(j) * dx) <= 1e-9 * period)) {
      g.slope_note = "surface points not evenly spaced over one period: no spectrum";
      return;
    }
  std::vector<double> heights(n);
  for (std::size_t j = 0; j < n; ++j)
    heights[j] = points[j].y();
  const SpectralSlopeFit fit =
      fit_spectral_slope(periodogram(heights), 1, static_cast<int>(n / 2) - 1);
  g.spectral_slope = fit.slope;
  g.measured_hurst = fit.hurst();
  g.slope_min_mode = fit.min_mode;
  g.slope_max_mode = fit.max_mode;
}

std::string fixed(double v, int digits = 4) {
  std::ostringstream s;
  s << std::setprecision(digits) << v;
  return s.str();
}

}  // namespace

void measure_gaps(const Model& model, SampleReport& r) {
  std::vector<Vec2> positions;
  compute_contour_positions(model, positions);
  const std::size_t n = model.bodies.size();
  std::vector<Polygon> contours(n);
  std::vector<BoundingBox> boxes(n);
  std::vector<double> sizes;
  for (std::size_t b = 0; b < n; ++b) {
    contours[b] = body_contour(model, positions, b);
    boxes[b] = bounding_box(contours[b]);
    if (!model.bodies[b].open_contour) sizes.push_back(boxes[b].size().maxCoeff());
  }
  // Pairs whose boxes are farther apart than a typical body size cannot hold the smallest
  // gap of a packing (its grains touch to within a fraction of their size).
  std::sort(sizes.begin(), sizes.end());
  const double reach = sizes.empty() ? 1.0 : sizes[sizes.size() / 2];
  const double period = model.x_max - model.x_min;
  std::vector<double> shifts{0.0};
  if (model.periodic_x) shifts = {-period, 0.0, period};
  r.smallest_gap = std::numeric_limits<double>::infinity();
  r.overlapping_pairs = 0;
  double deepest = 0.0;
  const auto edges = [&](std::size_t b) {
    return ContourEdges{contours[b], model.bodies[b].open_contour, model.bodies[b].closing_shift_x};
  };
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = a + 1; b < n; ++b) {
      bool overlap = false;
      for (double shift : shifts) {
        const Vec2 d(shift, 0.0);
        if (boxes_apart(boxes[a], boxes[b].shifted(d), reach)) continue;
        // Exact: crossing edges, or a closed contour inside the other (containment).
        const bool closed = !model.bodies[a].open_contour && !model.bodies[b].open_contour;
        const bool inside = closed && contour_inside_other(contours[a], contours[b], d);
        if (inside || contour_edges_interfere(edges(a), edges(b), d, 0.0)) {
          overlap = true;
          // Depth: the farthest contour point of one body inside the other (closed contours).
          if (closed) deepest = std::max(deepest, overlap_depth(contours[a], contours[b], d));
          continue;
        }
        const double gap = contour_gap(edges(a), edges(b), d);
        if (gap < r.smallest_gap) {
          r.smallest_gap = gap;
          r.gap_body_a = model.bodies[a].name;
          r.gap_body_b = model.bodies[b].name;
        }
      }
      if (overlap) {
        if (r.overlapping_pairs == 0) {
          r.gap_body_a = model.bodies[a].name;
          r.gap_body_b = model.bodies[b].name;
        }
        ++r.overlapping_pairs;
      }
    }
  }
  if (r.overlapping_pairs > 0) r.smallest_gap = -deepest;
}

namespace {

// The grains (the builders' grain_<i> and the explicit [[grains]]) among the bodies, and
// their areas at t = 0 (0 for the other bodies).
std::vector<double> count_grains(const ScenarioDef& scenario, const Model& model,
                                 const std::vector<Vec2>& positions, SampleReport& r) {
  std::set<std::string> grain_names;
  for (const GrainSpec& g : scenario.grains)
    grain_names.insert(g.name);
  const int built = scenario.compaction_box ? scenario.compaction_box->grains
                    : scenario.shear_cell   ? scenario.shear_cell->grains
                                            : 0;
  for (int i = 0; i < built; ++i)
    grain_names.insert("grain_" + std::to_string(i));
  std::vector<double> body_area(model.bodies.size(), 0.0);
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    const bool rigid = body.kind == BodyKind::rigid;
    ++(rigid ? r.rigid_bodies : r.deformable_bodies);
    if (!grain_names.count(body.name)) {
      ++r.other_bodies;
      continue;
    }
    ++r.grains;
    ++(rigid ? r.rigid_grains : r.deformable_grains);
    body_area[b] = signed_area(body_contour(model, positions, b));
    r.grain_area += body_area[b];
  }
  return body_area;
}

int find_body(const Model& model, const std::string& name) {
  for (std::size_t b = 0; b < model.bodies.size(); ++b)
    if (model.bodies[b].name == name) return static_cast<int>(b);
  return -1;
}

// The container at t = 0, read off the built bodies; the shear cell's roughness.
void measure_container(const ScenarioDef& scenario, const Model& model,
                       const std::vector<Vec2>& positions, SampleReport& r) {
  auto contour_of = [&](const std::string& name) {
    const int b = find_body(model, name);
    SG_VERIFY(b >= 0, "sample: no body named '" << name << "'");
    return body_contour(model, positions, static_cast<std::size_t>(b));
  };
  if (scenario.compaction_box) {
    const BoundingBox bottom = bounding_box(contour_of("bottom"));
    const BoundingBox left = bounding_box(contour_of("left"));
    const BoundingBox right = bounding_box(contour_of("right"));
    const BoundingBox lid = bounding_box(contour_of("lid"));
    r.container_area = (right.lo.x() - left.hi.x()) * (lid.lo.y() - bottom.hi.y());
  } else if (scenario.shear_cell) {
    const Polygon bottom = contour_of("bottom"), top = contour_of("top");
    const double gap = mean_of([&] {
                         std::vector<double> y;
                         for (const Vec2& v : top)
                           y.push_back(v.y());
                         return y;
                       }()) -
                       mean_of([&] {
                         std::vector<double> y;
                         for (const Vec2& v : bottom)
                           y.push_back(v.y());
                         return y;
                       }());
    r.container_area = (model.x_max - model.x_min) * gap;
    // Roughness: RMS of each surface's heights about its mean (paper 001: RMS of the profile).
    for (const auto& [name, surface] : {std::pair{"bottom", bottom}, std::pair{"top", top}}) {
      std::vector<double> y;
      for (const Vec2& v : surface)
        y.push_back(v.y());
      SurfaceRoughness g;
      g.body = name;
      g.requested_rms = scenario.shear_cell->roughness_rms;
      g.measured_rms = std_of(y);
      try {
        measure_spectral_slope(surface, model.x_max - model.x_min, scenario.shear_cell->hurst, g);
      } catch (const Error& e) {
        g.slope_note = std::string("no spectrum: ") + e.what();
      }
      r.roughness.push_back(g);
    }
  }
}

// Sizes: requested law vs the generator's draws, per component.
void measure_sizes(const ScenarioDef& scenario, const Model& model,
                   const std::vector<double>& body_area, SampleReport& r) {
  MixtureDef mixture;
  const std::vector<GrainDef> grains = regenerated_grains(scenario, mixture);
  if (grains.empty()) {
    r.sizes_note = "explicit grains: no size law requested";
  } else {
    bool consistent = true;
    std::vector<std::vector<double>> drawn(mixture.components.size()),
        area_diameter(mixture.components.size());
    for (std::size_t i = 0; i < grains.size(); ++i) {
      const int b = find_body(model, "grain_" + std::to_string(i));
      const double area = b >= 0 ? body_area[static_cast<std::size_t>(b)] : 0.0;
      const double generated = signed_area(grains[i].contour);
      if (!(std::abs(area - generated) <= 1e-9 * generated)) consistent = false;
      const auto c = static_cast<std::size_t>(grains[i].component);
      drawn[c].push_back(grains[i].size);
      area_diameter[c].push_back(2.0 * std::sqrt(area / std::numbers::pi));
    }
    if (!consistent)
      r.sizes_note =
          "the regenerated grains differ from the built ones (areas): sizes not measured";
    for (std::size_t c = 0; consistent && c < mixture.components.size(); ++c) {
      const GrainComponentDef& def = mixture.components[c];
      ComponentSizes s;
      s.name = def.name;
      s.rigid = def.rigid;
      const bool ellipse = def.shape.kind == GrainShapeKind::ellipse;
      s.quantity = def.shape.kind == GrainShapeKind::disc ? "diameter"
                   : ellipse                              ? "long axis"
                                                          : "2 r_mean";
      // Ellipses: the long axis is the major-axis draw unless the ranges overlap and the
      // draws were swapped (grain_population.h), so the law's moments and KS distance are
      // exact only without overlap.
      const SizeRangeDef& law = ellipse ? def.shape.major_axis : def.shape.diameter;
      s.count = static_cast<int>(drawn[c].size());
      s.requested_mean = size_mean(law);
      s.requested_std = std::sqrt(size_variance(law));
      s.drawn_mean = mean_of(drawn[c]);
      s.drawn_std = std_of(drawn[c]);
      s.area_diameter_mean = mean_of(area_diameter[c]);
      s.ks_statistic = ks_statistic(drawn[c], law);
      s.ks_critical_5pct = ks_critical_value_5pct(drawn[c].size());
      r.sizes.push_back(s);
    }
  }
}

// Step, mass scaling and memory: as `softgrain info` computes them (app/commands/info).
void measure_step(const ScenarioDef& scenario, Model& model, SampleReport& r) {
  double contact_stiffness = 0.0;
  if (!scenario.contact_laws.empty())
    contact_stiffness =
        ContactSystem(model, contact_law_table(scenario), contact_settings(scenario))
            .max_stiffness();
  const IntegratorParams integrator = resolve_integrator(scenario, model, contact_stiffness).params;
  if (scenario.mass_scaling_step > 0.0)
    r.mass_scaling =
        describe(apply_mass_scaling(model, scenario.mass_scaling_step, scenario.time_step_safety,
                                    contact_stiffness, integrator),
                 model);
  const StableStep stable =
      estimate_stable_time_step(model, scenario.time_step_safety, contact_stiffness, integrator);
  r.stable_step = stable.dt;
  r.damping_limited = stable.damping_limited;
  if (stable.limiting_body >= 0) r.limiting_body = model.body(stable.limiting_body).name;
  if (stable.dt > 0.0) r.steps = static_cast<long>(scenario.duration / stable.dt);
  const double bytes = static_cast<double>(model.node_count()) * 12 * sizeof(double) +
                       static_cast<double>(model.gauss_rows.entries()) * (4 * sizeof(double) + 4) +
                       static_cast<double>(model.node_rows.entries()) * (4 * sizeof(double) + 4);
  r.memory_mib = bytes / 1048576.0;
}

}  // namespace

SampleReport measure_sample(const ScenarioDef& scenario, Model& model) {
  SampleReport r;
  r.name = scenario.name;
  r.builder = scenario.compaction_box ? "compaction_box"
              : scenario.shear_cell   ? "shear_cell"
                                      : "explicit";
  r.bodies = model.bodies.size();
  r.nodes = model.node_count();
  r.gauss_points = model.gauss_point_count();
  r.contour_points = model.contour_point_count();
  r.triangles = model.triangles.size();

  std::vector<Vec2> positions;
  compute_contour_positions(model, positions);
  const std::vector<double> body_area = count_grains(scenario, model, positions, r);
  measure_container(scenario, model, positions, r);
  if (r.container_area > 0.0) r.solid_fraction = r.grain_area / r.container_area;
  measure_sizes(scenario, model, body_area, r);
  measure_gaps(model, r);
  measure_step(scenario, model, r);
  return r;
}

std::string sample_json(const SampleReport& r) {
  using json = nlohmann::ordered_json;
  json doc;
  doc["format"] = "softgrain-sample";
  doc["version"] = 1;
  doc["name"] = r.name;
  doc["builder"] = r.builder;
  doc["counts"] = {{"bodies", r.bodies},
                   {"rigid_bodies", r.rigid_bodies},
                   {"deformable_bodies", r.deformable_bodies},
                   {"grains", r.grains},
                   {"rigid_grains", r.rigid_grains},
                   {"deformable_grains", r.deformable_grains},
                   {"other_bodies", r.other_bodies},
                   {"nodes", r.nodes},
                   {"gauss_points", r.gauss_points},
                   {"contour_points", r.contour_points},
                   {"triangles", r.triangles}};
  json packing;
  packing["grain_area"] = r.grain_area;
  packing["container_area"] = r.container_area > 0.0 ? json(r.container_area) : json(nullptr);
  packing["solid_fraction"] = r.container_area > 0.0 ? json(r.solid_fraction) : json(nullptr);
  const bool finite_gap = std::isfinite(r.smallest_gap);
  packing["smallest_gap"] = finite_gap ? json(r.smallest_gap) : json(nullptr);
  packing["smallest_gap_between"] = finite_gap || r.overlapping_pairs > 0
                                        ? json::array({r.gap_body_a, r.gap_body_b})
                                        : json(nullptr);
  packing["overlapping_pairs"] = r.overlapping_pairs;
  doc["packing"] = packing;
  json sizes = json::array();
  for (const ComponentSizes& s : r.sizes)
    sizes.push_back({{"component", s.name},
                     {"rigid", s.rigid},
                     {"quantity", s.quantity},
                     {"count", s.count},
                     {"requested_mean", s.requested_mean},
                     {"requested_std", s.requested_std},
                     {"drawn_mean", s.drawn_mean},
                     {"drawn_std", s.drawn_std},
                     {"area_diameter_mean", s.area_diameter_mean},
                     {"ks_statistic", s.ks_statistic},
                     {"ks_critical_5pct", s.ks_critical_5pct},
                     {"ks_pass", s.ks_statistic <= s.ks_critical_5pct}});
  doc["sizes"] = sizes;
  if (!r.sizes_note.empty()) doc["sizes_note"] = r.sizes_note;
  json rough = json::array();
  auto number_or_null = [](double v) { return std::isfinite(v) ? json(v) : json(nullptr); };
  for (const SurfaceRoughness& s : r.roughness) {
    json g = {{"body", s.body},
              {"requested_rms", s.requested_rms},
              {"measured_rms", s.measured_rms},
              {"points", s.points},
              {"spectral_slope", number_or_null(s.spectral_slope)},
              {"expected_slope", s.expected_slope},
              {"slope_modes", json::array({s.slope_min_mode, s.slope_max_mode})},
              {"measured_hurst", number_or_null(s.measured_hurst)},
              {"requested_hurst", s.requested_hurst}};
    if (!s.slope_note.empty()) g["slope_note"] = s.slope_note;
    rough.push_back(g);
  }
  doc["roughness"] = rough;
  doc["time_step"] = {{"stable_step", r.stable_step},
                      {"damping_limited", r.damping_limited},
                      {"limiting_body", r.limiting_body},
                      {"steps", r.steps}};
  if (!r.mass_scaling.empty()) doc["time_step"]["mass_scaling"] = r.mass_scaling;
  doc["memory_mib"] = r.memory_mib;
  return doc.dump(2) + "\n";
}

std::string sample_table(const SampleReport& r) {
  std::ostringstream s;
  s << "sample '" << r.name << "' (" << r.builder << ")\n"
    << "  bodies          " << r.bodies << " (" << r.rigid_bodies << " rigid, "
    << r.deformable_bodies << " deformable)\n"
    << "  grains          " << r.grains << " (" << r.rigid_grains << " rigid, "
    << r.deformable_grains << " deformable); walls / first bodies: " << r.other_bodies << "\n"
    << "  nodes           " << r.nodes << " field nodes, " << r.gauss_points << " Gauss points, "
    << r.contour_points << " contour points, " << r.triangles << " triangles\n";
  if (r.container_area > 0.0)
    s << "  solid fraction  " << fixed(r.solid_fraction) << " (grain area "
      << fixed(r.grain_area, 6) << " / container " << fixed(r.container_area, 6) << ")\n";
  if (r.overlapping_pairs > 0)
    s << "  OVERLAP         " << r.overlapping_pairs << " pairs of bodies overlap (first: '"
      << r.gap_body_a << "' and '" << r.gap_body_b << "', deepest " << -r.smallest_gap << ")\n";
  else if (std::isfinite(r.smallest_gap))
    s << "  smallest gap    " << fixed(r.smallest_gap) << " between '" << r.gap_body_a << "' and '"
      << r.gap_body_b << "' (no overlap)\n";
  if (!r.sizes.empty()) {
    s << "  sizes           component      quantity    count  requested mean/std  drawn mean/std"
         "  area-equiv. d  KS D (5% crit.)\n";
    for (const ComponentSizes& c : r.sizes)
      s << "                  " << std::left << std::setw(14)
        << (c.name + (c.rigid ? " (R)" : " (D)")) << " " << std::setw(11) << c.quantity << " "
        << std::right << std::setw(5) << c.count << "  " << std::setw(8) << fixed(c.requested_mean)
        << " / " << std::left << std::setw(7) << fixed(c.requested_std) << std::right << " "
        << std::setw(7) << fixed(c.drawn_mean) << " / " << std::left << std::setw(7)
        << fixed(c.drawn_std) << std::right << " " << std::setw(13) << std::left
        << fixed(c.area_diameter_mean) << std::right << "  " << fixed(c.ks_statistic, 3) << " ("
        << fixed(c.ks_critical_5pct, 3) << ")\n";
  }
  if (!r.sizes_note.empty()) s << "  sizes           " << r.sizes_note << "\n";
  for (const SurfaceRoughness& g : r.roughness) {
    s << "  roughness       " << g.body << ": RMS " << fixed(g.measured_rms) << " (requested "
      << fixed(g.requested_rms) << ")";
    if (std::isfinite(g.spectral_slope))
      s << ", spectral slope " << fixed(g.spectral_slope, 6)
        << " -> H = " << fixed(g.measured_hurst, 6) << " (requested " << fixed(g.requested_hurst)
        << ")";
    else
      s << ", " << g.slope_note;
    s << "\n";
  }
  s << "  stable step     " << r.stable_step << " ("
    << (r.damping_limited ? "damping-limited" : "wave-speed-limited") << ", body '"
    << r.limiting_body << "'), " << r.steps << " steps\n";
  if (!r.mass_scaling.empty()) s << "  " << r.mass_scaling << "\n";
  s << "  memory          " << fixed(r.memory_mib) << " MiB (node state and shape rows)\n";
  return s.str();
}

void write_sample(const Model& model, const SampleReport& report,
                  const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  write_vtu_snapshot(model, dir / "sample.vtu");
  write_file_atomically(dir / "sample.json", sample_json(report));
}

}  // namespace sg
