#include <algorithm>
#include <cmath>

#include "analysis/agglomerate_statistics.h"
#include "analysis/coherence_frames.h"
#include "analysis/structure_cylinders.h"
#include "core/error.h"
#include "io/atomic_file.h"
#include "report/analyze_steps.h"

namespace sg::report {
namespace {

namespace fs = std::filesystem;

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

}  // namespace

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
    // The stacked picture and the cylinders (paper 002 Figs 8C, 9, 10, 14).
    r.space_time_path = run_dir / "analysis" / "agglomerate_space_time.csv";
    r.cylinders_path = run_dir / "analysis" / "agglomerate_cylinders.csv";
    write_space_time_csv(r.space_time_path.string(), a, frames.front().time);
    write_cylinders_csv(r.cylinders_path.string(), structure_cylinders(a, frames.front().time));
    r.agglomerates = std::move(a);
  } catch (const Error& e) {
    r.summary.agglomerates.reset();
    r.agglomerates.reset();
    r.notes.push_back(std::string("agglomerates not computed: ") + e.what());
  }
}

}  // namespace sg::report
