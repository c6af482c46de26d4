#include <cmath>
#include <nlohmann/json.hpp>

#include "report/analyze_steps.h"

namespace sg::report {

namespace fs = std::filesystem;

std::string summary_document(const AnalyzeResult& r, const fs::path& run_dir) {
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
  if (r.campaign) {
    // The requested coordinates beside the realized ones (quantities of the same name).
    nlohmann::ordered_json c, requested, realized;
    c["name"] = r.campaign->campaign;
    c["run"] = r.campaign->run;
    for (const auto& [key, value] : r.campaign->requested) {
      requested[key] = std::isfinite(value) ? nlohmann::ordered_json(value) : nullptr;
      const double v =
          doc["quantities"].contains(key) && doc["quantities"][key]["value"].is_number()
              ? doc["quantities"][key]["value"].get<double>()
              : kNan;
      realized[key] = std::isfinite(v) ? nlohmann::ordered_json(v) : nullptr;
    }
    c["requested"] = std::move(requested);
    c["realized"] = std::move(realized);
    doc["campaign"] = std::move(c);
  }
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
    ag["space_time_file"] = "agglomerate_space_time.csv";
    ag["cylinders_file"] = "agglomerate_cylinders.csv";
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
  if (r.att) {
    nlohmann::ordered_json att;
    att["file"] = "att.csv";
    att["threshold_low"] = r.att->thresholds.lo;
    att["threshold_high"] = r.att->thresholds.hi;
    att["layer_thickness"] = r.att->layer_thickness;
    att["layer_thickness_source"] = r.att_layer_source;
    att["profile_bins"] = r.att->profile_bins;
    att["snapshots"] = r.att->samples.size();
    doc["att"] = std::move(att);
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
  nlohmann::ordered_json unmeasured = nlohmann::ordered_json::array();
  for (const Unmeasured& u : r.unmeasured)
    unmeasured.push_back({{"quantity", u.quantity}, {"reason", u.reason}});
  doc["unmeasured"] = std::move(unmeasured);
  doc["notes"] = r.notes;
  return doc.dump(2) + "\n";
}

}  // namespace sg::report
