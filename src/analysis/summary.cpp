#include "analysis/summary.h"

#include <cmath>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/version.h"
#include "io/atomic_file.h"

namespace sg {
namespace {

constexpr double kNan = RunParameters::kUnknown;

void add_friction(std::vector<SummaryEntry>& e, const FrictionStats& f, const std::string& who) {
  const std::string p = f.body == "mean" ? "" : f.body + "_";
  e.push_back({p + "mu", f.mu, "1",
               "friction coefficient Ft_bar/Fn_bar over the window, " + who +
                   " (paper 002 eq. 4; paper 001 eq. 1)"});
  e.push_back({p + "mu_std", f.mu_std, "1",
               "sample standard deviation of mu(t) = Ft(t)/Fn(t) over the window, " + who});
  e.push_back({p + "mu_error", f.mu_error, "1",
               "error of the mean of mu(t) over the window, mu_std sqrt(2 tau_int / n) with "
               "tau_int the integrated autocorrelation time of mu(t) (Sokal 1997), " +
                   who});
  e.push_back(
      {p + "mu_decorrelation_time", f.mu_decorrelation_time, "time",
       "2 tau_int x the row interval: the time between independent values of mu(t), " + who});
  e.push_back({p + "normal_force", f.normal_force, "force",
               "Fn_bar, mean normal force the layer exerts, " + who});
  e.push_back({p + "tangential_force", f.tangential_force, "force",
               "Ft_bar, mean tangential force resisting the sliding, " + who});
  e.push_back({p + "normal_stress", f.normal_stress, "stress",
               "sigma_n = Fn_bar / L, " + who + " (paper 001 §2.3)"});
  e.push_back({p + "shear_stress", f.shear_stress, "stress",
               "sigma_t = Ft_bar / L, " + who + " (paper 001 §2.3)"});
}

std::string format_value(double v) {
  if (!std::isfinite(v)) return "-";
  std::ostringstream s;
  s << std::setprecision(6) << v;
  return s.str();
}

}  // namespace

std::vector<SummaryEntry> summary_entries(const AnalysisSummary& s) {
  std::vector<SummaryEntry> e;
  e.push_back({"window_begin", s.window.t_begin, "time",
               "start of the steady-state window (MSER-5 on Fn, Ft of every driven body, or "
               "given)"});
  e.push_back({"window_end", s.window.t_end, "time", "end of the steady-state window"});
  e.push_back({"window_detected", s.window.detected ? 1.0 : 0.0, "1",
               "1 if the window was detected (MSER), 0 if given"});
  e.push_back({"window_at_limit", s.window.truncation_at_limit ? 1.0 : 0.0, "1",
               "1 if MSER's truncation hit half the series: the transient may not be over"});
  add_friction(e, s.friction.mean, "bodies averaged");
  for (const auto& f : s.friction.bodies)
    add_friction(e, f, "body '" + f.body + "'");
  e.push_back({"imposed_pressure", s.imposed_pressure, "stress",
               "p, the normal stress imposed on the loaded first body 'top' under pressure "
               "loading (paper 003 §2), the sigma_n of E~ and c~; null under gap loading"});
  // Which sigma_n the coordinates use (analysis/pressure_loading.h).
  const std::string sigma = std::isfinite(s.imposed_pressure)
                                ? "sigma_n = imposed_pressure p"
                                : "sigma_n = normal_stress, the bodies' measured mean";
  e.push_back({"stiffness_tilde", s.dimensionless.stiffness, "1",
               "E~ = log10(E / sigma_n), " + sigma + " (paper 001 eq. 2)"});
  e.push_back({"cohesion_tilde", s.dimensionless.cohesion, "1",
               "c~ = log10(c / sigma_n), " + sigma + " (paper 001 eq. 3)"});
  e.push_back({"viscosity_tilde", s.dimensionless.viscosity, "1",
               "alpha~ = log10(alpha V / D) (paper 001 eq. 4)"});
  const EnergyBudget en = s.energy.value_or(
      EnergyBudget{kNan, kNan, kNan, kNan, kNan, kNan, kNan, kNan, kNan, kNan, kNan});
  e.push_back({"bulk_share", en.bulk_share, "1",
               "p_wb = P_b/(P_b + P_s), share of dissipation in bulk damping (paper 001 §3.3)"});
  e.push_back({"contact_share", en.contact_share, "1",
               "p_ws = P_s/(P_b + P_s), share of dissipation at contacts (paper 001 §3.3)"});
  e.push_back({"bulk_friction", en.bulk_friction, "1", "mu_b = p_wb mu (paper 001 eq. 5)"});
  e.push_back({"contact_friction", en.contact_friction, "1", "mu_s = p_ws mu (paper 001 eq. 6)"});
  e.push_back({"bulk_power", en.bulk_power, "energy/time",
               "P_b, mean damping dissipation rate over the window"});
  e.push_back({"contact_power", en.contact_power, "energy/time",
               "P_s, mean contact dissipation rate over the window"});
  e.push_back({"external_power", en.external_power, "energy/time",
               "P_ext, mean rate of work of the driving over the window"});
  e.push_back({"mu_from_dissipation", en.mu_from_dissipation, "1",
               "(P_b + P_s)/(Fn_bar V): check, equals mu in steady state"});
  e.push_back(
      {"mu_from_work", en.mu_from_work, "1", "P_ext/(Fn_bar V): check, equals mu in steady state"});
  e.push_back({"energy_residual_drift", en.residual_drift, "energy",
               "change of the energy-balance residual over the window (ideally 0)"});
  e.push_back({"solid_fraction", s.solid_fraction, "1",
               "S_F = grain area / (L x layer height), mean over snapshots (paper 002 §3.3)"});
  e.push_back({"att_map", s.att_map, "length",
               "activated third-body thickness from the velocity map: layer thickness x area "
               "share of the grains moving at 20-80% of the velocity jump (the thresholds: "
               "\"att\"), mean over the window's snapshots (paper 003 §3.4, Fig. 13a)"});
  e.push_back({"att_profile", s.att_profile, "length",
               "activated third-body thickness from the profile: height of the bins whose mean "
               "vx lies at 20-80% of the jump, mean over the snapshots (paper 003 Fig. 13b)"});
  const AgglomerateStatistics a = s.agglomerates.value_or(
      AgglomerateStatistics{kNan, kNan, kNan, kNan, kNan, kNan, kNan, kNan, kNan, {}, {}});
  e.push_back({"structure_count", a.structure_count, "1",
               "agglomerates: space-time connected regions with |C| > threshold (paper 002 §2.2)"});
  e.push_back({"structure_count_positive", a.positive_count, "1",
               "agglomerates turning counter-clockwise (C > threshold)"});
  e.push_back({"structure_count_negative", a.negative_count, "1",
               "agglomerates turning clockwise, with the shear (C < -threshold)"});
  e.push_back({"grain_share_in_structures", a.grain_share, "1",
               "(grain, snapshot) samples inside an agglomerate / all samples (paper 002 §3.2)"});
  e.push_back({"omega_tilde_mode", a.omega_mode, "1",
               "mode of the grain-weighted PDF of omega~ = omega/(-V/D) (paper 002 eqs 6-7, "
               "§3.3); +1 = rolling with the shear"});
  e.push_back({"omega_tilde_mean", a.omega_mean, "1", "grain-weighted mean of omega~"});
  e.push_back({"structure_diameter_mode", a.diameter_mode, "length",
               "mode of the grain-weighted PDF of D = 2 sqrt(A_bar/pi) (paper 002 §3.4)"});
  e.push_back({"structure_diameter_mean", a.diameter_mean, "length",
               "grain-weighted mean agglomerate diameter"});
  e.push_back({"structure_lifetime_mean", a.lifetime_mean, "time",
               "grain-weighted mean agglomerate lifetime (frames x snapshot period)"});
  return e;
}

std::string summary_json(const AnalysisSummary& summary, const std::vector<SummaryEntry>& extra) {
  nlohmann::ordered_json quantities = nlohmann::ordered_json::object();
  std::vector<SummaryEntry> entries = summary_entries(summary);
  entries.insert(entries.end(), extra.begin(), extra.end());
  for (const auto& entry : entries) {
    nlohmann::ordered_json q;
    // JSON has no NaN: an unknown value is null, which a reader cannot mistake for 0.
    if (std::isfinite(entry.value))
      q["value"] = entry.value;
    else
      q["value"] = nullptr;
    q["unit"] = entry.unit;
    q["definition"] = entry.definition;
    quantities[entry.key] = std::move(q);
  }
  nlohmann::ordered_json doc;
  doc["format"] = "softgrain-analysis-summary";
  doc["version"] = 1;
  // What computed it (core/version.h): the summary names the build, as run.log does.
  doc["softgrain"] = {{"version", softgrain_version()}, {"commit", softgrain_commit()}};
  doc["quantities"] = std::move(quantities);
  // The window's failed steadiness checks: the averages above are suspect (steadiness.h).
  nlohmann::ordered_json warnings = nlohmann::ordered_json::array();
  for (const SteadinessWarning& w : summary.warnings)
    warnings.push_back({{"check", w.check}, {"message", w.message}});
  doc["warnings"] = std::move(warnings);
  return doc.dump(2) + "\n";
}

void write_summary_json(const std::string& path, const AnalysisSummary& summary) {
  write_file_atomically(path, summary_json(summary));
}

std::string format_summary_rows(const std::vector<SummaryEntry>& entries, std::size_t key_width) {
  for (const auto& e : entries)
    key_width = std::max(key_width, e.key.size());
  std::ostringstream out;
  for (const auto& e : entries)
    out << std::left << std::setw(static_cast<int>(key_width)) << e.key << "  " << std::right
        << std::setw(14) << format_value(e.value) << "  " << e.unit << '\n';
  return out.str();
}

std::string format_summary_table(const AnalysisSummary& summary) {
  const auto entries = summary_entries(summary);
  std::size_t key_width = 8;
  for (const auto& e : entries)
    key_width = std::max(key_width, e.key.size());
  std::ostringstream out;
  out << std::left << std::setw(static_cast<int>(key_width)) << "quantity"
      << "  " << std::right << std::setw(14) << "value"
      << "  unit\n";
  out << std::string(key_width + 2 + 14 + 2 + 11, '-') << '\n';
  return out.str() + format_summary_rows(entries, key_width);
}

}  // namespace sg
