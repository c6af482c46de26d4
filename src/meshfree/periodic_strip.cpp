#include "meshfree/periodic_strip.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "meshfree/contour_rows.h"
#include "meshfree/mls.h"
#include "meshfree/triangle_quadrature.h"

namespace sg {

namespace {

// One column of nodes at a surface point: node indices from low to high y.
struct Column {
  double x = 0.0;
  std::vector<int> nodes;
  int intervals() const { return static_cast<int>(nodes.size()) - 1; }
};

// Zips column a (left) with column b (right; its nodes taken at +shift_b along x when it is
// the first column seen across the seam) into counter-clockwise triangles. Both columns run
// from the back face to the surface, so their nodes are matched by their fraction of the
// column height: the zipper advances on the side whose next node is lower in that fraction
// (exact integer comparison, ties to a). Each triangle has two vertices on one vertical
// column and one on the other: positive area (dx * dy > 0).
void zip_columns(const Column& a, const Column& b, std::vector<std::array<int, 3>>& out) {
  const int ma = a.intervals(), mb = b.intervals();
  int ia = 0, ib = 0;
  while (ia < ma || ib < mb) {
    const bool advance_a = ib == mb || (ia < ma && (ia + 1) * mb <= (ib + 1) * ma);
    const auto pa = static_cast<std::size_t>(ia), pb = static_cast<std::size_t>(ib);
    if (advance_a) {
      out.push_back({a.nodes[pa], b.nodes[pb], a.nodes[pa + 1]});
      ++ia;
    } else {
      out.push_back({a.nodes[pa], b.nodes[pb], b.nodes[pb + 1]});
      ++ib;
    }
  }
}

// Maps a row evaluated over the extended node set [nodes, nodes - L, nodes + L] back to the
// original nodes, recording the image of each entry.
void append_mapped_row(const ShapeRows& extended, std::size_t point, std::size_t n,
                       const std::vector<double>& extended_radius, ShapeRows& rows,
                       std::vector<std::int8_t>& image, const Vec2& at,
                       const std::string& body_name) {
  const auto begin = static_cast<std::size_t>(extended.offset[point]);
  const auto end = static_cast<std::size_t>(extended.offset[point + 1]);
  for (std::size_t k = begin; k < end; ++k) {
    const auto e = static_cast<std::size_t>(extended.node[k]);
    const std::size_t original = e % n;
    const std::int8_t shift = e < n ? 0 : (e < 2 * n ? -1 : 1);
    // An image's support radius comes from its k nearest neighbours in the extended set; it
    // equals its original's when the period holds all of them (up to the round-off of the
    // shifted coordinates).
    SG_VERIFY(std::abs(extended_radius[e] - extended_radius[original]) <=
                  1e-9 * extended_radius[original],
              "body '" << body_name << "': the periodic MLS support of node " << original
                       << " differs between the node and its image (the period is too short "
                          "for the MLS supports)");
    for (std::size_t j = begin; j < k; ++j)
      SG_VERIFY(static_cast<std::size_t>(extended.node[j]) % n != original,
                "body '" << body_name << "': the MLS row at (" << at.x() << ", " << at.y()
                         << ") sees node " << original
                         << " twice through the periodic seam (the period is too short for the "
                            "MLS supports)");
    rows.node.push_back(static_cast<std::int32_t>(original));
    rows.value.push_back(extended.value[k]);
    rows.dndx.push_back(extended.dndx[k]);
    rows.dndy.push_back(extended.dndy[k]);
    image.push_back(shift);
  }
  rows.offset.push_back(static_cast<std::int32_t>(rows.node.size()));
}

}  // namespace

namespace {

// The surface must be finite, strictly monotonic in x, on one side of the back face, and span
// less than one period.
void check_strip_input(const Polygon& surface, double closing_shift_x, double back_y, double h,
                       const std::string& body_name) {
  const std::size_t n_surface = surface.size();
  const double period = std::abs(closing_shift_x);
  SG_VERIFY(n_surface >= 3, "body '" << body_name << "': a deformable strip needs at least 3 "
                                     << "surface points, got " << n_surface);
  SG_VERIFY(period > 0.0 && std::isfinite(period),
            "body '" << body_name << "': a strip needs a closing shift (the period), got "
                     << closing_shift_x);
  SG_VERIFY(h > 0.0, "body '" << body_name << "': node spacing must be positive, got " << h);
  const bool material_below = closing_shift_x < 0.0;
  for (std::size_t k = 0; k < n_surface; ++k) {
    const Vec2& p = surface[k];
    SG_VERIFY(std::isfinite(p.x()) && std::isfinite(p.y()),
              "body '" << body_name << "': surface point " << k << " is not finite");
    SG_VERIFY(material_below ? back_y < p.y() : back_y > p.y(),
              "body '" << body_name << "': the back face y = " << back_y << " must lie "
                       << (material_below ? "below" : "above") << " every surface point (point "
                       << k << " has y = " << p.y() << ")");
    if (k > 0) {
      const double dx = p.x() - surface[k - 1].x();
      SG_VERIFY(material_below ? dx < 0.0 : dx > 0.0,
                "body '" << body_name << "': surface x must be strictly "
                         << (material_below ? "decreasing" : "increasing") << " (closing shift "
                         << closing_shift_x << "), point " << k << " breaks it");
    }
  }
  const double span = std::abs(surface.back().x() - surface.front().x());
  SG_VERIFY(span < period, "body '" << body_name << "': the surface spans " << span
                                    << " in x, not less than the period " << period);
}

// Depths below the surface (0 at the surface, `height` at the back face) of a column's nodes,
// from the back face up, graded (issue #32): the spacing grows linearly with depth z from h at
// the surface to `interior` at the back face, s(z) = h + a z with a = (interior - h) / height.
// In the stretched coordinate xi(z) = integral dz / s = ln(1 + a z / h) / a the nodes are
// equally spaced, xi_k = k xi(height) / n with n = ceil(xi(height)) intervals (each at most
// about s(z) long), so z_k = h (exp(a xi_k) - 1) / a. The same law for every column (each
// with its own height), so that neighbouring columns' nodes still zip into triangles.
std::vector<double> graded_depths(double height, double h, double interior) {
  const double a = (interior - h) / height;
  const double stretched = std::log1p(a * height / h) / a;
  const int intervals = std::max(1, static_cast<int>(std::ceil(stretched - 1e-9)));
  std::vector<double> depth(static_cast<std::size_t>(intervals) + 1);
  for (int i = 0; i <= intervals; ++i) {
    const double xi = stretched * static_cast<double>(intervals - i) / intervals;
    depth[static_cast<std::size_t>(i)] = h * std::expm1(a * xi) / a;
  }
  depth.front() = height;  // exactly on the back face
  return depth;
}

// The strip's nodes: the surface points, then per column the nodes below (or above) them down
// to the back face, at most h apart (graded: see graded_depths).
struct StripColumns {
  std::vector<Column> columns;
  std::vector<Vec2> nodes;
  std::vector<int> node_column;
  std::vector<int> back_nodes;
  // Per node: the longer of the two intervals of its column on either side of it.
  std::vector<double> column_interval;
};

// Graded strips: each node's MLS support reaches at least 1.5 times its column interval. Deep
// in a graded strip the rows are further apart (up to interior_spacing) than the columns (the
// surface spacing), so a node's k = 8 nearest neighbours may all lie in its own row, with the
// next row's node exactly on the support's edge (weight 0): the moment matrix at a back-face
// point was singular (measured: reciprocal condition 0 with 7 covering nodes, 0.05 / 0.2).
constexpr double kGradedStripSupportPerInterval = 1.5;
void set_column_intervals(StripColumns& built) {
  built.column_interval.assign(built.nodes.size(), 0.0);
  for (const Column& column : built.columns)
    for (std::size_t i = 0; i + 1 < column.nodes.size(); ++i) {
      const auto a = static_cast<std::size_t>(column.nodes[i]);
      const auto b = static_cast<std::size_t>(column.nodes[i + 1]);
      const double interval = std::abs(built.nodes[b].y() - built.nodes[a].y());
      built.column_interval[a] = std::max(built.column_interval[a], interval);
      built.column_interval[b] = std::max(built.column_interval[b], interval);
    }
}
StripColumns build_columns(const Polygon& surface, double back_y, double h, double interior,
                           bool material_below) {
  const std::size_t n_surface = surface.size();
  StripColumns out;
  std::vector<Column>& columns = out.columns;
  std::vector<Vec2>& nodes = out.nodes;
  std::vector<int>& node_column = out.node_column;
  std::vector<int>& back_nodes = out.back_nodes;
  // Columns in increasing x; surface point k sits on column c(k).
  columns.resize(n_surface);
  nodes.assign(surface.begin(), surface.end());
  node_column.resize(n_surface);
  back_nodes.resize(n_surface);
  for (std::size_t c = 0; c < n_surface; ++c) {
    const std::size_t k = material_below ? n_surface - 1 - c : c;
    const Vec2& top = surface[k];
    const double height = std::abs(top.y() - back_y);
    const bool graded = interior > h && height > h;
    const std::vector<double> depth =
        graded ? graded_depths(height, h, interior) : std::vector<double>();
    const int intervals = graded ? static_cast<int>(depth.size()) - 1
                                 : std::max(1, static_cast<int>(std::ceil(height / h - 1e-9)));
    Column& column = columns[c];
    column.x = top.x();
    node_column[k] = static_cast<int>(c);
    // Fraction 0 at the back face, 1 at the surface; stored from low to high y.
    std::vector<int> from_back;
    for (int i = 0; i <= intervals; ++i) {
      if (i == intervals) {
        from_back.push_back(static_cast<int>(k));
        continue;
      }
      const double y =
          graded ? top.y() + (back_y - top.y()) * depth[static_cast<std::size_t>(i)] / height
                 : back_y + (top.y() - back_y) * static_cast<double>(i) / intervals;
      from_back.push_back(static_cast<int>(nodes.size()));
      nodes.emplace_back(top.x(), y);
      node_column.push_back(static_cast<int>(c));
    }
    back_nodes[c] = from_back.front();
    column.nodes = from_back;
    if (!material_below) std::reverse(column.nodes.begin(), column.nodes.end());
  }
  return out;
}

// Row-sum lumping as in discretize_mesh: nodal volume = integral of N_I over one period.
void lump_strip_volumes(BodyDiscretization& d, const std::vector<Vec2>& nodes,
                        const std::string& body_name) {
  const std::size_t n = nodes.size();
  d.lumped_volume.assign(n, 0.0);
  for (std::size_t g = 0; g < d.gauss_rows.points(); ++g)
    for (auto k = d.gauss_rows.offset[g]; k < d.gauss_rows.offset[g + 1]; ++k)
      d.lumped_volume[static_cast<std::size_t>(d.gauss_rows.node[static_cast<std::size_t>(k)])] +=
          d.gauss_weight[g] * d.gauss_rows.value[static_cast<std::size_t>(k)];
  for (std::size_t i = 0; i < n; ++i)
    SG_VERIFY(d.lumped_volume[i] > 0.0, "body '" << body_name << "': node " << i << " at ("
                                                 << nodes[i].x() << ", " << nodes[i].y()
                                                 << ") gets a non-positive lumped mass ("
                                                 << d.lumped_volume[i] << " x density)");
}

}  // namespace

PeriodicStripDiscretization discretize_periodic_strip(const Polygon& surface,
                                                      double closing_shift_x, double back_y,
                                                      const DiscretizationParams& params,
                                                      const std::string& body_name) {
  const std::size_t n_surface = surface.size();
  const double period = std::abs(closing_shift_x);
  const double h = params.mesh.spacing;
  check_strip_input(surface, closing_shift_x, back_y, h, body_name);
  const double interior = params.mesh.interior_spacing;
  SG_VERIFY(std::isfinite(interior) && (interior == 0.0 || interior >= h),
            "body '" << body_name << "': interior spacing " << interior
                     << " must be 0 (uniform) or at least the surface spacing h=" << h
                     << " (a graded strip coarsens towards its back face)");
  const bool material_below = closing_shift_x < 0.0;
  StripColumns built =
      build_columns(surface, back_y, h, params.mesh.interior_spacing, material_below);
  std::vector<Column>& columns = built.columns;
  std::vector<Vec2>& nodes = built.nodes;
  std::vector<int>& node_column = built.node_column;
  std::vector<int>& back_nodes = built.back_nodes;
  // zip_columns matches nodes by their fraction of the column from its lowest node; for a
  // body above its surface the lowest node is the surface one: the same fractions apply.
  std::vector<std::array<int, 3>> triangles, seam;
  for (std::size_t c = 0; c + 1 < n_surface; ++c)
    zip_columns(columns[c], columns[c + 1], triangles);
  zip_columns(columns.back(), columns.front(), seam);

  PeriodicStripDiscretization strip;
  strip.period = period;
  strip.closing_shift_x = closing_shift_x;
  strip.back_y = back_y;
  strip.back_nodes = back_nodes;
  strip.seam_triangles = seam;
  BodyDiscretization& d = strip.body;
  d.mesh.nodes = nodes;
  d.mesh.boundary_count = static_cast<int>(n_surface);
  d.mesh.triangles = triangles;

  // MLS over the nodes and their images one period to the left and to the right.
  const std::size_t n = nodes.size();
  std::vector<Vec2> extended;
  extended.reserve(3 * n);
  for (const double shift : {0.0, -period, period})
    for (const Vec2& p : nodes)
      extended.emplace_back(p.x() + shift, p.y());
  std::vector<double> min_support;  // graded strips only (see set_column_intervals)
  if (interior > h) {
    set_column_intervals(built);
    for (int image = 0; image < 3; ++image)
      for (double interval : built.column_interval)
        min_support.push_back(kGradedStripSupportPerInterval * interval);
  }
  const MlsShapeFunctions mls(extended, params.mls, body_name, min_support);
  const std::vector<double>& radius = mls.support_radius();
  d.support_radius.assign(radius.begin(), radius.begin() + static_cast<std::ptrdiff_t>(n));

  const TriangleRule& rule = triangle_rule(params.gauss_points);
  ShapeRows scratch;
  auto integrate = [&](const std::array<int, 3>& tri, bool across_seam) {
    Vec2 v[3];
    for (std::size_t i = 0; i < 3; ++i) {
      const auto node = static_cast<std::size_t>(tri[i]);
      v[i] = nodes[node];
      if (across_seam && node_column[node] == 0) v[i].x() += period;
    }
    const double area = 0.5 * cross(v[1] - v[0], v[2] - v[0]);
    SG_VERIFY(area > 0.0, "body '" << body_name << "': strip triangle (" << tri[0] << ", " << tri[1]
                                   << ", " << tri[2] << ") has non-positive area " << area);
    for (std::size_t q = 0; q < rule.weight.size(); ++q) {
      const auto& l = rule.barycentric[q];
      const Vec2 x = l[0] * v[0] + l[1] * v[1] + l[2] * v[2];
      scratch = ShapeRows{};
      mls.evaluate(x, scratch);
      append_mapped_row(scratch, 0, n, radius, d.gauss_rows, strip.gauss_image, x, body_name);
      d.gauss_weight.push_back(rule.weight[q] * area);
      d.gauss_position.push_back(x);
      d.gauss_node.push_back(nearest_vertex(tri, l));
    }
  };
  for (const auto& tri : triangles)
    integrate(tri, false);
  for (const auto& tri : seam)
    integrate(tri, true);
  // Surface (contour) points get the contact-consistent row of meshfree/contour_rows.h, over
  // the extended node set: the first point's previous neighbour is the last one shifted back
  // across the seam, the last point's next one the first shifted by closing_shift_x.
  ShapeRows at_hat, mapped;
  std::vector<std::int8_t> mapped_image;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2& x = nodes[i];
    if (i >= n_surface) {
      scratch = ShapeRows{};
      mls.evaluate(x, scratch);
      append_mapped_row(scratch, 0, n, radius, d.node_rows, strip.node_image, x, body_name);
      continue;
    }
    const Vec2 shift(closing_shift_x, 0.0);
    const Vec2 previous = i > 0 ? nodes[i - 1] : Vec2(nodes[n_surface - 1] - shift);
    const Vec2 next = i + 1 < n_surface ? nodes[i + 1] : Vec2(nodes[0] + shift);
    const HatQuadrature hat = hat_quadrature(x, previous, next);
    mapped = ShapeRows{};
    mapped_image.clear();
    for (const Vec2& q : hat.point) {
      scratch = ShapeRows{};
      mls.evaluate(q, scratch);
      append_mapped_row(scratch, 0, n, radius, mapped, mapped_image, q, body_name);
    }
    append_contour_row(mapped, mapped_image, hat, d.node_rows, &strip.node_image);
    d.contour_offset.push_back(x - hat.centroid);
  }

  lump_strip_volumes(d, nodes, body_name);
  return strip;
}

}  // namespace sg
