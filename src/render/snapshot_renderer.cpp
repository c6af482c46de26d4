#include "render/snapshot_renderer.h"

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <unordered_map>

#include "analysis/coherence.h"
#include "analysis/velocity_grid.h"
#include "core/error.h"
#include "core/file_name.h"
#include "core/version.h"
#include "io/atomic_file.h"
#include "render/coherence_frames.h"
#include "render/colormap.h"
#include "render/contact_outlines.h"
#include "render/png_text.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

struct Bounds {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0;
  double y0 = x0, y1 = -x0;
  void add(const Vec2& p) {
    x0 = std::min(x0, p.x());
    x1 = std::max(x1, p.x());
    y0 = std::min(y0, p.y());
    y1 = std::max(y1, p.y());
  }
  bool empty() const { return !(x1 >= x0 && y1 >= y0); }
};

// Min and max of the field over the points of the cells it colours (each value also
// appended to `values` when given).
void accumulate_range(const VtuMesh& mesh, const std::string& field, double& lo, double& hi,
                      std::vector<double>* values = nullptr) {
  const std::vector<double> value = point_scalar(mesh, field);
  const bool rigid_too = field_defined_on_rigid(field);
  for (std::size_t c = 0; c < mesh.cell_count(); ++c) {
    if (mesh.types[c] != kVtkTriangle && !(rigid_too && mesh.types[c] == kVtkPolygon)) continue;
    for (int p : mesh.cell(c)) {
      const double v = value[static_cast<std::size_t>(p)];
      if (!std::isfinite(v)) continue;
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      if (values) values->push_back(v);
    }
  }
}

double quantile(std::vector<double>& v, double q) {
  const auto k = static_cast<std::size_t>(std::lround(q * static_cast<double>(v.size() - 1)));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// Moreland's cool-warm diverging map (K. Moreland, "Diverging Color Maps for Scientific
// Visualization", ISVC 2009), his table sampled every 1/8: blue -> light grey -> red, equal
// lightness on both sides, so C = -0.9 and C = +0.9 look equally strong.
Rgb cool_warm(double t) {
  static constexpr std::array<std::array<double, 3>, 9> kTable = {{
      {59, 76, 192},
      {98, 130, 234},
      {141, 176, 254},
      {184, 208, 249},
      {221, 221, 221},
      {245, 196, 173},
      {244, 154, 123},
      {222, 96, 77},
      {180, 4, 38},
  }};
  if (std::isnan(t)) return {0.45, 0.45, 0.45};  // undefined: darker than the midpoint
  t = std::fmin(1.0, std::fmax(0.0, t));
  const double x = t * 8.0;
  const int i = std::min(7, static_cast<int>(x));
  const double f = x - i;
  const auto& a = kTable[static_cast<std::size_t>(i)];
  const auto& b = kTable[static_cast<std::size_t>(i + 1)];
  return {((1 - f) * a[0] + f * b[0]) / 255.0, ((1 - f) * a[1] + f * b[1]) / 255.0,
          ((1 - f) * a[2] + f * b[2]) / 255.0};
}

std::string unit_of(const std::string& field, const std::string& rate_unit) {
  if (field == "coherence") return "1";
  if (field.rfind("velocity", 0) == 0) return "length/time";
  if (field.rfind("displacement", 0) == 0) return "length";
  if (field == "green_lagrange_norm") return "1";
  if (field_shows_contact_rates(field)) return rate_unit.empty() ? "V/D or 1/time" : rate_unit;
  if (field == "von_mises" || field == "pressure" || field.rfind("sigma_", 0) == 0) return "stress";
  return "";
}

std::string format_number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

// 1, 2 or 5 times a power of ten, close to `target` from below.
double nice_length(double target) {
  const double p = std::pow(10.0, std::floor(std::log10(target)));
  for (double m : {5.0, 2.0, 1.0})
    if (m * p <= target) return m * p;
  return p;
}

bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    std::error_code ec;
    const fs::path candidate = fs::path(dir) / program;
    if (fs::is_regular_file(candidate, ec) &&
        (fs::status(candidate, ec).permissions() & fs::perms::owner_exec) != fs::perms::none)
      return true;
  }
  return false;
}

// Picture geometry, fixed for the whole series: world box -> pixels.
struct Layout {
  int width = 0, height = 0;
  double font = 12.0;
  double plot_x0 = 0, plot_y0 = 0, plot_x1 = 0, plot_y1 = 0;  // pixel box of the drawing
  double scale = 1.0;                                         // pixels per length
  double offset_x = 0, offset_y = 0;                          // pixel of world (0, 0)
  Bounds world;
  bool colour_bar = true;

  double px(double x) const { return offset_x + scale * x; }
  double py(double y) const { return offset_y - scale * y; }
};

Layout make_layout(int width, int height, const Bounds& world, bool colour_bar) {
  Layout l;
  l.width = width;
  l.height = height;
  l.world = world;
  l.colour_bar = colour_bar;
  l.font = std::clamp(height / 42.0, 9.0, 26.0);
  const double title_band = 2.2 * l.font, bottom_band = 2.8 * l.font;
  const double right_band = colour_bar ? 8.5 * l.font : l.font;
  l.plot_x0 = l.font;
  l.plot_y0 = title_band;
  l.plot_x1 = std::max(l.plot_x0 + 1.0, width - right_band);
  l.plot_y1 = std::max(l.plot_y0 + 1.0, height - bottom_band);
  const double wx = std::max(world.x1 - world.x0, 1e-12);
  const double wy = std::max(world.y1 - world.y0, 1e-12);
  l.scale = std::min((l.plot_x1 - l.plot_x0) / wx, (l.plot_y1 - l.plot_y0) / wy);
  // Centre the world box in the plot box.
  const double cx = 0.5 * (l.plot_x0 + l.plot_x1), cy = 0.5 * (l.plot_y0 + l.plot_y1);
  l.offset_x = cx - l.scale * 0.5 * (world.x0 + world.x1);
  l.offset_y = cy + l.scale * 0.5 * (world.y0 + world.y1);
  return l;
}

struct Frame {
  const VtuMesh* mesh = nullptr;
  double time = 0.0;
  std::string label;                  // snapshot number
  std::vector<double> contact_value;  // per point: its contact rate (NaN: none); may be empty
};

struct Style {
  std::string field;
  std::string rate_unit;  // RenderOptions::strain_rate_unit
  bool categorical = false;
  bool diverging = false;  // cool-warm instead of viridis
  double lo = 0.0, hi = 1.0;
  std::optional<std::pair<double, double>> periodic;
  std::string title;
};

Rgb colour_of(const Style& s, double v) {
  if (s.categorical) return category_colour(static_cast<int>(std::lround(v)));
  const double t = s.hi > s.lo ? (v - s.lo) / (s.hi - s.lo) : 0.5;
  return s.diverging ? cool_warm(t) : viridis(t);
}

// The x shifts (multiples of the period) at which a cell spanning [x0, x1] shows in the
// period box.
std::vector<double> shifts_for(const Style& s, double x0, double x1) {
  if (!s.periodic) return {0.0};
  const double a = s.periodic->first, b = s.periodic->second, L = b - a;
  std::vector<double> out;
  for (int k = -1; k <= 1; ++k)
    if (x1 + k * L > a && x0 + k * L < b) out.push_back(k * L);
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

// Rigid bodies: filled polygons, coloured by the field where it is defined on them.
void draw_rigid_bodies(cairo_t* cr, const Layout& l, const Style& s, const VtuMesh& m,
                       const std::vector<double>& value, const std::vector<double>& body) {
  const bool rigid_coloured = field_defined_on_rigid(s.field);
  for (std::size_t c = 0; c < m.cell_count(); ++c) {
    if (m.types[c] != kVtkPolygon) continue;
    const auto cell = m.cell(c);
    if (cell.empty()) continue;
    Bounds b;
    double mean = 0.0;
    for (int p : cell) {
      b.add(m.points[static_cast<std::size_t>(p)]);
      mean += value[static_cast<std::size_t>(p)];
    }
    mean /= static_cast<double>(cell.size());
    const Rgb fill =
        rigid_coloured
            ? colour_of(s, s.categorical ? body[static_cast<std::size_t>(cell[0])] : mean)
            : Rgb{0.78, 0.78, 0.78};
    for (double shift : shifts_for(s, b.x0, b.x1)) {
      cairo_new_path(cr);
      for (int p : cell) {
        const Vec2& q = m.points[static_cast<std::size_t>(p)];
        cairo_line_to(cr, l.px(q.x() + shift), l.py(q.y()));
      }
      cairo_close_path(cr);
      cairo_set_source_rgb(cr, fill.r, fill.g, fill.b);
      cairo_fill_preserve(cr);
      cairo_set_source_rgba(cr, 0.15, 0.15, 0.15, 0.9);
      cairo_set_line_width(cr, 1.0);
      cairo_stroke(cr);
    }
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
      for (double shift : shifts_for(s, x0, x1)) {
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
    for (double shift : shifts_for(s, x0, x1)) {
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
  for (double shift : shifts_for(s, std::min(a.x(), b.x()), std::max(a.x(), b.x()))) {
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

void draw_frame(cairo_t* cr, const Layout& l, const Style& s, const Frame& f) {
  const VtuMesh& m = *f.mesh;
  const std::vector<double> value = point_scalar(m, s.field == "body" ? "body_id" : s.field);
  const std::vector<double> body = point_scalar(m, "body_id");

  cairo_save(cr);
  cairo_rectangle(cr, l.plot_x0, l.plot_y0, l.plot_x1 - l.plot_x0, l.plot_y1 - l.plot_y0);
  cairo_clip(cr);
  if (s.periodic) {
    // The period: a light band, so that the seam-wrapped cell reads as one.
    const double xa = l.px(s.periodic->first), xb = l.px(s.periodic->second);
    cairo_rectangle(cr, xa, l.py(l.world.y1), xb - xa, l.py(l.world.y0) - l.py(l.world.y1));
    cairo_set_source_rgb(cr, 0.965, 0.965, 0.965);
    cairo_fill_preserve(cr);
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

void draw_text(cairo_t* cr, double x, double y, const std::string& text, double size,
               double align = 0.0) {
  cairo_set_font_size(cr, size);
  cairo_text_extents_t e;
  cairo_text_extents(cr, text.c_str(), &e);
  cairo_move_to(cr, x - align * e.x_advance, y);
  cairo_show_text(cr, text.c_str());
}

void draw_decorations(cairo_t* cr, const Layout& l, const Style& s, const Frame& f) {
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  // Title: run, field, time.
  std::ostringstream title;
  if (!s.title.empty()) title << s.title << "   ";
  title << s.field << "   t = " << format_number(f.time);
  draw_text(cr, l.plot_x0, 1.4 * l.font, title.str(), l.font);
  draw_text(cr, l.width - l.font, 1.4 * l.font, "frame " + f.label, 0.8 * l.font, 1.0);

  // Scale bar under the drawing, bottom left.
  const double world_width = l.world.x1 - l.world.x0;
  const double length = nice_length(world_width / 5.0);
  const double bar_px = length * l.scale;
  const double bx = std::max(l.plot_x0, l.px(l.world.x0));
  const double by = l.plot_y1 + 1.1 * l.font;
  cairo_rectangle(cr, bx, by, bar_px, 0.35 * l.font);
  cairo_fill(cr);
  for (double x : {bx, bx + bar_px}) {
    cairo_move_to(cr, x, by - 0.25 * l.font);
    cairo_line_to(cr, x, by + 0.6 * l.font);
  }
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
  draw_text(cr, bx + bar_px + 0.6 * l.font, by + 0.45 * l.font, format_number(length) + " (length)",
            0.85 * l.font);

  if (!l.colour_bar) return;
  // Colour bar, right: the map sampled finely, the range at its ends, a few ticks between.
  const double cx = l.plot_x1 + 1.2 * l.font, cw = 1.3 * l.font;
  const double top = l.plot_y0 + 2.4 * l.font, bottom = l.plot_y1 - 0.5 * l.font;
  cairo_pattern_t* bar = cairo_pattern_create_linear(0, bottom, 0, top);
  for (int k = 0; k <= 20; ++k) {
    const Rgb c = s.diverging ? cool_warm(k / 20.0) : viridis(k / 20.0);
    cairo_pattern_add_color_stop_rgb(bar, k / 20.0, c.r, c.g, c.b);
  }
  cairo_rectangle(cr, cx, top, cw, bottom - top);
  cairo_set_source(cr, bar);
  cairo_fill_preserve(cr);
  cairo_pattern_destroy(bar);
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
  const std::string unit = unit_of(s.field, s.rate_unit);
  draw_text(cr, cx, top - 1.5 * l.font, s.field, 0.85 * l.font);
  if (!unit.empty()) draw_text(cr, cx, top - 0.5 * l.font, "(" + unit + ")", 0.75 * l.font);
  const int ticks = 5;
  for (int k = 0; k < ticks; ++k) {
    const double t = static_cast<double>(k) / (ticks - 1);
    const double y = bottom - t * (bottom - top);
    cairo_move_to(cr, cx + cw, y);
    cairo_line_to(cr, cx + cw + 0.35 * l.font, y);
    cairo_stroke(cr);
    draw_text(cr, cx + cw + 0.55 * l.font, y + 0.3 * l.font,
              format_number(s.lo + t * (s.hi - s.lo)), 0.8 * l.font);
  }
}

// Coherence at each grain's centre, per frame, indexed by body id (NaN for bodies without
// a grain row or where C is undefined): the numbers the "coherence" pictures show.
std::vector<std::vector<double>> grain_coherence(const fs::path& run_dir,
                                                 const std::vector<PvdEntry>& entries,
                                                 const RenderOptions& options, std::string& note) {
  std::vector<GrainSnapshot> snaps;
  for (const PvdEntry& e : entries) {
    const fs::path csv = run_dir / "grains" / (e.file.stem().string() + ".csv");
    SG_VERIFY(fs::exists(csv), "render --field coherence: '"
                                   << csv.string() << "' is missing (the grain snapshot of '"
                                   << e.file.filename().string() << "')");
    snaps.push_back(
        without_bodies(read_grain_snapshot(csv.string(), e.time), options.non_grain_rows));
  }
  double diameter = options.mean_diameter;
  for (std::size_t k = 0; !(diameter > 0.0) && k < snaps.size(); ++k)
    diameter = mean_equivalent_diameter(snaps[k]);
  SG_VERIFY(diameter > 0.0,
            "render --field coherence: no grain in " << (run_dir / "grains").string());
  const CoherenceSetup setup = choose_coherence_setup(snaps, diameter, options.periodic, {});
  note = "coherence grid: " + setup.note;
  std::vector<std::vector<double>> out;
  for (const GrainSnapshot& snap : snaps) {
    const CoherenceField c =
        compute_coherence(interpolate_velocity_grid(snap, setup.grid, setup.params.interpolation),
                          setup.params.coherence);
    std::vector<double> by_body;
    for (std::size_t g = 0; g < snap.size(); ++g) {
      int id = -1;
      try {
        id = std::stoi(snap.body[g]);
      } catch (const std::exception&) {
        SG_THROW("render --field coherence: grain snapshot at t = "
                 << snap.time << ": body '" << snap.body[g] << "' is not a body number");
      }
      SG_VERIFY(id >= 0 && id < (1 << 24), "render --field coherence: body number " << id);
      if (by_body.size() <= static_cast<std::size_t>(id))
        by_body.resize(static_cast<std::size_t>(id) + 1, std::numeric_limits<double>::quiet_NaN());
      by_body[static_cast<std::size_t>(id)] = coherence_at(c, snap.position[g]);
    }
    out.push_back(std::move(by_body));
  }
  return out;
}

// Adds the point array "coherence" to a mesh: each point gets its body's value.
void add_coherence_array(VtuMesh& m, const std::vector<double>& by_body) {
  const std::vector<double> body = point_scalar(m, "body_id");
  VtuArray a;
  a.name = "coherence";
  a.values.resize(m.points.size(), std::numeric_limits<double>::quiet_NaN());
  for (std::size_t p = 0; p < body.size(); ++p) {
    const long id = std::lround(body[p]);
    if (id >= 0 && static_cast<std::size_t>(id) < by_body.size())
      a.values[p] = by_body[static_cast<std::size_t>(id)];
  }
  m.point_data.push_back(std::move(a));
}

void write_png(const Layout& l, const Style& s, const Frame& f, const fs::path& path) {
  cairo_surface_t* surface = cairo_image_surface_create(CAIRO_FORMAT_RGB24, l.width, l.height);
  cairo_t* cr = cairo_create(surface);
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  draw_frame(cr, l, s, f);
  draw_decorations(cr, l, s, f);
  cairo_destroy(cr);
  cairo_surface_flush(surface);
  // To memory first, to add the version of softgrain that drew it (render/png_text.h); then
  // atomically: a reader never sees half a picture.
  std::string png;
  const cairo_status_t status = cairo_surface_write_to_png_stream(
      surface,
      [](void* closure, const unsigned char* data, unsigned int length) {
        static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
        return CAIRO_STATUS_SUCCESS;
      },
      &png);
  cairo_surface_destroy(surface);
  SG_VERIFY(status == CAIRO_STATUS_SUCCESS,
            "cannot write '" << path.string() << "': " << cairo_status_to_string(status));
  write_file_atomically(path, with_png_text(png, "Software", softgrain_version_line()));
}

}  // namespace

const std::vector<std::string>& render_field_choices() {
  static const std::vector<std::string> choices = {"von_mises",
                                                   "velocity",
                                                   "velocity_x",
                                                   "velocity_y",
                                                   "body",
                                                   "coherence",
                                                   "green_lagrange_norm",
                                                   "strain_rate",
                                                   "strain_rate_instant",
                                                   "pressure",
                                                   "sigma_xx",
                                                   "sigma_yy",
                                                   "sigma_xy",
                                                   "displacement",
                                                   "displacement_x",
                                                   "displacement_y",
                                                   "body_id",
                                                   "material_id"};
  return choices;
}

bool field_defined_on_rigid(const std::string& field) {
  return field.rfind("velocity", 0) == 0 || field.rfind("displacement", 0) == 0 ||
         field == "body" || field == "body_id" || field == "coherence";
}

std::pair<double, double> field_range(const std::vector<VtuMesh>& meshes,
                                      const std::string& field) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const auto& m : meshes)
    accumulate_range(m, field, lo, hi);
  SG_VERIFY(hi >= lo, "field '" << field << "': no point of any snapshot is coloured by it");
  return {lo, hi};
}

namespace {

void check_options(const RenderOptions& options) {
  SG_VERIFY(options.width >= 64 && options.height >= 64 && options.width <= 16384 &&
                options.height <= 16384,
            "render: picture size " << options.width << "x" << options.height
                                    << " outside 64..16384 pixels");
  if (options.range)
    SG_VERIFY(options.range->second > options.range->first,
              "render: --range " << options.range->first << " " << options.range->second
                                 << ": MAX must exceed MIN");
}

// Pass 1, over every frame: the drawing box, and (for a field read from the .vtu with no
// given range) the range of the coloured values with every value for the robust range.
struct SeriesExtent {
  Bounds world;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  std::vector<double> values;
  std::string contact_note;  // why the contact rates are not drawn (render/contact_outlines.h)
};

// The contact rates drawn on the outlines are coloured with the field's map: they count in
// its range.
void accumulate_contact_range(const fs::path& field_file, std::size_t points, SeriesExtent& e) {
  for (const double v : contact_rates_on_points(field_file, points, e.contact_note)) {
    if (!std::isfinite(v)) continue;
    e.lo = std::min(e.lo, v);
    e.hi = std::max(e.hi, v);
    e.values.push_back(v);
  }
}

SeriesExtent measure_series(const std::vector<PvdEntry>& entries, const Style& style,
                            const RenderOptions& options, const fs::path& pvd) {
  SeriesExtent e;
  const bool coherence = options.field == "coherence";
  for (const auto& entry : entries) {
    const VtuMesh m = read_vtu(entry.file);
    for (const Vec2& p : m.points)
      e.world.add(p);
    if (coherence) continue;  // computed from the grain snapshots below; range fixed
    if (!style.categorical && !options.range) {
      accumulate_range(m, options.field, e.lo, e.hi, &e.values);
      if (field_shows_contact_rates(options.field))
        accumulate_contact_range(entry.file, m.points.size(), e);
    } else
      (void)point_scalar(m, options.field);  // fail early on an unknown field
  }
  SG_VERIFY(!e.world.empty(), pvd.string() << ": the snapshots hold no point");
  if (options.periodic) {
    e.world.x0 = options.periodic->first;
    e.world.x1 = options.periodic->second;
  }
  return e;
}

// The colour range: given, else robust, else full (with a hint when it is dominated by
// outliers); C is always [-1, 1].
void choose_range(SeriesExtent& e, Style& style, const RenderOptions& options,
                  RenderResult& result) {
  const bool coherence = options.field == "coherence";
  double lo = e.lo, hi = e.hi;
  if (coherence) {
    // C lies in [-1, 1] (Cauchy-Schwarz, coherence.h): one fixed range for every run.
    lo = -1.0;
    hi = 1.0;
  }
  if (options.range) {
    lo = options.range->first;
    hi = options.range->second;
  } else if (!e.values.empty() && !coherence) {
    const double q01 = quantile(e.values, 0.01), q99 = quantile(e.values, 0.99);
    if (options.robust_range) {
      lo = q01;
      hi = q99;
    } else if (hi > lo && q99 - q01 < 0.2 * (hi - lo)) {
      result.note = "98% of the values lie in [" + format_number(q01) + ", " + format_number(q99) +
                    "], a fifth of the full range: try --robust or --range";
    }
  }
  SG_VERIFY(hi >= lo, "field '" << options.field << "': no point of any snapshot is coloured by it"
                                << " (rigid bodies only?)");
  style.lo = lo;
  style.hi = hi;
  result.has_range = true;
  result.range_min = lo;
  result.range_max = hi;
}

// A small margin so that outlines on the box's edge are not cut.
Bounds with_margin(Bounds world, bool periodic) {
  const double margin = 0.01 * std::max(world.x1 - world.x0, world.y1 - world.y0);
  if (!periodic) {
    world.x0 -= margin;
    world.x1 += margin;
  }
  world.y0 -= margin;
  world.y1 += margin;
  return world;
}

void add_note(RenderResult& result, const std::string& n) {
  result.note += (result.note.empty() ? "" : "; ") + n;
}

// The movie: ffmpeg if present; frames must be numbered consecutively.
void make_movie(const std::vector<PvdEntry>& entries, const RenderOptions& options,
                const fs::path& out_dir, RenderResult& result) {
  if (!options.movie || result.images.size() < 2) {
    if (options.movie) add_note(result, "one frame: no movie");
  } else if (!on_path("ffmpeg")) {
    add_note(result, "ffmpeg not found on PATH: no movie (the PNG frames are written)");
  } else {
    const fs::path mp4 = out_dir / (options.field + ".mp4");
    const std::string start = entries.front().file.stem().string();
    std::ostringstream cmd;
    cmd << "ffmpeg -y -loglevel error -framerate 8 -start_number " << std::stoi(start) << " -i '"
        << (out_dir / (options.field + "_%06d.png")).string()
        << "' -vf 'scale=trunc(iw/2)*2:trunc(ih/2)*2' -pix_fmt yuv420p -vcodec libx264 '"
        << mp4.string() << "' < /dev/null";
    if (std::system(cmd.str().c_str()) == 0)
      result.movie = mp4;
    else
      add_note(result, "ffmpeg failed: no movie (command: " + cmd.str() + ")");
  }
}

}  // namespace

RenderResult render_run(const fs::path& run_dir, const RenderOptions& options) {
  check_options(options);
  const fs::path pvd = run_dir / "fields.pvd";
  SG_VERIFY(fs::exists(pvd), "'" << run_dir.string() << "' has no fields.pvd: not a run folder, "
                                 << "or the run wrote no field snapshot");
  const std::vector<PvdEntry> entries = read_pvd(pvd);
  SG_VERIFY(!entries.empty(), pvd.string() << ": no snapshot listed");

  Style style;
  style.field = options.field;
  style.rate_unit = options.strain_rate_unit;
  style.categorical = options.field == "body" || options.field == "body_id";
  const bool coherence = options.field == "coherence";
  style.diverging = coherence;
  style.periodic = options.periodic;
  style.title = options.title;

  // Pass 1: the drawing box and the colour range, fixed for the series.
  SeriesExtent extent = measure_series(entries, style, options, pvd);
  RenderResult result;
  std::vector<std::vector<double>> coherence_by_frame;
  if (coherence) coherence_by_frame = grain_coherence(run_dir, entries, options, result.note);
  if (!style.categorical) choose_range(extent, style, options, result);
  const Layout layout =
      make_layout(options.width, options.height,
                  with_margin(extent.world, options.periodic.has_value()), !style.categorical);

  // Pass 2: the pictures.
  require_plain_file_name(options.field, "render --field (names its pictures)");
  const fs::path out_dir = run_dir / "render";
  fs::create_directories(out_dir);
  const std::size_t first = options.last_frame_only ? entries.size() - 1 : 0;
  for (std::size_t i = first; i < entries.size(); ++i) {
    VtuMesh m = read_vtu(entries[i].file);
    if (coherence) add_coherence_array(m, coherence_by_frame[i]);
    const std::string number = entries[i].file.stem().string();
    Frame frame{&m, entries[i].time, number, {}};
    if (field_shows_contact_rates(options.field))
      frame.contact_value =
          contact_rates_on_points(entries[i].file, m.points.size(), extent.contact_note);
    const fs::path png = out_dir / (options.field + "_" + number + ".png");
    write_png(layout, style, frame, png);
    result.images.push_back(png);
  }
  if (!extent.contact_note.empty()) add_note(result, extent.contact_note);
  make_movie(entries, options, out_dir, result);
  return result;
}

namespace {

// The image surface of a PNG file; throws sg::Error naming the file if it cannot be read.
cairo_surface_t* read_png(const fs::path& png) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(png.c_str());
  const cairo_status_t status = cairo_surface_status(s);
  if (status != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(s);
    SG_THROW("cannot read PNG '" << png.string() << "': " << cairo_status_to_string(status));
  }
  return s;
}

}  // namespace

PngPixels png_pixels(const fs::path& png) {
  cairo_surface_t* s = read_png(png);
  cairo_surface_t* rgb = cairo_image_surface_create(
      CAIRO_FORMAT_RGB24, cairo_image_surface_get_width(s), cairo_image_surface_get_height(s));
  cairo_t* cr = cairo_create(rgb);  // whatever the file's format: drawn onto RGB24
  cairo_set_source_surface(cr, s, 0, 0);
  cairo_paint(cr);
  cairo_destroy(cr);
  cairo_surface_flush(rgb);
  PngPixels out;
  out.width = cairo_image_surface_get_width(rgb);
  out.height = cairo_image_surface_get_height(rgb);
  const int stride = cairo_image_surface_get_stride(rgb);
  const unsigned char* data = cairo_image_surface_get_data(rgb);
  out.rgb.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height));
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x) {
      std::uint32_t v = 0;
      std::memcpy(&v, data + static_cast<std::ptrdiff_t>(y) * stride + 4 * x, 4);
      out.rgb[static_cast<std::size_t>(y * out.width + x)] = v & 0xffffffu;  // native-endian word
    }
  cairo_surface_destroy(rgb);
  cairo_surface_destroy(s);
  return out;
}

std::pair<int, int> png_size(const fs::path& png) {
  cairo_surface_t* s = read_png(png);
  const std::pair<int, int> size(cairo_image_surface_get_width(s),
                                 cairo_image_surface_get_height(s));
  cairo_surface_destroy(s);
  return size;
}

}  // namespace sg
