#pragma once
// Grain size laws, and the portable random draws every sample generator uses.
//
// Determinism across platforms: std::mt19937_64 is specified bit for bit by the C++
// standard, but std::uniform_real_distribution and friends are not (libstdc++, libc++ and
// MSVC give different numbers for the same engine state). Every generator in geometry/
// therefore draws its engine words through `uniform01` below, and nothing else, so a seed
// gives the same sample on every compiler.
#include <cstdint>
#include <random>
#include <vector>

namespace sg {

using RandomEngine = std::mt19937_64;

// Uniform in [0, 1): the top 53 bits of one engine word, scaled by 2^-53 (every double of
// the form k 2^-53 equally likely; exact, no rounding).
inline double uniform01(RandomEngine& engine) {
  return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

// Uniform in [lo, hi).
inline double uniform_in(RandomEngine& engine, double lo, double hi) {
  return lo + (hi - lo) * uniform01(engine);
}

// Uniform integer in [0, n), n >= 1 (bias below 2^-53 n: irrelevant here).
int uniform_index(RandomEngine& engine, int n);

// How sizes are distributed between the bounds of a SizeRangeDef. In 2D the "volume" of
// a grain is its area, proportional to d^2.
enum class SizeLaw {
  // Uniform in d: number density p(d) = 1/(d_max - d_min). Paper 001 §2: discs with
  // diameters uniformly distributed in [0.85, 1.15].
  uniform,
  // Each size class holds the same grain area ("uniform by volume fraction", the usual
  // sieve-curve reading): area density flat, so number density p(d) ∝ 1/d^2.
  uniform_area,
  // Uniform in log d: p(d) ∝ 1/d (equal number per size octave).
  log_uniform,
};

// A size (diameter or axis length, units of length) in [min, max] following `law`.
// min == max gives a monodisperse sample.
struct SizeRangeDef {
  double min = 0.85;  // length
  double max = 1.15;  // length
  SizeLaw law = SizeLaw::uniform;
};

// Checks 0 < min <= max; `what` names the quantity in the error message.
void verify_size_range(const SizeRangeDef& range, const char* what);

// One size, by inversion of the cumulative distribution (one engine word per draw).
double sample_size(const SizeRangeDef& range, RandomEngine& engine);
// `count` sizes from a fresh engine seeded with `seed`.
std::vector<double> sample_sizes(const SizeRangeDef& range, int count, std::uint64_t seed);

// Cumulative distribution F(d) = P(size <= d), for goodness-of-fit tests.
double size_cdf(const SizeRangeDef& range, double d);
// Exact mean and variance of the law (for moment checks and reports).
double size_mean(const SizeRangeDef& range);
double size_variance(const SizeRangeDef& range);

// Kolmogorov-Smirnov statistic D = sup_d |F_n(d) - F(d)| of a sample against the law's CDF
// (F_n the sample's empirical CDF), 0 for an empty sample. For a continuous law and n
// independent draws, sqrt(n) D follows Kolmogorov's distribution as n grows: D exceeds
// 1.36 / sqrt(n) with probability 5%, 1.628 / sqrt(n) with 1%. A monodisperse law (min == max)
// is a step: D = 0 when every draw is that size.
double ks_statistic(std::vector<double> sample, const SizeRangeDef& range);

// The large-n critical value c_alpha / sqrt(n) for alpha = 5% (c = 1.358, often quoted 1.36).
double ks_critical_value_5pct(std::size_t n);

}  // namespace sg
