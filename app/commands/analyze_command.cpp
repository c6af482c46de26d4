// softgrain analyze RUN_DIR: friction, energy budget, profiles, solid fraction and
// agglomerates of a run folder, the compaction curve of a compaction box ->
// RUN_DIR/analysis/summary.json, profiles.csv, compaction.csv, a table.
#include <iostream>

#include "command_registry.h"
#include "core/exit_status.h"
#include "io/run_directory.h"
#include "render/composite_snapshots.h"
#include "render/plot_runner.h"
#include "report/analyze_run.h"

namespace sg::app {
namespace {

struct AnalyzeArguments {
  std::string run_dir;
  std::vector<double> window, layer;
  double length = RunParameters::kUnknown, gap = RunParameters::kUnknown,
         velocity = RunParameters::kUnknown, young = RunParameters::kUnknown,
         cohesion = RunParameters::kUnknown, alpha = RunParameters::kUnknown,
         diameter = RunParameters::kUnknown;
  int bins = 0;
  bool no_agglomerates = false;
  double threshold = 0.8;
  std::vector<double> att_thresholds;
  double stress_imbalance = SteadinessThresholds{}.stress_imbalance;
  bool plots = false, no_plots = false;
};

// The composite figure's snapshots (render/composite_snapshots.h) as plot_run.py's
// arguments: --snapshot FIELD=PNG for each picture, --snapshot-note TEXT for each failure.
std::vector<std::string> composite_arguments(const std::string& run_dir) {
  const CompositeSnapshots snapshots = render_composite_snapshots(run_dir);
  std::vector<std::string> arguments;
  for (const auto& [field, png] : snapshots.pictures) {
    arguments.push_back("--snapshot");
    arguments.push_back(field + "=" + png.string());
  }
  for (const std::string& note : snapshots.notes) {
    arguments.push_back("--snapshot-note");
    arguments.push_back(note);
  }
  return arguments;
}

// Runs scripts/plot_run.py (render/plot_runner.h), after drawing the snapshots of its
// composite figure. Asked for (--plots) and impossible is an error; by default, a missing
// matplotlib or script is only reported.
int draw_plots(const std::string& run_dir, bool asked) {
  if (!python_has_matplotlib()) {
    std::cout << "plots: skipped: " << kPlotPython
              << " with matplotlib and numpy not found (Debian: apt-get install "
                 "python3-matplotlib python3-numpy)\n";
    return asked ? 1 : 0;
  }
  std::vector<std::filesystem::path> tried;
  const auto script = find_plot_script(current_executable(), &tried);
  if (!script) {
    std::cout << "plots: skipped: plot_run.py not found (tried";
    for (const auto& t : tried)
      std::cout << " " << t.string();
    std::cout << ")\n";
    return asked ? 1 : 0;
  }
  const int status = run_plot_script(*script, run_dir, composite_arguments(run_dir));
  if (status != 0)
    std::cout << "plots: " << script->string() << " failed (exit status " << status << ")\n";
  return status == 0 ? 0 : 1;
}

const Registration registration(
    {"analyze",
     [](CLI::App& app, const GlobalOptions& options) {
       auto a = std::make_shared<AnalyzeArguments>();
       CLI::App* cmd = app.add_subcommand(
           "analyze",
           "Friction, energy budget, profiles, agglomerates of a run folder, the compaction "
           "curve of a compaction box; writes RUN_DIR/analysis/summary.json, profiles.csv, "
           "compaction.csv");
       cmd->add_option("run_dir", a->run_dir, "run folder (holds series.csv)")->required();
       cmd->add_option("--window", a->window,
                       "averaging window T0 T1 (default: MSER-5 steady state, or the whole run)")
           ->expected(2);
       cmd->add_option("--length", a->length, "L, period of the cell (default: scenario)");
       cmd->add_option("--gap", a->gap, "D, gap between the first bodies (default: scenario)");
       cmd->add_option("--velocity", a->velocity, "V, sliding velocity (default: scenario)");
       cmd->add_option("--young", a->young, "E of the grains (default: scenario)");
       cmd->add_option("--cohesion", a->cohesion, "c, cohesion (default: scenario)");
       cmd->add_option("--alpha", a->alpha, "alpha, Rayleigh damping (default: scenario)");
       cmd->add_option("--diameter", a->diameter,
                       "mean grain diameter (default: from grains/*.csv)");
       cmd->add_option("--layer", a->layer,
                       "layer bounds Y0 Y1 for profiles and solid fraction (default: grains)")
           ->expected(2);
       cmd->add_option("--bins", a->bins, "profile bins (default: two per mean diameter)");
       cmd->add_flag("--no-agglomerates", a->no_agglomerates, "skip the coherence analysis");
       cmd->add_option("--coherence-threshold", a->threshold,
                       "|C| above which a grid node belongs to a structure (paper 002: 0.8)")
           ->check(CLI::Range(0.0, 1.0).description("in (0, 1)"))
           ->capture_default_str();
       cmd->add_option("--att-thresholds", a->att_thresholds,
                       "shares of the velocity jump LO HI bounding the activated third-body "
                       "thickness (paper 003: 0.2 0.8)")
           ->expected(2);
       cmd->add_option("--stress-imbalance", a->stress_imbalance,
                       "warn when the top and bottom mean normal stresses differ by more than "
                       "this fraction of their mean (docs/analysis.md, steadiness checks)")
           ->check(CLI::PositiveNumber)
           ->capture_default_str();
       CLI::Option* plots = cmd->add_flag(
           "--plots", a->plots,
           "draw mu(t), profiles, energy shares, agglomerate PDFs, the compaction curve and, "
           "for a shear cell, the composite figure (the last frame's velocity, strain rate "
           "and stress, drawn into RUN_DIR/render/, beside mu(t), the profiles and the run's "
           "place in (E~, c~, alpha~)) into RUN_DIR/analysis/*.png "
           "(default: on when /usr/bin/python3 imports matplotlib)");
       cmd->add_flag("--no-plots", a->no_plots, "no plots")->excludes(plots);
       return std::function<int()>([a, &options] {
         apply_threads(options);
         AnalyzeOptions o;
         if (a->window.size() == 2) o.window = std::make_pair(a->window[0], a->window[1]);
         if (a->layer.size() == 2) o.layer = std::make_pair(a->layer[0], a->layer[1]);
         o.given.length = a->length;
         o.given.gap = a->gap;
         o.given.velocity = a->velocity;
         o.given.young_modulus = a->young;
         o.given.cohesion = a->cohesion;
         o.given.damping_alpha = a->alpha;
         o.given.mean_diameter = a->diameter;
         o.profile_bins = a->bins;
         o.agglomerates = !a->no_agglomerates;
         o.coherence_threshold = a->threshold;
         if (a->att_thresholds.size() == 2) o.att = {a->att_thresholds[0], a->att_thresholds[1]};
         o.steadiness.stress_imbalance = a->stress_imbalance;
         // analysis/ must be a real folder: nothing written through a link (io/run_directory.h).
         refuse_links_in_run_folder(a->run_dir);
         const AnalyzeResult r = analyze_run(a->run_dir, o);
         std::cout << format_summary_table(r.summary);
         if (r.compaction) std::cout << format_compaction_table(*r.compaction);
         std::cout << "\nparameters:\n";
         for (const ParameterSource& p : r.parameter_sources)
           std::cout << "  " << p.key << " = "
                     << (std::isfinite(p.value) ? std::to_string(p.value) : std::string("-"))
                     << "  (" << p.source << ")\n";
         if (!r.notes.empty()) {
           std::cout << "\nnotes:\n";
           for (const std::string& n : r.notes)
             std::cout << "  - " << n << "\n";
         }
         std::cout << "\nwritten: " << r.summary_path.string();
         for (const auto* path :
              {&r.profile_path, &r.agglomerates_path, &r.agglomerate_pdfs_path, &r.space_time_path,
               &r.cylinders_path, &r.att_path, &r.compaction_path})
           if (!path->empty()) std::cout << ", " << path->filename().string();
         std::cout << "\n";
         const int plot_status = a->no_plots ? 0 : draw_plots(a->run_dir, a->plots);
         // The window's failed steadiness checks (analysis/steadiness.h), where they are seen.
         if (!r.summary.warnings.empty()) {
           std::cout << "\nWARNINGS (the window is not steady; the averages are suspect):\n";
           for (const SteadinessWarning& w : r.summary.warnings)
             std::cout << "  - " << w.check << ": " << w.message << "\n";
         }
         // Last, where it is seen: what the run asks for and did not give (exit status 3).
         for (const Unmeasured& u : r.unmeasured)
           std::cout << "\nNOT MEASURED: " << u.quantity << ": " << u.reason << "\n";
         if (!r.unmeasured.empty()) {
           std::cout << "analyze: exit status " << kExitUnmeasured
                     << " (summary written without what is not measured)\n";
           return kExitUnmeasured;
         }
         return plot_status;
       });
     },
     30});

}  // namespace
}  // namespace sg::app
