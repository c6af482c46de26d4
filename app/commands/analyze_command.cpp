// softgrain analyze RUN_DIR: friction, energy budget, profiles, solid fraction and
// agglomerates of a run folder, the compaction curve of a compaction box ->
// RUN_DIR/analysis/summary.json, profiles.csv, compaction.csv, a table.
#include <iostream>

#include "analyze_options.h"
#include "command_registry.h"
#include "core/exit_status.h"
#include "io/run_directory.h"
#include "render/composite_snapshots.h"
#include "render/plot_runner.h"
#include "report/analyze_run.h"

namespace sg::app {
namespace {

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
       add_analyze_options(*cmd, *a);
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
           std::cout << "\nWARNINGS (the window is not steady or the ledger does not close; the "
                        "averages are suspect):\n";
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
