// softgrain render RUN_DIR: PNG snapshots of a field (and an MP4 when ffmpeg is present).
#include <algorithm>
#include <iostream>
#include <limits>
#include <optional>

#include "analysis/series.h"
#include "command_registry.h"
#include "core/error.h"
#include "core/nearest_name.h"
#include "io/run_directory.h"
#include "render/run_folder.h"
#include "render/snapshot_renderer.h"
#include "report/analyze_run.h"

namespace sg::app {
namespace {

struct RenderArguments {
  std::string run_dir;
  std::string field = "von_mises";
  std::string size = "1200x800";
  std::vector<double> range;
  std::string frames = "all";
  std::optional<double> from, to;
  bool no_movie = false;
  bool robust = false;
  bool log = false;
  std::optional<double> threshold;
};

std::pair<int, int> parse_size(const std::string& text) {
  const auto x = text.find('x');
  SG_VERIFY(x != std::string::npos, "--size '" << text << "': expected WxH, e.g. 1200x800");
  try {
    return {std::stoi(text.substr(0, x)), std::stoi(text.substr(x + 1))};
  } catch (const std::exception&) {
    SG_THROW("--size '" << text << "': expected WxH, e.g. 1200x800");
  }
}

// A misspelled field is answered before any snapshot is read, with the one meant and every
// choice (the .vtu's arrays alone would omit body and coherence).
const CLI::Validator field_choice(
    [](const std::string& field) -> std::string {
      const std::vector<std::string>& choices = render_field_choices();
      if (std::find(choices.begin(), choices.end(), field) != choices.end()) return "";
      return "unknown field '" + field + "'; nearest: '" + nearest_name(field, choices) +
             "'; the fields: " + join_names(choices);
    },
    "FIELD");

const Registration registration(
    {"render",
     [](CLI::App& app, const GlobalOptions&) {
       auto args = std::make_shared<RenderArguments>();
       CLI::App* cmd = app.add_subcommand(
           "render", "Draw PNG snapshots of a run's fields into RUN_DIR/render/");
       cmd->add_option("run_dir", args->run_dir, "run folder (holds fields.pvd)")->required();
       cmd->add_option("--field", args->field,
                       "von_mises | velocity | velocity_x | velocity_y | body | "
                       "green_lagrange_norm | strain_rate (increment of |E| over the output "
                       "interval, over V/D; contact rates on the outlines) | strain_rate_instant "
                       "| pressure | sigma_xx | sigma_yy | sigma_xy | displacement | "
                       "displacement_x | displacement_y | body_id | material_id | coherence "
                       "(paper 002 eq. 5 at each grain's centre, from grains/NNNNNN.csv; range "
                       "[-1, 1]) | agglomerates (grains with |C| > --threshold red (C > 0) or "
                       "blue (C < 0), others light grey: paper 002 Fig. 8B)")
           ->capture_default_str()
           ->check(field_choice);
       cmd->add_option("--size", args->size,
                       "picture size WxH in pixels (the drawing fills it; a periodic layer is "
                       "repeated beyond its period to fill a wide picture)")
           ->capture_default_str();
       cmd->add_option("--range", args->range,
                       "colour range MIN MAX (default: over the frames drawn; velocity of a "
                       "shear cell: +-V/2, speed 0..V/2)")
           ->expected(2);
       cmd->add_option("--frames", args->frames,
                       "all | last | window (the steady window of analysis/summary.json: run "
                       "`softgrain analyze` first); the drawing box and colour range follow "
                       "the frames drawn")
           ->check(CLI::IsMember({"all", "last", "window"}))
           ->capture_default_str();
       cmd->add_option("--from", args->from, "draw only the snapshots at time >= T")
           ->type_name("T");
       cmd->add_option("--to", args->to, "draw only the snapshots at time <= T")->type_name("T");
       cmd->add_flag("--robust", args->robust,
                     "colour range from the 1st to the 99th percentile over the frames drawn");
       cmd->add_flag("--log", args->log,
                     "logarithmic colour scale (fields >= 0: strain_rate, strain_rate_instant, "
                     "von_mises, velocity, displacement, green_lagrange_norm); default range: "
                     "3 decades below the maximum (--robust: the 99th percentile)");
       cmd->add_option("--threshold", args->threshold,
                       "--field agglomerates: the |C| above which a grain is coloured "
                       "(default 0.8)")
           ->type_name("C");
       cmd->add_flag("--no-movie", args->no_movie, "do not make an MP4 even if ffmpeg is present");
       return std::function<int()>([args] {
         RenderOptions options;
         options.field = args->field;
         std::tie(options.width, options.height) = parse_size(args->size);
         if (args->range.size() == 2)
           options.range = std::make_pair(args->range[0], args->range[1]);
         options.last_frame_only = args->frames == "last";
         SG_VERIFY(!(args->frames == "window" && (args->from || args->to)),
                   "--frames window takes the analysed window: give it or --from/--to, not both");
         options.steady_window = args->frames == "window";
         if (args->from || args->to)
           options.time_window =
               std::make_pair(args->from.value_or(-std::numeric_limits<double>::infinity()),
                              args->to.value_or(std::numeric_limits<double>::infinity()));
         options.log_scale = args->log;
         SG_VERIFY(!args->threshold || options.field == "agglomerates",
                   "--threshold is for --field agglomerates (not '" << options.field << "')");
         if (args->threshold) options.agglomerate_threshold = *args->threshold;
         options.movie = !args->no_movie;
         options.robust_range = args->robust;
         const std::filesystem::path dir(args->run_dir);
         // render/ must be a real folder: nothing written through a link (io/run_directory.h).
         refuse_links_in_run_folder(dir);
         const RunInfo run = read_run_info(dir);
         if (run.has_scenario) {
           set_from_run(options, run);
           if (options.field == "coherence" || options.field == "agglomerates") {
             // Only grains carry a coherence: drop the driven bodies, walls, first bodies.
             std::vector<std::string> driven;
             if (std::filesystem::exists(dir / "series.csv"))
               driven = read_series((dir / "series.csv").string()).body_names;
             options.non_grain_rows = non_grain_rows(run, driven);
           }
         } else {
           options.title = std::filesystem::absolute(dir).lexically_normal().filename().string();
           std::cerr << "note: " << run.note
                     << "; periodic wrapping unknown, drawing positions as written"
                     << (options.field == "coherence" || options.field == "agglomerates"
                             ? "; walls cannot be told from grains (all treated as grains)"
                             : "")
                     << "\n";
         }
         const RenderResult r = render_run(dir, options);
         std::cout << "render '" << options.field << "': " << r.images.size() << " picture"
                   << (r.images.size() == 1 ? "" : "s") << " (t = " << r.first_time;
         if (r.images.size() > 1) std::cout << " to " << r.last_time;
         std::cout << (options.steady_window ? ", the analysed window" : "") << ") in "
                   << (dir / "render").string() << "\n";
         if (r.has_range)
           std::cout << "  colour range [" << r.range_min << ", " << r.range_max << "]"
                     << (options.log_scale ? " on a log scale" : "") << " (" << r.range_source
                     << ")\n";
         if (!r.movie.empty()) std::cout << "  movie: " << r.movie.string() << "\n";
         if (!r.note.empty()) std::cout << "  note: " << r.note << "\n";
         return 0;
       });
     },
     40});

}  // namespace
}  // namespace sg::app
