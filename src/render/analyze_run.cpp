#include "render/analyze_run.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "analysis/agglomerate_statistics.h"
#include "analysis/driven_body.h"
#include "analysis/energy_budget.h"
#include "analysis/friction.h"
#include "analysis/grain_snapshot.h"
#include "analysis/series.h"
#include "analysis/steady_state.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "render/coherence_frames.h"
#include "render/run_folder.h"
#include "render/vtu_reader.h"

namespace sg {
namespace {

namespace fs = std::filesystem;
constexpr double kNan = RunParameters::kUnknown;

FrictionStats unknown_friction(const std::string& body) {
  FrictionStats s;
  s.body = body;
  s.normal_force = s.tangential_force = s.mu = s.mu_std = kNan;
  s.normal_stress = s.shear_stress = kNan;
  return s;
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// One run parameter: the option if given, else the run's value, else unknown.
double pick(AnalyzeResult& r, const std::string& key, const std::string& unit, double option,
            double from_run, const std::string& run_source) {
  ParameterSource p{key, kNan, unit, "unknown"};
  if (std::isfinite(option)) {
    p.value = option;
    p.source = "option";
  } else if (std::isfinite(from_run)) {
    p.value = from_run;
    p.source = run_source;
  }
  r.parameter_sources.push_back(p);
  return p.value;
}

struct Snapshots {
  std::vector<GrainSnapshot> all;  // grains only, time order
  std::size_t files = 0;
};

Snapshots read_snapshots(const fs::path& run_dir, const std::vector<std::string>& exclude,
                         std::vector<std::string>& notes) {
  Snapshots out;
  const fs::path dir = run_dir / "grains";
  if (!fs::is_directory(dir)) {
    notes.push_back("no grains/ folder: no velocity profile, solid fraction or agglomerates");
    return out;
  }
  std::map<std::string, double> time_of;  // snapshot number -> time, from fields.pvd
  if (fs::exists(run_dir / "fields.pvd"))
    for (const PvdEntry& e : read_pvd(run_dir / "fields.pvd"))
      time_of[e.file.stem().string()] = e.time;
  std::vector<fs::path> files;
  for (const auto& entry : fs::directory_iterator(dir))
    if (entry.path().extension() == ".csv") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  bool missing_time = false;
  for (const fs::path& f : files) {
    const auto t = time_of.find(f.stem().string());
    if (t == time_of.end()) {
      missing_time = true;
      continue;
    }
    out.all.push_back(without_bodies(read_grain_snapshot(f.string(), t->second), exclude));
    ++out.files;
  }
  if (missing_time)
    notes.push_back("some grains/*.csv have no time in fields.pvd and were skipped");
  std::sort(out.all.begin(), out.all.end(),
            [](const GrainSnapshot& a, const GrainSnapshot& b) { return a.time < b.time; });
  return out;
}

// A number for a CSV cell: full precision; empty for an unknown value.
std::string cell(double v) {
  if (!std::isfinite(v)) return "";
  std::ostringstream s;
  s << std::setprecision(12) << v;
  return s.str();
}

std::string structures_csv(const AgglomerateResult& a, std::span<const GrainSnapshot> frames) {
  std::ostringstream out;
  out << "id,sign,first_frame,last_frame,first_time,last_time,frames,lifetime,mean_area,"
         "diameter,grain_samples,omega,omega_tilde\n";
  for (std::size_t k = 0; k < a.structures.size(); ++k) {
    const Structure& st = a.structures[k];
    out << k << ',' << st.sign << ',' << st.first_frame << ',' << st.last_frame << ','
        << cell(frames[static_cast<std::size_t>(st.first_frame)].time) << ','
        << cell(frames[static_cast<std::size_t>(st.last_frame)].time) << ',' << st.frame_count
        << ',' << cell(st.lifetime) << ',' << cell(st.mean_area) << ',' << cell(st.diameter) << ','
        << st.grain_samples << ',' << cell(st.omega) << ',' << cell(st.omega_normalized) << '\n';
  }
  return out.str();
}

void append_pdf(std::ostringstream& out, const std::string& quantity, const WeightedPdf& pdf) {
  const double width =
      pdf.centre.empty() ? 0.0 : (pdf.hi - pdf.lo) / static_cast<double>(pdf.centre.size());
  for (std::size_t b = 0; b < pdf.centre.size(); ++b)
    out << quantity << ',' << cell(pdf.centre[b] - 0.5 * width) << ','
        << cell(pdf.centre[b] + 0.5 * width) << ',' << cell(pdf.density[b]) << '\n';
}

// Grain-weighted PDF of the lifetimes: one bin per whole number of frames (a lifetime is
// frames x period), centred on it.
WeightedPdf lifetime_pdf(const AgglomerateResult& a) {
  int most = 1;
  std::vector<double> life, weight;
  for (const Structure& st : a.structures) {
    most = std::max(most, st.frame_count);
    life.push_back(st.lifetime);
    weight.push_back(static_cast<double>(st.grain_samples));
  }
  const double T = a.frame_period;
  return weighted_pdf(life, weight, most, 0.5 * T, (most + 0.5) * T);
}

// Largest |C| over the defined nodes of every frame (0 if none): tells a reader how far
// from the threshold a run without structures is.
double largest_coherence(const AgglomerateResult& a) {
  double largest = 0.0;
  for (const CoherenceField& c : a.coherence)
    for (std::size_t n = 0; n < c.value.size(); ++n)
      if (c.defined[n]) largest = std::max(largest, std::abs(c.value[n]));
  return largest;
}

// Paper 002 §2.2-3.4 on the window's snapshots: coherence per snapshot, |C| > 0.8,
// space-time labels (x periodic), per-structure statistics, PDFs. Anything that cannot
// be computed leaves summary.agglomerates absent (null in the JSON) with a note.
void analyze_agglomerates(AnalyzeResult& r, std::span<const GrainSnapshot> frames,
                          const RunInfo& run, const AnalyzeOptions& options,
                          const fs::path& run_dir) {
  const RunParameters& p = r.parameters;
  if (!(p.mean_diameter > 0.0)) {
    r.notes.push_back("agglomerates null: mean grain diameter unknown (pass --diameter)");
    return;
  }
  // The period: the scenario's span, or [0, L) for a length given as an option.
  std::optional<std::pair<double, double>> period = run.periodic;
  if (std::isfinite(options.given.length)) {
    const double x0 = period ? period->first : 0.0;
    period = std::make_pair(x0, x0 + options.given.length);
  }
  try {
    CoherenceSetup setup = choose_coherence_setup(frames, p.mean_diameter, period, options.layer);
    setup.params.threshold = options.coherence_threshold;
    r.agglomerate_grid = setup.note;
    r.agglomerate_threshold = setup.params.threshold;
    if (frames.size() >= 3) {
      // Lifetimes count frames x the mean period: say so if the spacing is uneven.
      const double mean_dt =
          (frames.back().time - frames.front().time) / static_cast<double>(frames.size() - 1);
      double worst = 0.0;
      for (std::size_t k = 1; k < frames.size(); ++k)
        worst = std::max(worst, std::abs(frames[k].time - frames[k - 1].time - mean_dt));
      if (worst > 0.01 * mean_dt)
        r.notes.push_back("agglomerates: snapshot spacing uneven (up to " + number(worst) +
                          " off the mean " + number(mean_dt) + "); lifetimes use the mean spacing");
    }
    AgglomerateResult a = detect_agglomerates(frames, setup.grid, setup.params, p.velocity, p.gap);
    r.summary.agglomerates = compute_agglomerate_statistics(a, p.mean_diameter);
    if (!std::isfinite(p.velocity) || !std::isfinite(p.gap))
      r.notes.push_back("omega~ null: needs V and D (pass --velocity, --gap)");
    if (a.structures.empty())
      r.notes.push_back("agglomerates: no region with |C| > " + number(setup.params.threshold) +
                        " in the window (largest |C| " + number(largest_coherence(a)) +
                        "; modes and means null)");
    if (frames.size() == 1)
      r.notes.push_back("agglomerates: one snapshot in the window: lifetimes are one frame");
    std::ostringstream pdfs;
    pdfs << "quantity,bin_lo,bin_hi,density\n";
    append_pdf(pdfs, "omega_tilde", r.summary.agglomerates->omega_pdf);
    append_pdf(pdfs, "diameter", r.summary.agglomerates->diameter_pdf);
    append_pdf(pdfs, "lifetime", lifetime_pdf(a));
    r.agglomerates_path = run_dir / "analysis" / "agglomerates.csv";
    r.agglomerate_pdfs_path = run_dir / "analysis" / "agglomerate_pdfs.csv";
    write_file_atomically(r.agglomerates_path.string(), structures_csv(a, frames));
    write_file_atomically(r.agglomerate_pdfs_path.string(), pdfs.str());
    r.agglomerates = std::move(a);
  } catch (const Error& e) {
    r.summary.agglomerates.reset();
    r.agglomerates.reset();
    r.notes.push_back(std::string("agglomerates not computed: ") + e.what());
  }
}

// The compaction curve of a [compaction_box] run over every series.csv row; A(t) from the
// snapshots' grains (walls removed), else the generated grains' areas. A failure is a note.
void analyze_compaction(AnalyzeResult& r, const Series& series, const CompactionBoxGeometry& box,
                        std::span<const GrainSnapshot> snapshots, const fs::path& run_dir) {
  std::vector<GrainAreaSample> areas;
  for (const GrainSnapshot& snap : snapshots) {
    if (snap.size() == 0) continue;
    double area = 0.0;
    for (const double a : snap.area)
      area += a;
    areas.push_back({snap.time, area});
  }
  const std::string source =
      areas.empty()
          ? "the generated grains' contour areas, constant (no grains/*.csv: a deformable "
            "grain's change of area is not seen)"
          : "grains/*.csv: sum of the grains' current contour areas, linear in time between "
            "the " +
                std::to_string(areas.size()) + " snapshots";
  // The snapshots must hold the grains and only them: at t = 0 their area is the generated one.
  if (!areas.empty() && areas.front().time == 0.0 && std::isfinite(box.generated_grain_area) &&
      !(std::abs(areas.front().area - box.generated_grain_area) <= 1e-9 * box.generated_grain_area))
    r.notes.push_back("compaction: grains/*.csv at t = 0 hold grain area " +
                      number(areas.front().area) + ", the scenario's grains " +
                      number(box.generated_grain_area) + " (walls not told apart?)");
  try {
    CompactionCurve curve =
        compute_compaction_curve(series, box, areas, box.generated_grain_area, source);
    r.compaction_path = run_dir / "analysis" / "compaction.csv";
    write_compaction_csv(r.compaction_path.string(), curve);
    r.compaction = std::move(curve);
  } catch (const Error& e) {
    r.compaction.reset();
    r.compaction_path.clear();
    r.notes.push_back(std::string("compaction curve not computed: ") + e.what());
  }
}

std::string json_document(const AnalyzeResult& r, const fs::path& run_dir) {
  nlohmann::ordered_json doc = nlohmann::ordered_json::parse(
      summary_json(r.summary, r.compaction ? compaction_summary_entries(*r.compaction)
                                           : std::vector<SummaryEntry>{}));
  doc["run"] = fs::absolute(run_dir).lexically_normal().string();
  nlohmann::ordered_json params = nlohmann::ordered_json::object();
  for (const ParameterSource& p : r.parameter_sources) {
    nlohmann::ordered_json q;
    if (std::isfinite(p.value))
      q["value"] = p.value;
    else
      q["value"] = nullptr;
    q["unit"] = p.unit;
    q["source"] = p.source;
    params[p.key] = std::move(q);
  }
  doc["parameters"] = std::move(params);
  if (r.profile) {
    nlohmann::ordered_json prof;
    prof["file"] = "profiles.csv";
    prof["y_min"] = r.profile->y_min;
    prof["y_max"] = r.profile->y_max;
    prof["bins"] = r.profile->bins.size();
    prof["samples_outside"] = r.profile->outside;
    doc["profile"] = std::move(prof);
  }
  if (r.agglomerates) {
    const AgglomerateResult& a = *r.agglomerates;
    nlohmann::ordered_json ag;
    ag["structures_file"] = "agglomerates.csv";
    ag["pdfs_file"] = "agglomerate_pdfs.csv";
    ag["grid"] = r.agglomerate_grid;
    ag["grid_spacing"] = a.grid.hx;
    ag["mls_support_radius"] = 2.0 * r.parameters.mean_diameter;
    ag["coherence_radius"] = 2.5 * r.parameters.mean_diameter;
    ag["threshold"] = r.agglomerate_threshold;
    ag["frames"] = a.labels.nt;
    ag["frame_period"] = a.frame_period;
    ag["grain_samples"] = a.grain_samples;
    ag["grain_samples_in_structures"] = a.grain_samples_in_structures;
    ag["largest_abs_coherence"] = largest_coherence(a);
    if (r.summary.agglomerates) {
      ag["omega_tilde_pdf_outside"] = r.summary.agglomerates->omega_pdf.outside;
    }
    doc["agglomerates"] = std::move(ag);
  }
  if (r.compaction) {
    nlohmann::ordered_json c;
    c["file"] = "compaction.csv";
    c["rows"] = r.compaction->points.size();
    c["width"] = r.compaction->width;
    c["lid_thickness"] = r.compaction->lid_thickness;
    c["grain_area_source"] = r.compaction->area_source;
    doc["compaction"] = std::move(c);
  }
  doc["notes"] = r.notes;
  return doc.dump(2) + "\n";
}

}  // namespace

std::vector<std::string> non_grain_rows(const RunInfo& run,
                                        const std::vector<std::string>& driven_bodies) {
  std::vector<std::string> rows;
  if (!run.has_scenario) return rows;
  std::vector<std::string> not_grains(driven_bodies);
  not_grains.insert(not_grains.end(), run.walls.begin(), run.walls.end());
  if (run.shear_cell) {
    not_grains.push_back("top");
    not_grains.push_back("bottom");
  }
  // grains/*.csv number bodies in build order; the rows of the non-grains by index.
  for (std::size_t i = 0; i < run.body_names.size(); ++i)
    if (std::find(not_grains.begin(), not_grains.end(), run.body_names[i]) != not_grains.end())
      rows.push_back(std::to_string(i));
  return rows;
}

AnalyzeResult analyze_run(const fs::path& run_dir, const AnalyzeOptions& options) {
  AnalyzeResult r;
  std::vector<std::string>& notes = r.notes;
  const fs::path series_path = run_dir / "series.csv";
  if (!fs::exists(series_path) && fs::exists(run_dir / "series.csv.partial"))
    SG_THROW("'" << run_dir.string()
                 << "': only series.csv.partial: the run is still going or was interrupted");
  SG_VERIFY(fs::exists(series_path),
            "'" << run_dir.string() << "' has no series.csv: not a run folder");
  const Series series = read_series(series_path.string());
  SG_VERIFY(series.size() >= 2, series_path.string() << ": fewer than 2 rows, nothing to average");

  // --- Run parameters: options, then the scenario, then measured.
  const RunInfo run = read_run_info(run_dir);
  const std::string scenario_source = "scenario " + run.source.filename().string();
  const std::vector<std::string> exclude = non_grain_rows(run, series.body_names);
  if (run.has_scenario) {
    notes.insert(notes.end(), run.notes.begin(), run.notes.end());
  } else {
    notes.push_back(run.note +
                    ": run parameters only from options; walls cannot be told from "
                    "grains in grains/*.csv");
  }
  const RunParameters& sv = run.parameters;
  const RunParameters& g = options.given;
  RunParameters& p = r.parameters;
  p.length = pick(r, "length", "length", g.length, sv.length, scenario_source);
  p.gap = pick(r, "gap", "length", g.gap, sv.gap, scenario_source);
  p.velocity = pick(r, "velocity", "length/time", g.velocity, sv.velocity, scenario_source);
  p.young_modulus =
      pick(r, "young_modulus", "stress", g.young_modulus, sv.young_modulus, scenario_source);
  p.cohesion = pick(r, "cohesion", "force/length", g.cohesion, sv.cohesion, scenario_source);
  p.damping_alpha =
      pick(r, "damping_alpha", "time", g.damping_alpha, sv.damping_alpha, scenario_source);

  Snapshots snaps = read_snapshots(run_dir, exclude, notes);
  // Mean equivalent diameter 2 sqrt(A/pi) of the grains in the first snapshot.
  const double measured_diameter =
      snaps.all.empty() ? kNan : mean_equivalent_diameter(snaps.all.front());
  p.mean_diameter = pick(r, "mean_diameter", "length", g.mean_diameter, measured_diameter,
                         "grains/*.csv (mean 2 sqrt(area/pi), first snapshot)");

  // --- Compaction box: the curve over the whole run.
  if (run.compaction_box) {
    analyze_compaction(r, series, *run.compaction_box, snaps.all, run_dir);
  } else if (series.has(std::string(kCompactionLid) + "_fy")) {
    notes.push_back(
        "series.csv has a driven 'lid' but the run's scenario is not known as a "
        "[compaction_box]: no compaction curve");
  }

  // --- Driven bodies of the shear cell, window, friction.
  std::vector<DrivenBody> bodies;
  for (const DrivenBody& b : shear_cell_bodies())
    if (std::find(series.body_names.begin(), series.body_names.end(), b.name) !=
        series.body_names.end())
      bodies.push_back(b);
  const bool shear_cell = bodies.size() == 2;
  if (!shear_cell) {
    notes.push_back(
        "series.csv has no 'top' and 'bottom' columns (not a shear cell): no "
        "friction, stresses, E~ or c~");
    bodies.clear();
  }
  AnalysisSummary& s = r.summary;
  if (options.window) {
    s.window = window_from_times(series, options.window->first, options.window->second);
  } else if (shear_cell) {
    s.window = detect_steady_window(series, bodies);
  } else {
    s.window.first = 0;
    s.window.last = series.size() - 1;
    s.window.t_begin = series.column("time")[0];
    s.window.t_end = series.column("time")[series.size() - 1];
    s.window.detected = false;
    notes.push_back(
        "window: the whole run (no driven shear-cell body to detect a steady state "
        "on; pass --window T0 T1)");
  }
  if (s.window.truncation_at_limit)
    notes.push_back(
        "window: MSER's truncation hit half the series; the transient may not be "
        "over, the averages are suspect");
  s.friction.mean = unknown_friction("mean");
  if (shear_cell) {
    try {
      s.friction = compute_friction(series, bodies, s.window, p.length);
    } catch (const Error& e) {
      notes.push_back(std::string("friction not computed: ") + e.what());
      s.friction.bodies.clear();
      s.friction.mean = unknown_friction("mean");
    }
  }
  s.dimensionless = compute_dimensionless(p, s.friction.mean.normal_stress);
  if (std::isfinite(s.friction.mean.normal_stress)) {
    if (!std::isfinite(p.young_modulus)) notes.push_back("E~ null: E unknown (pass --young)");
    if (!(p.cohesion > 0.0)) notes.push_back("c~ null: cohesion unknown or 0");
  }
  if (!std::isfinite(s.dimensionless.viscosity)) {
    std::string missing;
    if (!std::isfinite(p.velocity)) missing += "V unknown; ";
    if (!std::isfinite(p.gap)) missing += "D unknown; ";
    notes.push_back("alpha~ null: needs alpha > 0, V and D (" + missing +
                    "alpha = " + number(p.damping_alpha) + ")");
  }

  try {
    s.energy = compute_energy_budget(series, s.window, s.friction.mean.mu,
                                     s.friction.mean.normal_force, p.velocity);
  } catch (const Error& e) {
    notes.push_back(std::string("energy budget not computed: ") + e.what());
  }

  // --- Grain snapshots of the window: profiles, solid fraction, agglomerates.
  std::vector<GrainSnapshot> window_snaps;
  const double eps = 1e-9 * std::max(1.0, std::abs(s.window.t_end));
  for (const GrainSnapshot& snap : snaps.all)
    if (snap.time >= s.window.t_begin - eps && snap.time <= s.window.t_end + eps && snap.size() > 0)
      window_snaps.push_back(snap);
  s.solid_fraction = kNan;
  if (window_snaps.empty()) {
    if (!snaps.all.empty())
      notes.push_back(
          "no grain snapshot inside the window: no profile, solid fraction or "
          "agglomerates");
  } else {
    double cy0 = INFINITY, cy1 = -INFINITY, ext0 = 0.0, ext1 = 0.0;
    for (const GrainSnapshot& snap : window_snaps) {
      double lo = INFINITY, hi = -INFINITY;
      for (std::size_t i = 0; i < snap.size(); ++i) {
        const double y = snap.position[i].y(), radius = std::sqrt(snap.area[i] / M_PI);
        cy0 = std::min(cy0, y);
        cy1 = std::max(cy1, y);
        lo = std::min(lo, y - radius);
        hi = std::max(hi, y + radius);
      }
      ext0 += lo;
      ext1 += hi;
    }
    ext0 /= static_cast<double>(window_snaps.size());
    ext1 /= static_cast<double>(window_snaps.size());
    // Profiles: over the given layer, else over the span of the grain centres.
    const double y0 = options.layer ? options.layer->first : cy0;
    const double y1 = options.layer ? options.layer->second : cy1;
    int bins = options.profile_bins;
    if (bins <= 0)
      bins =
          std::isfinite(p.mean_diameter) && p.mean_diameter > 0.0
              ? std::clamp(static_cast<int>(std::lround(2.0 * (y1 - y0) / p.mean_diameter)), 4, 200)
              : 20;
    try {
      r.profile = compute_velocity_profile(window_snaps, y0, y1, bins);
      r.profile_path = run_dir / "analysis" / "profiles.csv";
      write_velocity_profile_csv(r.profile_path.string(), *r.profile);
      if (!options.layer)
        notes.push_back("profile: " + std::to_string(bins) +
                        " bins over the span of the grain "
                        "centres [" +
                        number(y0) + ", " + number(y1) + "] (pass --layer)");
    } catch (const Error& e) {
      notes.push_back(std::string("velocity profile not computed: ") + e.what());
      r.profile.reset();
    }
    // Solid fraction: over L x layer; the layer from the grains' extent if not given.
    const double l0 = options.layer ? options.layer->first : ext0;
    const double l1 = options.layer ? options.layer->second : ext1;
    if (!std::isfinite(p.length)) {
      notes.push_back(run.compaction_box
                          ? "solid fraction null: a layer's, for periodic runs; the box's is "
                            "compaction_*_solid_fraction (analysis/compaction.csv)"
                          : "solid fraction null: L unknown (not a periodic run; pass --length)");
    } else {
      try {
        s.solid_fraction = mean_solid_fraction(window_snaps, p.length, l0, l1);
        if (!options.layer)
          notes.push_back("solid fraction over the grains' extent [" + number(l0) + ", " +
                          number(l1) +
                          "] (mean lowest grain bottom to highest grain top; the "
                          "papers use the rough surfaces' mean lines: pass --layer)");
      } catch (const Error& e) {
        notes.push_back(std::string("solid fraction not computed: ") + e.what());
      }
    }
    if (options.agglomerates)
      analyze_agglomerates(r, window_snaps, run, options, run_dir);
    else
      notes.push_back("agglomerates not computed (--no-agglomerates)");
  }
  r.summary_path = run_dir / "analysis" / "summary.json";
  write_file_atomically(r.summary_path.string(), json_document(r, run_dir));
  return r;
}

}  // namespace sg
