#pragma once
// The scalars of paper 002 §3.2-3.4 drawn from detected structures, for summary.json:
// counts, share of grains, and the modes ("peak of the PDF", paper 002 §3.3) and weighted
// means of omega~ and of the diameter, every PDF and mean weighted by equivalent grains
// (a structure weighs by its (grain, frame) samples).
// Binning of the modes (ours; a mode depends on it): omega~ in bins of 0.1 over [-5, 5];
// diameter in bins of half a mean grain diameter from 0 to the largest structure.
#include "analysis/agglomerates.h"

namespace sg {

struct AgglomerateStatistics {
  double structure_count = 0.0;
  double positive_count = 0.0;  // counter-clockwise (C > threshold)
  double negative_count = 0.0;  // clockwise, turning with the shear
  double grain_share = 0.0;     // paper 002 §3.2
  double omega_mode = 0.0;      // mode of the PDF of omega~ (paper 002 §3.3); NaN if none
  double omega_mean = 0.0;      // grain-weighted mean of omega~
  double diameter_mode = 0.0;   // mode of the PDF of D (paper 002 §3.4) (length)
  double diameter_mean = 0.0;   // grain-weighted mean of D (length)
  double lifetime_mean = 0.0;   // grain-weighted mean lifetime (time)
  WeightedPdf omega_pdf;
  WeightedPdf diameter_pdf;
};

AgglomerateStatistics compute_agglomerate_statistics(const AgglomerateResult& result,
                                                     double mean_diameter);

}  // namespace sg
