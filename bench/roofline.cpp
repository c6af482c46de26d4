#include "roofline.h"

#include <array>
#include <chrono>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "material/simd.h"

namespace sg::bench {
namespace {

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Keeps a result alive without a store the compiler could drop.
template <class T>
void keep(const T& value) {
  asm volatile("" : : "r,m"(value) : "memory");
}

std::vector<std::uint32_t> random_indices(std::size_t count, std::size_t range) {
  std::mt19937 random(12345);
  std::uniform_int_distribution<std::uint32_t> pick(0, static_cast<std::uint32_t>(range - 1));
  std::vector<std::uint32_t> index(count);
  for (auto& i : index)
    i = pick(random);
  return index;
}

}  // namespace

double triad_bytes_per_second(std::size_t n, double seconds) {
  std::vector<double> a(n, 0.0), b(n, 1.0), c(n, 2.0);
  const double s = 0.5;
  std::size_t passes = 0;
  const auto t0 = Clock::now();
  do {
    for (std::size_t i = 0; i < n; ++i)
      a[i] = b[i] + s * c[i];
    keep(a[passes % n]);
    ++passes;
  } while (since(t0) < seconds);
  return 24.0 * static_cast<double>(n) * static_cast<double>(passes) / since(t0);
}

double gather_loads_per_second(std::size_t n, double seconds) {
  std::vector<double> x(n, 1.0);
  const std::vector<std::uint32_t> index = random_indices(1u << 16, n);
  std::size_t passes = 0;
  double s0 = 0, s1 = 0, s2 = 0, s3 = 0;
  const auto t0 = Clock::now();
  do {
    for (std::size_t k = 0; k < index.size(); k += 4) {
      s0 += x[index[k]];
      s1 += x[index[k + 1]];
      s2 += x[index[k + 2]];
      s3 += x[index[k + 3]];
    }
    ++passes;
  } while (since(t0) < seconds);
  keep(s0 + s1 + s2 + s3);
  return static_cast<double>(index.size()) * static_cast<double>(passes) / since(t0);
}

double chase_seconds_per_load(std::size_t n, double seconds) {
  // A single random cycle through all n entries (Sattolo's shuffle), so every load depends on
  // the previous one and the prefetchers cannot guess the next.
  std::vector<std::uint64_t> next(n);
  std::iota(next.begin(), next.end(), 0);
  std::mt19937_64 random(12345);
  for (std::size_t i = n - 1; i > 0; --i)
    std::swap(next[i], next[std::uniform_int_distribution<std::size_t>(0, i - 1)(random)]);
  std::uint64_t p = 0;
  std::size_t loads = 0;
  const auto t0 = Clock::now();
  do {
    for (int k = 0; k < 4096; ++k)
      p = next[p];
    loads += 4096;
  } while (since(t0) < seconds);
  keep(p);
  return since(t0) / static_cast<double>(loads);
}

double peak_flops_per_second(double seconds) {
  constexpr int chains = 12;  // enough independent chains to cover the add and multiply latency
  std::array<DoubleBatch, chains> x;
  for (int c = 0; c < chains; ++c)
    x[static_cast<std::size_t>(c)] = DoubleBatch(1.0 + 1e-3 * c);
  const DoubleBatch a(0.999999), b(1e-6);
  std::size_t iterations = 0;
  const auto t0 = Clock::now();
  do {
    for (int k = 0; k < 1024; ++k)
      for (auto& v : x)
        v = v * a + b;
    iterations += 1024;
  } while (since(t0) < seconds);
  double sum = 0.0;
  for (const auto& v : x) {
    alignas(kSimdAlignment) std::array<double, kSimdWidth> lanes;
    v.store_aligned(lanes.data());
    for (double l : lanes)
      sum += l;
  }
  keep(sum);
  return 2.0 * chains * kSimdWidth * static_cast<double>(iterations) / since(t0);
}

// GCC's vector extension in a function compiled for AVX2 (xsimd's AVX2 batch exists only in code
// compiled with -mavx2); the chains stay in this function, in registers.
__attribute__((target("avx2"))) double peak_avx2_flops_per_second(double seconds) {
  typedef double Quad __attribute__((vector_size(32)));
  constexpr int chains = 12;
  Quad x[chains];
  for (int c = 0; c < chains; ++c)
    x[c] = Quad{} + (1.0 + 1e-3 * c);
  const Quad a = Quad{} + 0.999999, b = Quad{} + 1e-6;
  std::size_t iterations = 0;
  const auto t0 = Clock::now();
  do {
    for (int k = 0; k < 1024; ++k)
      for (auto& v : x)
        v = v * a + b;
    iterations += 1024;
  } while (since(t0) < seconds);
  double sum = 0.0;
  for (const auto& v : x)
    sum += v[0] + v[1] + v[2] + v[3];
  keep(sum);
  return 2.0 * chains * 4 * static_cast<double>(iterations) / since(t0);
}

}  // namespace sg::bench
