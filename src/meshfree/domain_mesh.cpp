#include "meshfree/domain_mesh.h"

// How a body's domain is meshed:
//   1. the contour points are inserted in a constrained Delaunay triangulation (CDT), each
//      contour edge a constraint;
//   2. CGAL's Delaunay refinement (Delaunay_mesher_2, Ruppert/Shewchuk style) inserts
//      circumcentres of triangles that are too large or too flat, and splits constrained
//      edges they would encroach. The size bound is set from the contour edges so that a
//      contour sampled at about h is kept as it is (CGAL User Manual, "2D Conforming
//      Triangulations and Meshes", §Meshes: criteria). Graded meshes (boundary_grading,
//      interior_spacing) bound the size by a sizing field instead, a function of the distance
//      to the contour (SizingField);
//   3. Lloyd smoothing moves every interior node to the centroid of its Voronoi cell, which
//      evens out the spacing the refinement left; our own loop, not lloyd_optimize_mesh_2,
//      for determinism (see lloyd_step). A graded mesh takes the centroid under the density
//      (h_contour / h_local)^4, so that smoothing keeps the grading instead of evening it out;
//   4. the output is read back in a canonical order: boundary by walking the domain boundary
//      counter-clockwise from boundary[0], interior sorted by position, triangles sorted.
//
// CGAL stays in this file only: including the mesher costs ~20 s and ~1 GB to compile.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wconversion"
#pragma GCC diagnostic ignored "-Wshadow"
#pragma GCC diagnostic ignored "-Wpedantic"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#pragma GCC diagnostic pop

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include "core/error.h"
#include "geometry/polygon.h"

namespace sg {

namespace {

// Shape bound of Delaunay_mesh_size_criteria_2: the squared sine of the smallest angle,
// 0.125 -> 20.7 degrees, the largest value for which CGAL guarantees termination.
constexpr double kShapeBound = 0.125;
// The size bound limits the longest edge of a triangle. Refinement stops with edges between
// about 0.6 and 1 times the bound; 1.3 times the contour spacing gives interior spacing close
// to h after smoothing and leaves triangles with one contour edge (length ~h) alone.
constexpr double kSizeBoundFactor = 1.5;
// Contour edges up to this multiple of h still set the size bound; longer edges are split by
// the mesher (their midpoints become boundary nodes) instead of coarsening the whole body.
constexpr double kLongestContourEdgeKept = 1.5;

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
// The vertex info is our node index, set once meshing is done.
using VertexBase =
    CGAL::Delaunay_mesh_vertex_base_2<Kernel,
                                      CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds>;
using Point = Cdt::Point;

// Distance from a point to the contour, capped at `cap`: the graded size stops growing at
// that distance, so only segments closer than `cap` matter, and a uniform grid of cells no
// smaller than `cap` finds all of them in the 3x3 block of cells around the point.
class CappedContourDistance {
 public:
  CappedContourDistance(const Polygon& contour, double cap, double longest_edge)
      : contour_(contour), cap_(cap), cell_(std::max(cap, longest_edge)) {
    lower_ = upper_ = contour.front();
    for (const Vec2& p : contour) {
      lower_ = lower_.cwiseMin(p);
      upper_ = upper_.cwiseMax(p);
    }
    nx_ = cell_index(upper_.x() - lower_.x()) + 1;
    ny_ = cell_index(upper_.y() - lower_.y()) + 1;
    cells_.resize(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_));
    for (std::size_t i = 0; i < contour.size(); ++i) {
      const Vec2& a = contour[i];
      const Vec2& b = contour[(i + 1) % contour.size()];
      const Vec2 lo = a.cwiseMin(b) - lower_, hi = a.cwiseMax(b) - lower_;
      for (int ix = cell_index(lo.x()); ix <= cell_index(hi.x()); ++ix)
        for (int iy = cell_index(lo.y()); iy <= cell_index(hi.y()); ++iy)
          cells_[cell(ix, iy)].push_back(static_cast<int>(i));
    }
  }

  double operator()(const Vec2& p) const {
    const int cx = std::clamp(cell_index(p.x() - lower_.x()), 0, nx_ - 1);
    const int cy = std::clamp(cell_index(p.y() - lower_.y()), 0, ny_ - 1);
    double d = cap_;
    for (int ix = std::max(cx - 1, 0); ix <= std::min(cx + 1, nx_ - 1); ++ix)
      for (int iy = std::max(cy - 1, 0); iy <= std::min(cy + 1, ny_ - 1); ++iy)
        for (int s : cells_[cell(ix, iy)]) {
          const auto i = static_cast<std::size_t>(s);
          d = std::min(
              d, project_on_segment(p, contour_[i], contour_[(i + 1) % contour_.size()]).distance);
        }
    return d;
  }

 private:
  int cell_index(double offset) const { return static_cast<int>(std::floor(offset / cell_)); }
  std::size_t cell(int ix, int iy) const {
    return static_cast<std::size_t>(iy) * static_cast<std::size_t>(nx_) +
           static_cast<std::size_t>(ix);
  }

  const Polygon& contour_;
  double cap_;
  double cell_;
  Vec2 lower_, upper_;
  int nx_ = 0, ny_ = 0;
  std::vector<std::vector<int>> cells_;  // contour edge indices per cell, row-major
};

// The size bound of a triangle at distance d from the contour (its centroid's):
//   bound(d) = min(ratio * s, s + slope * max(0, d - ramp_start)),
// s the bound at the contour. boundary_grading: ratio = grading, slope kMaxGradingSlope,
// ramp_start h (the first layer of triangles, which carries the contact nodes' MLS
// neighbourhoods, stays as fine as in a uniform mesh); interior_spacing: ratio = interior / h,
// ramp_start 0 and the slope that reaches ratio * s at the body's depth, at most
// kMaxGradingSlope (issue #32: the spacing linear from contour to centre, as the mesh ratios
// of the reference code's preprocessor). Uniform: no distance.
class SizingField {
 public:
  explicit SizingField(double size_bound) : size_bound_(size_bound) {}
  SizingField(double size_bound, double ratio, double ramp_start, double slope,
              const CappedContourDistance* distance)
      : size_bound_(size_bound),
        ratio_(ratio),
        ramp_start_(ramp_start),
        slope_(slope),
        distance_(distance) {}

  bool graded() const { return distance_ != nullptr; }
  double contour_bound() const { return size_bound_; }
  // The distance beyond which the bound stops growing (the distance cap it needs).
  double full_growth_distance() const {
    return ramp_start_ + (ratio_ - 1.0) * size_bound_ / slope_;
  }
  double operator()(const Vec2& p) const {
    if (!distance_) return size_bound_;
    const double d = (*distance_)(p);
    return std::min(ratio_ * size_bound_, size_bound_ + slope_ * std::max(0.0, d - ramp_start_));
  }

 private:
  double size_bound_;
  double ratio_ = 1.0;
  double ramp_start_ = 0.0;
  double slope_ = kMaxGradingSlope;
  const CappedContourDistance* distance_ = nullptr;  // null: uniform
};

// Delaunay_mesh_size_criteria_2 with the size bound of a SizingField at the triangle's
// centroid. Same quality measure as CGAL's (squared sine of the smallest angle, longest edge
// over the bound), so CGAL's queue ordering and termination argument are unchanged.
class GradedSizeCriteria : public CGAL::Delaunay_mesh_size_criteria_2<Cdt> {
 public:
  using Uniform = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;

  explicit GradedSizeCriteria(const SizingField* sizing)
      : CGAL::Delaunay_mesh_criteria_2<Cdt>(kShapeBound),
        Uniform(kShapeBound, sizing->contour_bound()),
        sizing_(sizing) {}

  class Is_bad : public Uniform::Is_bad {
   public:
    Is_bad(const Uniform::Is_bad& uniform, const SizingField* sizing)
        : Uniform::Is_bad(uniform), sizing_(sizing) {}

    using Uniform::Is_bad::operator();

    CGAL::Mesh_2::Face_badness operator()(const Cdt::Face_handle& face, Quality& q) const {
      const Vec2 a(face->vertex(0)->point().x(), face->vertex(0)->point().y());
      const Vec2 b(face->vertex(1)->point().x(), face->vertex(1)->point().y());
      const Vec2 c(face->vertex(2)->point().x(), face->vertex(2)->point().y());
      const double local_bound = (*sizing_)((a + b + c) / 3.0);
      std::array<double, 3> squared_edge = {(b - c).squaredNorm(), (c - a).squaredNorm(),
                                            (a - b).squaredNorm()};
      std::sort(squared_edge.begin(), squared_edge.end());
      q.second = squared_edge[2] / (local_bound * local_bound);
      if (q.size() > 1.0) {
        q.first = 1.0;  // too large: split it whatever its shape (CGAL does the same)
        return CGAL::Mesh_2::IMPERATIVELY_BAD;
      }
      // sin^2 of the smallest angle = (2 area)^2 / (product of the two longest edges)^2.
      const double twice_area = cross(b - a, c - a);
      q.first = twice_area * twice_area / (squared_edge[2] * squared_edge[1]);
      return q.sine() < this->B ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
    }

   private:
    const SizingField* sizing_;
  };

  Is_bad is_bad_object() const { return Is_bad(Uniform::is_bad_object(), sizing_); }

 private:
  const SizingField* sizing_;
};

using Mesher = CGAL::Delaunay_mesher_2<Cdt, GradedSizeCriteria>;

void verify_input(const Polygon& boundary, const DomainMeshParams& params,
                  const std::string& body_name) {
  const double h = params.spacing;
  SG_VERIFY(boundary.size() >= 3, "body '" << body_name
                                           << "': a contour needs at least 3 points, got "
                                           << boundary.size());
  for (std::size_t i = 0; i < boundary.size(); ++i)
    SG_VERIFY(boundary[i].allFinite(), "body '" << body_name << "': contour point " << i << " ("
                                                << boundary[i].x() << ", " << boundary[i].y()
                                                << ") is not finite");
  SG_VERIFY(std::isfinite(h) && h > 0.0,
            "body '" << body_name << "': node spacing h=" << h << " must be positive");
  SG_VERIFY(params.smoothing_iterations >= 0, "body '" << body_name << "': smoothing iterations "
                                                       << params.smoothing_iterations
                                                       << " must be >= 0");
  SG_VERIFY(std::isfinite(params.boundary_grading) && params.boundary_grading >= 1.0,
            "body '" << body_name << "': boundary grading " << params.boundary_grading
                     << " must be >= 1 (1 = uniform spacing)");
  const double interior = params.interior_spacing;
  SG_VERIFY(std::isfinite(interior) && (interior == 0.0 || interior >= h),
            "body '" << body_name << "': interior spacing " << interior
                     << " must be 0 (uniform) or at least the contour spacing h=" << h
                     << " (a graded mesh coarsens inwards)");
  SG_VERIFY(!(interior > h && params.boundary_grading > 1.0),
            "body '" << body_name << "': interior spacing " << interior << " and boundary grading "
                     << params.boundary_grading << " both grade the mesh; give one");
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    const double edge = (boundary[(i + 1) % boundary.size()] - boundary[i]).norm();
    SG_VERIFY(edge > 1e-9 * h, "body '" << body_name << "': contour points " << i << " and "
                                        << (i + 1) % boundary.size() << " coincide (edge length "
                                        << edge << ")");
  }
  SG_VERIFY(!is_self_intersecting(boundary),
            "body '" << body_name << "': contour is self-intersecting");
  // After the self-intersection test: a figure-eight has zero area, not a clockwise one.
  const double area = signed_area(boundary);
  SG_VERIFY(area > 0.0, "body '" << body_name << "': contour is clockwise (signed area " << area
                                 << "); contours must be counter-clockwise");
  const double equivalent_diameter = 2.0 * std::sqrt(area / std::numbers::pi);
  SG_VERIFY(h <= 0.5 * equivalent_diameter,
            "body '" << body_name << "': node spacing h=" << h
                     << " is too large for a body of equivalent diameter " << equivalent_diameter
                     << " (need h <= " << 0.5 * equivalent_diameter << ")");
  SG_VERIFY(h >= equivalent_diameter / kMaxDiameterPerSpacing,
            "body '" << body_name << "': node spacing h=" << h
                     << " is too small for a body of equivalent diameter " << equivalent_diameter
                     << " (need h >= " << equivalent_diameter / kMaxDiameterPerSpacing << ")");
  // Few contour points: the contour was sampled too coarsely for the body, i.e. at a spacing
  // too large for it (sampled at h, it has about perimeter / h points).
  SG_VERIFY(boundary.size() >= 8, "body '" << body_name << "': node spacing h=" << h
                                           << " is too large for the body: its contour has "
                                           << boundary.size()
                                           << " points, need at least 8 (sampled at h: need h <= "
                                           << perimeter(boundary) / 8.0 << ")");
}

Vec2 to_vec(const Point& p) {
  return Vec2(p.x(), p.y());
}

// Constrained Delaunay triangulation of given nodes: [0, boundary_count) the contour in order
// (each edge a constraint), then the interior. Vertex info = node index; faces inside the
// contour are marked in-domain. Built from scratch in node order, so the result depends on the
// node positions and order only, never on where the allocator put CGAL's records.
Cdt triangulate(const std::vector<Vec2>& nodes, int boundary_count, const std::string& body_name) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> vertex;
  vertex.reserve(nodes.size());
  for (const Vec2& p : nodes) {
    vertex.push_back(cdt.insert(Point(p.x(), p.y()),
                                vertex.empty() ? Cdt::Face_handle() : vertex.back()->face()));
    vertex.back()->info() = static_cast<int>(vertex.size()) - 1;
  }
  SG_INTERNAL_CHECK(cdt.number_of_vertices() == nodes.size(),
                    "body '" << body_name << "': two nodes coincide");
  const auto n = static_cast<std::size_t>(boundary_count);
  for (std::size_t i = 0; i < n; ++i)
    cdt.insert_constraint(vertex[i], vertex[(i + 1) % n]);
  const std::vector<Point> no_seeds;  // the domain is what the constraints enclose
  Mesher::mark_facets(cdt, no_seeds.begin(), no_seeds.end());
  return cdt;
}

// Part of `polygon` on the left of the directed line a->b (Sutherland-Hodgman, one edge).
std::vector<Vec2> clip_left_of(const std::vector<Vec2>& polygon, const Vec2& a, const Vec2& b) {
  std::vector<Vec2> kept;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2& p = polygon[i];
    const Vec2& q = polygon[(i + 1) % polygon.size()];
    const double sp = cross(b - a, p - a), sq = cross(b - a, q - a);
    if (sp >= 0.0) kept.push_back(p);
    if ((sp >= 0.0) != (sq >= 0.0)) kept.push_back(p + (q - p) * (sp / (sp - sq)));
  }
  return kept;
}

// One Lloyd iteration (Du, Faber & Gunzburger, SIAM Review 41, 1999): every interior node
// moves to the centroid of its Voronoi cell, the polygon through the circumcentres of its
// incident triangles, clipped by the contour edges of its star where an obtuse triangle puts
// a circumcentre outside. All targets are computed on the same triangulation, then applied.
// Written here rather than calling CGAL::lloyd_optimize_mesh_2: CGAL keeps its moving vertices
// in a std::set ordered by address, so the order of its floating-point updates, hence the
// last bits of the nodes, changed from one call to the next (measured: two calls on the
// same ellipse gave 477 of 692 nodes different after 10 iterations).
// A graded mesh (sizing given) takes the centroid under the density rho = (s / s_local)^4
// instead, over a fan of triangles from the cell's first corner, each weighted by rho at its
// centroid: a centroidal Voronoi tessellation under rho has cells of diameter ~ rho^(-1/4) in
// two dimensions (Gersho's conjecture, in Du, Faber & Gunzburger 1999), so the smoothed spacing
// follows s_local.
Vec2 cell_centroid(const std::vector<Vec2>& cell, const SizingField* sizing, double& weight) {
  double twice_area = 0.0;
  Vec2 moment = Vec2::Zero();
  if (!sizing) {
    // Centroid of a polygon from its signed-area decomposition.
    for (std::size_t k = 0; k < cell.size(); ++k) {
      const Vec2& p = cell[k];
      const Vec2& q = cell[(k + 1) % cell.size()];
      const double w = cross(p, q);
      twice_area += w;
      moment += w * (p + q);
    }
    weight = twice_area;
    return moment / (3.0 * twice_area);
  }
  for (std::size_t k = 1; k + 1 < cell.size(); ++k) {
    const Vec2 c = (cell[0] + cell[k] + cell[k + 1]) / 3.0;
    const double ratio = sizing->contour_bound() / (*sizing)(c);
    const double w = cross(cell[k] - cell[0], cell[k + 1] - cell[0]) * std::pow(ratio, 4);
    twice_area += w;
    moment += w * c;
  }
  weight = twice_area;
  return moment / twice_area;
}

void lloyd_step(const Cdt& cdt, std::vector<Vec2>& nodes, int boundary_count,
                const Polygon& contour, const SizingField* sizing) {
  std::vector<Vec2> target = nodes;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    if (v->info() < boundary_count) continue;
    std::vector<Vec2> cell;
    std::vector<std::pair<Vec2, Vec2>> contour_edges;  // of the star, counter-clockwise
    auto f = cdt.incident_faces(v);
    const auto first = f;
    do {
      // An interior vertex only touches in-domain, finite faces.
      const int j = f->index(v);
      const Point c = cdt.circumcenter(f);
      cell.emplace_back(c.x(), c.y());
      if (f->is_constrained(j))
        contour_edges.emplace_back(to_vec(f->vertex(Cdt::ccw(j))->point()),
                                   to_vec(f->vertex(Cdt::cw(j))->point()));
    } while (++f != first);
    for (const auto& [a, b] : contour_edges)
      cell = clip_left_of(cell, a, b);
    if (cell.size() < 3) continue;
    double weight = 0.0;
    const Vec2 centroid = cell_centroid(cell, sizing, weight);
    if (!(weight > 0.0)) continue;
    // A cell reaching past a contour edge outside the star (deep concave notch) could pull
    // a node out of the body: such a node stays where it is for this iteration.
    if (contains(contour, centroid)) target[static_cast<std::size_t>(v->info())] = centroid;
  }
  nodes = std::move(target);
}

// Interior nodes sorted along the longer side of the bounding box: a canonical order that
// keeps neighbours close in the node arrays, also for long strips.
void sort_interior(std::vector<Vec2>& nodes, int boundary_count) {
  Vec2 lower = nodes.front(), upper = nodes.front();
  for (const Vec2& p : nodes) {
    lower = lower.cwiseMin(p);
    upper = upper.cwiseMax(p);
  }
  const int major = (upper - lower).x() >= (upper - lower).y() ? 0 : 1;
  const int minor = 1 - major;
  std::sort(nodes.begin() + boundary_count, nodes.end(), [&](const Vec2& a, const Vec2& b) {
    return a[major] != b[major] ? a[major] < b[major] : a[minor] < b[minor];
  });
}
// Depth of a body: the largest distance from an inside point to its contour, the radius of
// its largest inscribed circle. That circle's centre lies near a vertex of the Voronoi diagram
// of the contour points, i.e. a circumcentre of their Delaunay triangles. A circumcircle passes
// through three contour points, so its radius bounds the distance from its centre to the
// contour from above: the candidates are visited by decreasing radius and the exact distance
// kept, until no radius left can beat it.
double body_depth(const Polygon& contour, const std::string& body_name) {
  const Cdt cdt = triangulate(contour, static_cast<int>(contour.size()), body_name);
  std::vector<std::pair<double, Vec2>> candidates;  // circumradius, circumcentre
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    const Vec2 centre = to_vec(cdt.circumcenter(f));
    candidates.emplace_back((centre - to_vec(f->vertex(0)->point())).norm(), centre);
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const auto& a, const auto& b) { return a.first > b.first; });
  double depth = 0.0;
  for (const auto& [radius, centre] : candidates) {
    if (radius <= depth) break;
    if (!contains(contour, centre)) continue;
    double d = radius;
    for (std::size_t i = 0; i < contour.size(); ++i)
      d = std::min(
          d, project_on_segment(centre, contour[i], contour[(i + 1) % contour.size()]).distance);
    depth = std::max(depth, d);
  }
  return depth;
}

// The sizing field of `params` (SizingField). `distance` receives the contour distance the
// field points to (empty for a uniform mesh).
SizingField sizing_field(const Polygon& boundary, const DomainMeshParams& params, double size_bound,
                         double longest_edge, std::optional<CappedContourDistance>& distance,
                         const std::string& body_name) {
  const double h = params.spacing;
  if (params.boundary_grading > 1.0) {
    const SizingField shape(size_bound, params.boundary_grading, h, kMaxGradingSlope, nullptr);
    distance.emplace(boundary, shape.full_growth_distance(), longest_edge);
    return SizingField(size_bound, params.boundary_grading, h, kMaxGradingSlope, &*distance);
  }
  if (!(params.interior_spacing > h)) return SizingField(size_bound);
  const double ratio = params.interior_spacing / h;
  const double depth = std::max(body_depth(boundary, body_name), h);
  const double slope = std::min(kMaxGradingSlope, (ratio - 1.0) * size_bound / depth);
  const SizingField shape(size_bound, ratio, 0.0, slope, nullptr);
  distance.emplace(boundary, shape.full_growth_distance(), longest_edge);
  return SizingField(size_bound, ratio, 0.0, slope, &*distance);
}

}  // namespace

DomainMesh mesh_domain(const Polygon& boundary, const DomainMeshParams& params,
                       const std::string& body_name) {
  verify_input(boundary, params, body_name);
  const double h = params.spacing;

  Cdt cdt;
  std::vector<Cdt::Vertex_handle> contour;
  contour.reserve(boundary.size());
  double longest_edge = 0.0;
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    const Vec2& p = boundary[i];
    contour.push_back(cdt.insert(Point(p.x(), p.y()),
                                 contour.empty() ? Cdt::Face_handle() : contour.back()->face()));
    longest_edge = std::max(longest_edge, (boundary[(i + 1) % boundary.size()] - p).norm());
  }
  SG_VERIFY(cdt.number_of_vertices() == boundary.size(),
            "body '" << body_name << "': contour has duplicate points");
  for (std::size_t i = 0; i < contour.size(); ++i)
    cdt.insert_constraint(contour[i], contour[(i + 1) % contour.size()]);

  // Size bound from the contour spacing actually given (capped, see kLongestContourEdgeKept).
  const double contour_spacing = std::clamp(longest_edge, h, kLongestContourEdgeKept * h);
  const double size_bound = kSizeBoundFactor * contour_spacing;
  std::optional<CappedContourDistance> distance;
  const SizingField field =
      sizing_field(boundary, params, size_bound, longest_edge, distance, body_name);
  // Without seeds, the mesher's domain is every face not connected to the infinite face
  // without crossing a constraint: the inside of the contour.
  Mesher mesher(cdt, GradedSizeCriteria(&field));
  mesher.refine_mesh();

  // Temporary ids in CGAL's vertex order.
  std::vector<Cdt::Vertex_handle> vertex;
  vertex.reserve(cdt.number_of_vertices());
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    v->info() = static_cast<int>(vertex.size());
    vertex.push_back(v);
  }
  const std::size_t vertex_count = vertex.size();

  // Boundary edges separate an in-domain face from an outside (or infinite) one. Seen from
  // the in-domain face f, the edge opposite vertex e runs from ccw(e) to cw(e) with f on its
  // left: that is the counter-clockwise direction around the domain.
  std::vector<int> next_on_boundary(vertex_count, -1);
  std::size_t boundary_edges = 0;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    for (int e = 0; e < 3; ++e) {
      const auto neighbour = f->neighbor(e);
      if (!cdt.is_infinite(neighbour) && neighbour->is_in_domain()) continue;
      const auto from = static_cast<std::size_t>(f->vertex(Cdt::ccw(e))->info());
      SG_INTERNAL_CHECK(next_on_boundary[from] < 0,
                        "body '" << body_name << "': two boundary edges leave one vertex");
      next_on_boundary[from] = f->vertex(Cdt::cw(e))->info();
      ++boundary_edges;
    }
  }

  DomainMesh mesh;
  std::vector<bool> on_boundary(vertex_count, false);
  mesh.nodes.reserve(vertex_count);
  int v = contour.front()->info();
  do {
    const auto vi = static_cast<std::size_t>(v);
    SG_INTERNAL_CHECK(!on_boundary[vi] && next_on_boundary[vi] >= 0,
                      "body '" << body_name << "': the meshed boundary is not a closed loop");
    on_boundary[vi] = true;
    mesh.nodes.push_back(to_vec(vertex[vi]->point()));
    v = next_on_boundary[vi];
  } while (v != contour.front()->info());
  mesh.boundary_count = static_cast<int>(mesh.nodes.size());
  SG_INTERNAL_CHECK(static_cast<std::size_t>(mesh.boundary_count) == boundary_edges,
                    "body '" << body_name << "': the meshed boundary has " << boundary_edges
                             << " edges but its loop from boundary[0] only "
                             << mesh.boundary_count);
  for (std::size_t i = 0; i < vertex_count; ++i)
    if (!on_boundary[i]) mesh.nodes.push_back(to_vec(vertex[i]->point()));
  sort_interior(mesh.nodes, mesh.boundary_count);

  // The boundary loop, Steiner points included, is the contour from here on.
  const Polygon domain(mesh.nodes.begin(), mesh.nodes.begin() + mesh.boundary_count);
  for (int iteration = 0; iteration < params.smoothing_iterations; ++iteration)
    lloyd_step(triangulate(mesh.nodes, mesh.boundary_count, body_name), mesh.nodes,
               mesh.boundary_count, domain, field.graded() ? &field : nullptr);
  if (params.smoothing_iterations > 0) sort_interior(mesh.nodes, mesh.boundary_count);

  // Triangles of the final nodes. CGAL faces are counter-clockwise; rotating a triple keeps
  // its orientation.
  const Cdt final_cdt = triangulate(mesh.nodes, mesh.boundary_count, body_name);
  for (auto f = final_cdt.finite_faces_begin(); f != final_cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    std::array<int, 3> t = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    mesh.triangles.push_back(t);
  }
  std::sort(mesh.triangles.begin(), mesh.triangles.end());
  return mesh;
}

}  // namespace sg
