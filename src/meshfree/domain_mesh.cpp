#include "meshfree/domain_mesh.h"

// How a body's domain is meshed:
//   1. the contour points are inserted in a constrained Delaunay triangulation (CDT), each
//      contour edge a constraint;
//   2. CGAL's Delaunay refinement (Delaunay_mesher_2, Ruppert/Shewchuk style) inserts
//      circumcentres of triangles that are too large or too flat, and splits constrained
//      edges they would encroach. The size bound is set from the contour edges so that a
//      contour sampled at about h is kept as it is (CGAL User Manual, "2D Conforming
//      Triangulations and Meshes", §Meshes: criteria);
//   3. Lloyd smoothing (lloyd_optimize_mesh_2) moves every unconstrained vertex towards the
//      centroid of its Voronoi cell, which evens out the spacing the refinement left
//      (same chapter, §Optimization of Meshes with Lloyd);
//   4. the output is read back in a canonical order: boundary by walking the domain boundary
//      counter-clockwise from boundary[0], interior sorted by position, triangles sorted.
// Rejected alternative: our own Lloyd loop on a re-triangulated point cloud (the provisional
// version) re-filters triangles by centroid-in-polygon tests and can lose quality near
// concave corners; CGAL's optimizer keeps the constraints and the domain marks consistent.
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
#include <CGAL/lloyd_optimize_mesh_2.h>
#pragma GCC diagnostic pop

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <utility>

#include "core/error.h"

namespace sg {

namespace {

// Shape bound of Delaunay_mesh_size_criteria_2: the squared sine of the smallest angle,
// 0.125 -> 20.7 degrees, the largest value for which CGAL guarantees termination.
constexpr double kShapeBound = 0.125;
// The size bound limits the longest edge of a triangle. Refinement stops with edges between
// about 0.6 and 1 times the bound; 1.3 times the contour spacing gives interior spacing close
// to h after smoothing and leaves triangles with one contour edge (length ~h) alone.
constexpr double kSizeBoundFactor = 1.3;
// Contour edges up to this multiple of h still set the size bound; longer edges are split by
// the mesher (their midpoints become boundary nodes) instead of coarsening the whole body.
constexpr double kLongestContourEdgeKept = 1.5;
// Graded spacing grows by this much per unit distance from the contour (a gradation below 1
// keeps neighbouring triangles of similar size, hence well shaped).
constexpr double kGradingSlope = 0.5;

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

// Delaunay_mesh_size_criteria_2 with a size bound that may grow away from the contour:
// local bound = min(grading * s, s + slope * distance to contour), s the bound at the contour.
// Same quality measure as CGAL's (squared sine of the smallest angle, longest edge over the
// bound), so CGAL's queue ordering and termination argument are unchanged.
class GradedSizeCriteria : public CGAL::Delaunay_mesh_size_criteria_2<Cdt> {
 public:
  using Uniform = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;

  GradedSizeCriteria(double size_bound, double grading, const CappedContourDistance* distance)
      : CGAL::Delaunay_mesh_criteria_2<Cdt>(kShapeBound),
        Uniform(kShapeBound, size_bound),
        grading_(grading),
        distance_(distance) {}

  class Is_bad : public Uniform::Is_bad {
   public:
    Is_bad(const Uniform::Is_bad& uniform, double size_bound, double grading,
           const CappedContourDistance* distance)
        : Uniform::Is_bad(uniform),
          size_bound_(size_bound),
          grading_(grading),
          distance_(distance) {}

    using Uniform::Is_bad::operator();

    CGAL::Mesh_2::Face_badness operator()(const Cdt::Face_handle& face, Quality& q) const {
      const Vec2 a(face->vertex(0)->point().x(), face->vertex(0)->point().y());
      const Vec2 b(face->vertex(1)->point().x(), face->vertex(1)->point().y());
      const Vec2 c(face->vertex(2)->point().x(), face->vertex(2)->point().y());
      double local_bound = size_bound_;
      if (grading_ > 1.0) {
        const double d = (*distance_)((a + b + c) / 3.0);
        local_bound = std::min(grading_ * size_bound_, size_bound_ + kGradingSlope * d);
      }
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
    double size_bound_;
    double grading_;
    const CappedContourDistance* distance_;
  };

  Is_bad is_bad_object() const {
    return Is_bad(Uniform::is_bad_object(), size_bound(), grading_, distance_);
  }

 private:
  double grading_;
  const CappedContourDistance* distance_;  // null when grading == 1
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
  SG_VERIFY(boundary.size() >= 8, "body '" << body_name << "': node spacing h=" << h
                                           << " is too large for the body: its contour has "
                                           << boundary.size()
                                           << " points, need at least 8 (sample it at h)");
}

Vec2 to_vec(const Point& p) {
  return Vec2(p.x(), p.y());
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
  const double grading = params.boundary_grading;
  std::optional<CappedContourDistance> distance;
  if (grading > 1.0)
    distance.emplace(boundary, (grading - 1.0) * size_bound / kGradingSlope, longest_edge);
  // Without seeds, the mesher's domain is every face not connected to the infinite face
  // without crossing a constraint: the inside of the contour.
  Mesher mesher(cdt, GradedSizeCriteria(size_bound, grading, distance ? &*distance : nullptr));
  mesher.refine_mesh();
  // Lloyd moves only vertices without incident constraints (Mesh_global_optimizer_2), so the
  // contour stays fixed; it re-marks the domain after each move. max_iteration_number = 0
  // would mean "until convergence (<= 1000)", hence the guard.
  if (params.smoothing_iterations > 0)
    CGAL::lloyd_optimize_mesh_2(
        cdt, CGAL::parameters::max_iteration_number = params.smoothing_iterations);

  // Temporary ids in CGAL's vertex order, then the final numbering.
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

  constexpr int kUnnumbered = -1;
  std::vector<int> node_of(vertex_count, kUnnumbered);
  DomainMesh mesh;
  mesh.nodes.reserve(vertex_count);
  int v = contour.front()->info();
  do {
    const auto vi = static_cast<std::size_t>(v);
    SG_INTERNAL_CHECK(node_of[vi] == kUnnumbered && next_on_boundary[vi] >= 0,
                      "body '" << body_name << "': the meshed boundary is not a closed loop");
    node_of[vi] = static_cast<int>(mesh.nodes.size());
    mesh.nodes.push_back(to_vec(vertex[vi]->point()));
    v = next_on_boundary[vi];
  } while (v != contour.front()->info());
  mesh.boundary_count = static_cast<int>(mesh.nodes.size());
  SG_INTERNAL_CHECK(static_cast<std::size_t>(mesh.boundary_count) == boundary_edges,
                    "body '" << body_name << "': the meshed boundary has " << boundary_edges
                             << " edges but its loop from boundary[0] only "
                             << mesh.boundary_count);

  // Interior nodes sorted along the longer side of the bounding box: a deterministic order
  // that does not depend on CGAL's memory layout, and that keeps neighbours close in the node
  // arrays of long strips.
  Vec2 lower = boundary.front(), upper = boundary.front();
  for (const Vec2& p : boundary) {
    lower = lower.cwiseMin(p);
    upper = upper.cwiseMax(p);
  }
  const int major = (upper - lower).x() >= (upper - lower).y() ? 0 : 1;
  std::vector<int> interior;
  for (std::size_t i = 0; i < vertex_count; ++i)
    if (node_of[i] == kUnnumbered) interior.push_back(static_cast<int>(i));
  auto key = [&](int i) {
    const Point& p = vertex[static_cast<std::size_t>(i)]->point();
    return major == 0 ? std::pair(p.x(), p.y()) : std::pair(p.y(), p.x());
  };
  std::sort(interior.begin(), interior.end(), [&](int a, int b) { return key(a) < key(b); });
  for (int i : interior) {
    node_of[static_cast<std::size_t>(i)] = static_cast<int>(mesh.nodes.size());
    mesh.nodes.push_back(to_vec(vertex[static_cast<std::size_t>(i)]->point()));
  }

  // CGAL faces are counter-clockwise; rotating a triple keeps its orientation.
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    std::array<int, 3> t;
    for (int k = 0; k < 3; ++k)
      t[static_cast<std::size_t>(k)] = node_of[static_cast<std::size_t>(f->vertex(k)->info())];
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    mesh.triangles.push_back(t);
  }
  std::sort(mesh.triangles.begin(), mesh.triangles.end());
  return mesh;
}

}  // namespace sg
