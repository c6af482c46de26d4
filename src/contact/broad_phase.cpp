#include "contact/broad_phase.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>

#include <omp.h>

#include "core/error.h"
#include "core/parallel.h"
#include "core/rounding.h"
#include "geometry/polygon.h"

namespace sg {

void validate(const BroadPhaseParams& params) {
  SG_VERIFY(std::isfinite(params.cutoff) && params.cutoff > 0.0,
            "contact broad phase: cutoff must be > 0, got " << params.cutoff);
  SG_VERIFY(std::isfinite(params.skin) && params.skin >= 0.0,
            "contact broad phase: skin must be >= 0, got " << params.skin);
  if (params.periodic_x) {
    SG_VERIFY(
        std::isfinite(params.x_min) && std::isfinite(params.x_max) && params.x_max > params.x_min,
        "contact broad phase: periodic cell [" << params.x_min << ", " << params.x_max
                                               << ") is empty");
  }
}

double nearest_image_shift(const BroadPhaseParams& params, const Vec2& node, const Vec2& a,
                           const Vec2& b) {
  if (!params.periodic_x) return 0.0;
  const double period = params.x_max - params.x_min;
  return period * round_half_away((0.5 * (a.x() + b.x()) - node.x()) / period);
}

BroadPhase::BroadPhase(const BroadPhaseParams& params) : params_(params) {
  validate(params_);
}

namespace {

// Geometry of the cell grid for one build. Cells are at least `reach` wide in both
// directions, so everything within `reach` of a point lies in the 3 x 3 block of cells
// around the point's cell.
struct Grid {
  bool periodic = false;
  double x0 = 0.0, y0 = 0.0;          // origin
  double cell_w = 1.0, cell_h = 1.0;  // cell sizes
  int nx = 1, ny = 1;

  // Unwrapped column index (periodic: may be outside [0, nx)).
  long long column(double x) const { return floor_index((x - x0) / cell_w); }
  int wrap_column(long long c) const {
    if (!periodic) return static_cast<int>(std::clamp<long long>(c, 0, nx - 1));
    const long long m = c % nx;
    return static_cast<int>(m < 0 ? m + nx : m);
  }
  int row(double y) const {
    const long long r = floor_index((y - y0) / cell_h);
    return static_cast<int>(std::clamp<long long>(r, 0, ny - 1));
  }
  int cell(int column_index, int row_index) const { return row_index * nx + column_index; }
};

}  // namespace

namespace {

void check_input(const BroadPhaseInput& input) {
  const std::size_t node_count = input.nodes.size();
  const std::size_t segment_count = input.segment_start.size();
  SG_VERIFY(input.node_body.size() == node_count,
            "contact broad phase: " << node_count << " nodes but " << input.node_body.size()
                                    << " node owners");
  SG_VERIFY(input.segment_end.size() == segment_count && input.segment_body.size() == segment_count,
            "contact broad phase: segment arrays differ in size ("
                << segment_count << " starts, " << input.segment_end.size() << " ends, "
                << input.segment_body.size() << " owners)");
}

// Bounding box of everything, and the widest segment in x.
struct Extent {
  Vec2 lo, hi;
  double widest = 0.0;
};

// Every position finite (else the grid, and cwiseMin which may pass over a NaN, mean nothing).
void check_finite(const BroadPhaseInput& input) {
  for (std::size_t i = 0; i < input.nodes.size(); ++i)
    SG_VERIFY(input.nodes[i].allFinite(), "contact broad phase: node "
                                              << i << " (body " << input.node_body[i]
                                              << ") has a non-finite position");
  for (std::size_t s = 0; s < input.segment_start.size(); ++s)
    SG_VERIFY(input.segment_start[s].allFinite() && input.segment_end[s].allFinite(),
              "contact broad phase: segment " << s << " (body " << input.segment_body[s]
                                              << ") has a non-finite end point");
}

Extent extent_of(const BroadPhaseInput& input) {
  check_finite(input);
  Extent e{input.nodes[0], input.nodes[0], 0.0};
  for (const Vec2& p : input.nodes) {
    e.lo = e.lo.cwiseMin(p);
    e.hi = e.hi.cwiseMax(p);
  }
  for (std::size_t s = 0; s < input.segment_start.size(); ++s) {
    const Vec2 &a = input.segment_start[s], &b = input.segment_end[s];
    e.lo = e.lo.cwiseMin(a).cwiseMin(b);
    e.hi = e.hi.cwiseMax(a).cwiseMax(b);
    e.widest = std::max(e.widest, std::abs(b.x() - a.x()));
  }
  return e;
}

// Cell size: at least `min_cell`; coarser if the grid would have many more cells than
// objects (memory and clearing cost), which only costs more distance tests.
Grid choose_grid(const BroadPhaseParams& params, const Extent& e, std::size_t objects,
                 double min_cell) {
  const double period = params.x_max - params.x_min;
  const double max_cells = 4.0 * static_cast<double>(objects) + 16.0;
  const double width = params.periodic_x ? period : e.hi.x() - e.lo.x();
  const double height = e.hi.y() - e.lo.y();
  double cell = min_cell;
  Grid grid;
  grid.periodic = params.periodic_x;
  for (;;) {
    if (grid.periodic) {
      grid.x0 = params.x_min;
      grid.nx = std::max(1, static_cast<int>(std::floor(period / cell)));
      grid.cell_w = period / grid.nx;  // >= cell: the columns tile the period exactly
    } else {
      grid.x0 = e.lo.x();
      grid.nx = static_cast<int>(std::floor(width / cell)) + 1;
      grid.cell_w = cell;
    }
    grid.y0 = e.lo.y();
    grid.ny = static_cast<int>(std::floor(height / cell)) + 1;
    grid.cell_h = cell;
    const double cells = static_cast<double>(grid.nx) * static_cast<double>(grid.ny);
    if (cells <= max_cells) return grid;
    cell *= std::max(1.1, std::sqrt(cells / max_cells));
  }
}

// Bins the segments: a segment goes in every cell its bounding box overlaps (a counting sort
// by cell). In parallel over segments, each slot taken with an atomic increment: the order of
// a cell's segments then depends on the threads, and nothing depends on that order (a node's
// query tests each segment once, whichever cell it meets it in first, and sorts what it
// accepts). Serial, the binning was 0.28 s of the 400-grain cell's 10 s on 2 threads (about
// 0.55 ms per build).
void bin_segments(const BroadPhaseInput& input, const Grid& grid, std::vector<int>& cell_start,
                  std::vector<int>& cell_segments, std::vector<int>& fill) {
  const auto segment_count = static_cast<std::ptrdiff_t>(input.segment_start.size());
  const std::size_t cell_count =
      static_cast<std::size_t>(grid.nx) * static_cast<std::size_t>(grid.ny);
  cell_start.assign(cell_count + 1, 0);
  const auto for_each_cell_of_segment = [&](std::ptrdiff_t s, auto&& visit) {
    const auto k = static_cast<std::size_t>(s);
    const Vec2 &a = input.segment_start[k], &b = input.segment_end[k];
    const long long c_lo = grid.column(std::min(a.x(), b.x()));
    long long c_hi = grid.column(std::max(a.x(), b.x()));
    if (grid.periodic) c_hi = std::min(c_hi, c_lo + grid.nx - 1);  // all columns at most once
    const int r_lo = grid.row(std::min(a.y(), b.y())), r_hi = grid.row(std::max(a.y(), b.y()));
    for (long long c = c_lo; c <= c_hi; ++c) {
      const int column = grid.wrap_column(c);
      for (int r = r_lo; r <= r_hi; ++r)
        visit(static_cast<std::size_t>(grid.cell(column, r)));
    }
  };
  const auto take = [](int& counter) {
    return std::atomic_ref<int>(counter).fetch_add(1, std::memory_order_relaxed);
  };
  const bool parallel = segment_count >= static_cast<std::ptrdiff_t>(kParallelContourPoints);
#pragma omp parallel if (parallel)
  {
#pragma omp for schedule(static)
    for (std::ptrdiff_t s = 0; s < segment_count; ++s)
      for_each_cell_of_segment(s, [&](std::size_t c) { take(cell_start[c + 1]); });
#pragma omp single
    {
      for (std::size_t c = 0; c < cell_count; ++c)
        cell_start[c + 1] += cell_start[c];
      cell_segments.resize(static_cast<std::size_t>(cell_start[cell_count]));
      // (A kept scratch: allocated anew at each build, the large grids of the 400-grain cell
      // were fresh pages from the kernel every few steps.)
      fill.assign(cell_start.begin(), cell_start.end() - 1);
    }
#pragma omp for schedule(static)
    for (std::ptrdiff_t s = 0; s < segment_count; ++s)
      for_each_cell_of_segment(s, [&](std::size_t c) {
        cell_segments[static_cast<std::size_t>(take(fill[c]))] = static_cast<int>(s);
      });
  }
}

// A segment's distance to `node` exceeds `accept` for sure: the node is farther than that from
// the segment's box in x or in y. The margin of 1e-9 (relative) is far above the round-off of
// the distance computed by project_on_segment: a pair it rejects is never one the distance
// test accepts, so the candidates are those of the distance test alone.
inline bool outside_box(const Vec2& node, const Vec2& a, const Vec2& b, double accept) {
  const double margin = accept * (1.0 + 1e-9);
  return node.x() < std::min(a.x(), b.x()) - margin || node.x() > std::max(a.x(), b.x()) + margin ||
         node.y() < std::min(a.y(), b.y()) - margin || node.y() > std::max(a.y(), b.y()) + margin;
}

// Every segment of another body in the cells around node n (distinct columns only: with few
// columns a periodic range wraps onto itself), within `accept` of the node: appended to the
// candidates in increasing segment order. A segment spanning several of the cells is tested
// once: `seen` (one entry per segment, this thread's) holds `stamp`, unique to this node and
// build, for the segments already met.
void query_node(const BroadPhaseParams& params, const BroadPhaseInput& input, const Grid& grid,
                const std::vector<int>& cell_start, const std::vector<int>& cell_segments,
                std::size_t n, double accept, std::uint64_t stamp, std::uint64_t* seen,
                std::vector<ContactCandidate>& candidates) {
  const Vec2& node = input.nodes[n];
  // The cells the node's reach square [x -+ m] x [y -+ m] overlaps: any segment within
  // `accept` of the node has a point in that square, and so lies in one of them (its box's
  // cells). The 1e-9 margin covers the round-off of the bounds and of the cell indices. Cells
  // are at least `reach` wide: 2 or 3 columns and rows, where the 3 x 3 block around the
  // node's cell was 9 cells.
  const double m = accept * (1.0 + 1e-9);
  const long long c_lo = grid.column(node.x() - m), c_hi = grid.column(node.x() + m);
  SG_ASSERT(c_hi - c_lo < 4, "contact broad phase: cells narrower than the reach");
  int columns[4];
  int column_count = 0;
  for (long long c = c_lo; c <= c_hi; ++c) {
    if (!grid.periodic && (c < 0 || c >= grid.nx)) continue;
    const int column = grid.wrap_column(c);
    if (std::find(columns, columns + column_count, column) == columns + column_count)
      columns[column_count++] = column;
  }
  const int r_lo = grid.row(node.y() - m), r_hi = grid.row(node.y() + m);
  const std::size_t first = candidates.size();
  for (int k = 0; k < column_count; ++k) {
    for (int r = r_lo; r <= r_hi; ++r) {
      const std::size_t c = static_cast<std::size_t>(grid.cell(columns[k], r));
      for (int i = cell_start[c]; i < cell_start[c + 1]; ++i) {
        const int s = cell_segments[static_cast<std::size_t>(i)];
        const auto segment = static_cast<std::size_t>(s);
        if (seen[segment] == stamp || input.segment_body[segment] == input.node_body[n]) continue;
        seen[segment] = stamp;
        const Vec2& a = input.segment_start[segment];
        const Vec2& b = input.segment_end[segment];
        // The only image that can be within reach is the nearest one of the segment's centre
        // (period > 2 reach + widest segment, checked in build).
        const double shift = nearest_image_shift(params, node, a, b);
        const Vec2 image = node + Vec2(shift, 0.0);
        if (outside_box(image, a, b, accept)) continue;
        if (project_on_segment(image, a, b).distance <= accept)
          candidates.push_back({static_cast<int>(n), s, shift});
      }
    }
  }
  // In increasing segment order (the cells are visited column by column, not in that order).
  std::sort(
      candidates.begin() + static_cast<std::ptrdiff_t>(first), candidates.end(),
      [](const ContactCandidate& x, const ContactCandidate& y) { return x.segment < y.segment; });
}

}  // namespace

void BroadPhase::build(const BroadPhaseInput& input) {
  check_input(input);
  const std::size_t node_count = input.nodes.size();
  const std::size_t segment_count = input.segment_start.size();
  ++build_count_;
  built_nodes_.assign(input.nodes.begin(), input.nodes.end());
  built_segment_start_.assign(input.segment_start.begin(), input.segment_start.end());
  built_segment_end_.assign(input.segment_end.begin(), input.segment_end.end());
  candidates_.clear();
  if (node_count == 0 || segment_count == 0) return;

  const double reach = params_.cutoff + params_.skin;
  // Pairs are accepted up to reach (1 + 1e-12): round-off in the distance must not turn the
  // strict guarantee of the header into a miss. Cells get a 1e-9 relative margin over reach,
  // far above the round-off of cell indices for coordinates up to ~1e6 reach.
  const double accept = reach * (1.0 + 1e-12);
  const double min_cell = reach * (1.0 + 1e-9);
  const double period = params_.x_max - params_.x_min;
  const Extent extent = extent_of(input);
  if (params_.periodic_x) {
    SG_VERIFY(period > 2.0 * reach + extent.widest,
              "contact broad phase: the periodic cell (length "
                  << period << ") must be longer than 2 (cutoff + skin) + the widest segment = "
                  << 2.0 * reach + extent.widest << " so that a node meets one image of a segment");
  }
  const Grid grid = choose_grid(params_, extent, node_count + segment_count, min_cell);
  bin_segments(input, grid, cell_start_, cell_segments_, cell_fill_);
  // The nodes are queried in parallel, in kQueryChunks contiguous ranges whose lists are
  // joined in range order: the list is that of a query in node order, on any number of threads.
  // (Serial, the queries were a whole contact phase that did not speed up on 2 threads.)
  chunk_candidates_.resize(kQueryChunks);
  thread_seen_.resize(static_cast<std::size_t>(omp_get_max_threads()));
  for (std::vector<std::uint64_t>& seen : thread_seen_)
    seen.resize(segment_count, 0);  // stale stamps are below this build's
  const std::uint64_t stamp_base = next_stamp_;
  next_stamp_ += node_count;
  const auto chunk_begin = [&](std::size_t c) { return c * node_count / kQueryChunks; };
#pragma omp parallel for schedule(dynamic)
  for (std::size_t c = 0; c < kQueryChunks; ++c) {
    std::vector<ContactCandidate>& chunk = chunk_candidates_[c].list;
    chunk.clear();
    std::uint64_t* seen = thread_seen_[static_cast<std::size_t>(omp_get_thread_num())].data();
    for (std::size_t n = chunk_begin(c); n < chunk_begin(c + 1); ++n)
      query_node(params_, input, grid, cell_start_, cell_segments_, n, accept, stamp_base + n, seen,
                 chunk);
  }
  for (const ChunkCandidates& chunk : chunk_candidates_)
    candidates_.insert(candidates_.end(), chunk.list.begin(), chunk.list.end());
}

namespace {

// The box [lo, hi] widened to hold d.
inline void widen_box(const Vec2& d, double& lo_x, double& lo_y, double& hi_x, double& hi_y) {
  lo_x = std::min(lo_x, d.x());
  lo_y = std::min(lo_y, d.y());
  hi_x = std::max(hi_x, d.x());
  hi_y = std::max(hi_y, d.y());
}

}  // namespace

bool BroadPhase::needs_rebuild(const BroadPhaseInput& input) const {
  if (build_count_ == 0) return true;
  if (input.nodes.size() != built_nodes_.size() ||
      input.segment_start.size() != built_segment_start_.size() ||
      input.segment_end.size() != built_segment_end_.size())
    return true;
  if (built_nodes_.empty() && built_segment_start_.empty()) return false;
  // The box of the nearest-image displacements (header): rebuild when half its diagonal
  // exceeds skin / 2, that is when its squared diagonal exceeds skin^2. Minima and maxima are
  // exact whatever their order: the same box on any number of threads.
  const double period = params_.x_max - params_.x_min;
  const bool periodic = params_.periodic_x;
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  double lo_x = kInfinity, lo_y = kInfinity, hi_x = -kInfinity, hi_y = -kInfinity;
  // Nearest image: a position wrapped across the seam has not moved by L. (Only a move of
  // over half a period can be a wrap: the test skips the division and rounding otherwise,
  // and at exactly half a period either image is as far.)
  const auto dx_of = [periodic, period](double now, double then) {
    const double dx = now - then;
    return periodic && std::abs(dx) > 0.5 * period ? dx - period * round_half_away(dx / period)
                                                   : dx;
  };
  const auto displacement = [&](const Vec2& now, const Vec2& then) {
    return Vec2(dx_of(now.x(), then.x()), now.y() - then.y());
  };
  const auto nodes = static_cast<std::ptrdiff_t>(built_nodes_.size());
  const auto segments = static_cast<std::ptrdiff_t>(built_segment_start_.size());
  const bool parallel = static_cast<std::size_t>(nodes + segments) >= kParallelContourPoints;
  // (The loops name the reduction variables themselves: a lambda capturing them by reference
  // would widen the shared box, not each thread's.)
#pragma omp parallel if (parallel) reduction(min : lo_x, lo_y) reduction(max : hi_x, hi_y)
  {
#pragma omp for schedule(static) nowait
    for (std::ptrdiff_t i = 0; i < nodes; ++i) {
      const auto k = static_cast<std::size_t>(i);
      widen_box(displacement(input.nodes[k], built_nodes_[k]), lo_x, lo_y, hi_x, hi_y);
    }
#pragma omp for schedule(static) nowait
    for (std::ptrdiff_t i = 0; i < segments; ++i) {
      const auto k = static_cast<std::size_t>(i);
      widen_box(displacement(input.segment_start[k], built_segment_start_[k]), lo_x, lo_y, hi_x,
                hi_y);
      widen_box(displacement(input.segment_end[k], built_segment_end_[k]), lo_x, lo_y, hi_x, hi_y);
    }
  }
  const Vec2 diagonal(hi_x - lo_x, hi_y - lo_y);
  // (A NaN displacement is caught before: the contact system checks the positions.)
  return diagonal.squaredNorm() > params_.skin * params_.skin;
}

void BroadPhase::capture(BroadPhaseState& state) const {
  state.build_count = build_count_;
  state.built_nodes = built_nodes_;  // vector assignment reuses the destination's capacity
  state.built_segment_start = built_segment_start_;
  state.built_segment_end = built_segment_end_;
  state.candidates = candidates_;
}

void BroadPhase::restore(const BroadPhaseState& state) {
  SG_VERIFY(
      state.build_count >= 0 && state.built_segment_start.size() == state.built_segment_end.size(),
      "contact broad phase: inconsistent saved state ("
          << state.built_segment_start.size() << " segment starts, "
          << state.built_segment_end.size() << " ends)");
  for (const ContactCandidate& c : state.candidates)
    SG_VERIFY(c.node >= 0 && static_cast<std::size_t>(c.node) < state.built_nodes.size() &&
                  c.segment >= 0 &&
                  static_cast<std::size_t>(c.segment) < state.built_segment_start.size(),
              "contact broad phase: saved candidate (node "
                  << c.node << ", segment " << c.segment << ") is out of range ("
                  << state.built_nodes.size() << " nodes, " << state.built_segment_start.size()
                  << " segments)");
  build_count_ = state.build_count;
  built_nodes_ = state.built_nodes;
  built_segment_start_ = state.built_segment_start;
  built_segment_end_ = state.built_segment_end;
  candidates_ = state.candidates;
}

}  // namespace sg
