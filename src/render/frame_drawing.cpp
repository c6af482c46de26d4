#include "render/frame_drawing.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <unordered_map>

#include "render/contact_outlines.h"
#include "render/snapshot_renderer.h"

namespace sg {
namespace {

// The x shifts (multiples of the period) at which a cell spanning [x0, x1] shows in the drawn
// part of the world (one period, or more when the layout repeats it to fill the width).
std::vector<double> shifts_for(const Layout& l, const Style& s, double x0, double x1) {
  if (!s.periodic) return {0.0};
  const double L = s.periodic->second - s.periodic->first;
  const double lo = l.world.lo.x(), hi = l.world.hi.x();
  std::vector<double> out;
  for (double k = std::floor((lo - x1) / L); k <= std::ceil((hi - x0) / L); k += 1.0)
    if (x1 + k * L > lo && x0 + k * L < hi) out.push_back(k * L);
  return out;
}

// Triangle vertices, unwrapped to the periodic image nearest the first vertex (the writer
// may wrap each node into the period on its own).
std::array<Vec2, 3> triangle_points(const VtuMesh& m, std::span<const int> cell, const Style& s) {
  std::array<Vec2, 3> p;
  for (int k = 0; k < 3; ++k)
    p[static_cast<std::size_t>(k)] =
        m.points[static_cast<std::size_t>(cell[static_cast<std::size_t>(k)])];
  if (s.periodic) {
    const double L = s.periodic->second - s.periodic->first;
    for (int k = 1; k < 3; ++k) {
      Vec2& q = p[static_cast<std::size_t>(k)];
      q.x() -= L * std::round((q.x() - p[0].x()) / L);
    }
  }
  return p;
}

// A rigid body's contour as drawn: each point unwrapped to the periodic image nearest the one
// before it, so that a body crossing the seam stays whole. A first body spanning the period is
// written as its open surface (model/model.h Body::open_contour): its walk then ends one period
// away from its start, `period_shift` (+-L; 0 for a closed contour).
struct RigidOutline {
  std::vector<Vec2> points;
  double period_shift = 0.0;
  BoundingBox box;
};

RigidOutline rigid_outline(const VtuMesh& m, std::span<const int> cell, const Style& s) {
  RigidOutline o;
  for (int p : cell) {
    Vec2 q = m.points[static_cast<std::size_t>(p)];
    if (s.periodic && !o.points.empty()) {
      const double L = s.periodic->second - s.periodic->first;
      q.x() -= L * std::round((q.x() - o.points.back().x()) / L);
    }
    o.points.push_back(q);
    o.box.add(q);
  }
  if (s.periodic && o.points.size() > 2) {
    const double L = s.periodic->second - s.periodic->first;
    const double closing_gap = o.points.front().x() - o.points.back().x();
    o.period_shift = L * std::round((o.points.back().x() - o.points.front().x()) / L);
    if (std::abs(closing_gap + o.period_shift) > 0.5 * L) o.period_shift = 0.0;
  }
  return o;
}

// Adds the path of a rigid body at x shift `shift` (a sub-path). A closed contour is closed. An
// open surface is completed by its seam segment (to its first point one period on) and filled out
// to the back, beyond the drawn world: the body lies to the left of the surface's direction (the
// contours are counterclockwise), above a surface written in +x, below one written in -x.
// `surface_only`: the path of the surface alone, for its outline.
void add_rigid_path(cairo_t* cr, const Layout& l, const RigidOutline& o, double shift,
                    bool surface_only) {
  cairo_new_sub_path(cr);
  for (const Vec2& q : o.points)
    cairo_line_to(cr, l.px(q.x() + shift), l.py(q.y()));
  if (o.period_shift == 0.0) {
    cairo_close_path(cr);
    return;
  }
  const Vec2& first = o.points.front();
  cairo_line_to(cr, l.px(first.x() + o.period_shift + shift), l.py(first.y()));
  if (surface_only) return;
  const double depth = l.world.hi.y() - l.world.lo.y() + (o.box.hi.y() - o.box.lo.y());
  const double back = o.period_shift > 0.0 ? std::max(l.world.hi.y(), o.box.hi.y()) + depth
                                           : std::min(l.world.lo.y(), o.box.lo.y()) - depth;
  cairo_line_to(cr, l.px(first.x() + o.period_shift + shift), l.py(back));
  cairo_line_to(cr, l.px(first.x() + shift), l.py(back));
  cairo_close_path(cr);
}

// Rigid bodies: filled polygons, coloured by the field where it is defined on them.
void draw_rigid_bodies(cairo_t* cr, const Layout& l, const Style& s, const VtuMesh& m,
                       const std::vector<double>& value, const std::vector<double>& body) {
  const bool rigid_coloured = field_defined_on_rigid(s.field);
  for (std::size_t c = 0; c < m.cell_count(); ++c) {
    if (m.types[c] != kVtkPolygon) continue;
    const auto cell = m.cell(c);
    if (cell.empty()) continue;
    const RigidOutline outline = rigid_outline(m, cell, s);
    double mean = 0.0;
    for (int p : cell)
      mean += value[static_cast<std::size_t>(p)];
    mean /= static_cast<double>(cell.size());
    const Rgb fill =
        rigid_coloured
            ? colour_of(s, s.categorical ? body[static_cast<std::size_t>(cell[0])] : mean)
            : Rgb{0.78, 0.78, 0.78};
    const double x0 = std::min(outline.box.lo.x(), outline.box.lo.x() + outline.period_shift);
    const double x1 = std::max(outline.box.hi.x(), outline.box.hi.x() + outline.period_shift);
    // The images filled as one path, so that no seam shows where they meet.
    const std::vector<double> shifts = shifts_for(l, s, x0, x1);
    cairo_new_path(cr);
    for (double shift : shifts)
      add_rigid_path(cr, l, outline, shift, false);
    cairo_set_source_rgb(cr, fill.r, fill.g, fill.b);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    cairo_fill(cr);
    cairo_new_path(cr);
    for (double shift : shifts)
      add_rigid_path(cr, l, outline, shift, true);
    cairo_set_source_rgba(cr, 0.15, 0.15, 0.15, 0.9);
    cairo_set_line_width(cr, 1.0);
    cairo_stroke(cr);
  }
}

// Deformable grains, one flat colour per body: all its triangles as one path, so no seams
// show between them.
void draw_flat_grains(cairo_t* cr, const Layout& l, const Style& s, const VtuMesh& m,
                      const std::vector<double>& body) {
  std::unordered_map<int, std::vector<std::size_t>> by_body;
  for (std::size_t c = 0; c < m.cell_count(); ++c)
    if (m.types[c] == kVtkTriangle)
      by_body[static_cast<int>(std::lround(body[static_cast<std::size_t>(m.cell(c)[0])]))]
          .push_back(c);
  for (const auto& [id, cells] : by_body) {
    cairo_new_path(cr);
    for (std::size_t c : cells) {
      const auto p = triangle_points(m, m.cell(c), s);
      const double x0 = std::min({p[0].x(), p[1].x(), p[2].x()});
      const double x1 = std::max({p[0].x(), p[1].x(), p[2].x()});
      for (double shift : shifts_for(l, s, x0, x1)) {
        cairo_move_to(cr, l.px(p[0].x() + shift), l.py(p[0].y()));
        cairo_line_to(cr, l.px(p[1].x() + shift), l.py(p[1].y()));
        cairo_line_to(cr, l.px(p[2].x() + shift), l.py(p[2].y()));
        cairo_close_path(cr);
      }
    }
    const Rgb c = category_colour(id);
    cairo_set_source_rgb(cr, c.r, c.g, c.b);
    cairo_set_fill_rule(cr, CAIRO_FILL_RULE_WINDING);
    cairo_fill(cr);
  }
}

// Deformable grains shaded by the field: one mesh-pattern patch per triangle (and per
// periodic image).
void draw_shaded_grains(cairo_t* cr, const Layout& l, const Style& s, const VtuMesh& m,
                        const std::vector<double>& value) {
  cairo_pattern_t* mesh = cairo_pattern_create_mesh();
  bool any = false;
  for (std::size_t c = 0; c < m.cell_count(); ++c) {
    if (m.types[c] != kVtkTriangle) continue;
    const auto cell = m.cell(c);
    const auto p = triangle_points(m, cell, s);
    const double x0 = std::min({p[0].x(), p[1].x(), p[2].x()});
    const double x1 = std::max({p[0].x(), p[1].x(), p[2].x()});
    for (double shift : shifts_for(l, s, x0, x1)) {
      cairo_mesh_pattern_begin_patch(mesh);
      cairo_mesh_pattern_move_to(mesh, l.px(p[0].x() + shift), l.py(p[0].y()));
      cairo_mesh_pattern_line_to(mesh, l.px(p[1].x() + shift), l.py(p[1].y()));
      cairo_mesh_pattern_line_to(mesh, l.px(p[2].x() + shift), l.py(p[2].y()));
      for (unsigned k = 0; k < 3; ++k) {
        const Rgb col = colour_of(s, value[static_cast<std::size_t>(cell[k])]);
        cairo_mesh_pattern_set_corner_color_rgb(mesh, k, col.r, col.g, col.b);
      }
      cairo_mesh_pattern_end_patch(mesh);
      any = true;
    }
  }
  if (any) {
    cairo_set_source(cr, mesh);
    cairo_paint(cr);
  }
  cairo_pattern_destroy(mesh);
}

// A segment a -> b of the picture, b unwrapped to a's periodic image, at each shift it shows.
void add_segment(cairo_t* cr, const Layout& l, const Style& s, const Vec2& a, Vec2 b) {
  if (s.periodic) {
    const double L = s.periodic->second - s.periodic->first;
    b.x() -= L * std::round((b.x() - a.x()) / L);
  }
  for (double shift : shifts_for(l, s, std::min(a.x(), b.x()), std::max(a.x(), b.x()))) {
    cairo_move_to(cr, l.px(a.x() + shift), l.py(a.y()));
    cairo_line_to(cr, l.px(b.x() + shift), l.py(b.y()));
  }
}

double outline_width(const Layout& l) {
  return std::clamp(l.scale * 0.012, 0.6, 1.5);
}

// Grain outlines: triangle edges used once within a body are its boundary.
void draw_outlines(cairo_t* cr, const Layout& l, const Style& s, const VtuMesh& m) {
  cairo_new_path(cr);
  for (const auto& [a, b] : boundary_edges(m, false))
    add_segment(cr, l, s, m.points[static_cast<std::size_t>(a)],
                m.points[static_cast<std::size_t>(b)]);
  cairo_set_source_rgba(cr, 0.1, 0.1, 0.1, 0.75);
  cairo_set_line_width(cr, outline_width(l));
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_ROUND);
  cairo_stroke(cr);
}

// The contact rates on the outlines (render/contact_outlines.h): the half of each boundary
// edge (grains and rigid bodies) at a contact's slave point, in the point's colour, wider
// than the outline so that it reads beside the grain's own shading.
void draw_contact_outlines(cairo_t* cr, const Layout& l, const Style& s, const VtuMesh& m,
                           const std::vector<double>& contact_value) {
  if (contact_value.empty()) return;
  cairo_set_line_width(cr, std::max(2.5, 3.0 * outline_width(l)));
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  for (const auto& [a, b] : boundary_edges(m, true)) {
    const Vec2& pa = m.points[static_cast<std::size_t>(a)];
    Vec2 pb = m.points[static_cast<std::size_t>(b)];
    if (s.periodic) {
      const double L = s.periodic->second - s.periodic->first;
      pb.x() -= L * std::round((pb.x() - pa.x()) / L);
    }
    const Vec2 mid = 0.5 * (pa + pb);
    for (const auto& [point, from] : {std::make_pair(a, pa), std::make_pair(b, pb)}) {
      const double v = contact_value[static_cast<std::size_t>(point)];
      if (!std::isfinite(v)) continue;
      cairo_new_path(cr);
      add_segment(cr, l, s, from, mid);
      const Rgb c = colour_of(s, v);
      cairo_set_source_rgb(cr, c.r, c.g, c.b);
      cairo_stroke(cr);
    }
  }
}

}  // namespace

void draw_frame(cairo_t* cr, const Layout& l, const Style& s, const Frame& f) {
  const VtuMesh& m = *f.mesh;
  const std::vector<double> value = point_scalar(m, s.field == "body" ? "body_id" : s.field);
  const std::vector<double> body = point_scalar(m, "body_id");

  cairo_save(cr);
  cairo_rectangle(cr, l.plot_x0, l.plot_y0, l.plot_x1 - l.plot_x0, l.plot_y1 - l.plot_y0);
  cairo_clip(cr);
  if (s.periodic) {
    // The period: a light band, so that the seam-wrapped cell reads as one (and, where the
    // layout repeats the layer to fill the width, where the period is).
    const double xa = l.px(s.periodic->first), xb = l.px(s.periodic->second);
    const double ya = l.py(l.world.hi.y()), yb = l.py(l.world.lo.y());
    cairo_rectangle(cr, xa, ya, xb - xa, yb - ya);
    cairo_set_source_rgb(cr, 0.965, 0.965, 0.965);
    cairo_fill(cr);
    cairo_rectangle(cr, l.px(l.world.lo.x()), ya, l.px(l.world.hi.x()) - l.px(l.world.lo.x()),
                    yb - ya);
    cairo_clip(cr);
  }
  draw_rigid_bodies(cr, l, s, m, value, body);
  if (s.categorical)
    draw_flat_grains(cr, l, s, m, body);
  else
    draw_shaded_grains(cr, l, s, m, value);
  draw_outlines(cr, l, s, m);
  draw_contact_outlines(cr, l, s, m, f.contact_value);
  cairo_restore(cr);
}

}  // namespace sg
