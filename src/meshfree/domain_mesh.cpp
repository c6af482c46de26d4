#include "meshfree/domain_mesh.h"

// CGAL's 2D constrained Delaunay mesher (Delaunay_mesher_2, Shewchuk-style refinement with a
// shape bound and a size bound) and Lloyd smoothing (lloyd_optimize_mesh_2).
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
#include <CGAL/Constrained_triangulation_face_base_2.h>
#pragma GCC diagnostic pop

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "core/error.h"

namespace sg {

namespace {
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Delaunay_mesh_vertex_base_2<Kernel>;
using FaceBase = CGAL::Delaunay_mesh_face_base_2<Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds>;
using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
using Mesher = CGAL::Delaunay_mesher_2<Cdt, Criteria>;
using Point = Cdt::Point;

// A plain constrained Delaunay triangulation whose vertices carry our node index, rebuilt
// for each smoothing iteration (see smooth_interior).
using IndexedVertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using ConstrainedFaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel>;
using IndexedTds = CGAL::Triangulation_data_structure_2<IndexedVertexBase, ConstrainedFaceBase>;
using IndexedCdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, IndexedTds, CGAL::Exact_predicates_tag>;

// Triangulates the nodes (contour first, then interior) constrained by the contour and keeps
// the triangles inside it, counter-clockwise. Insertion in node order: the result depends on
// the nodes only (the Delaunay triangulation is unique up to co-circular points).
std::vector<std::array<int, 3>> triangulate(const std::vector<Vec2>& nodes, int boundary_count,
                                            const Polygon& contour) {
  IndexedCdt cdt;
  std::vector<IndexedCdt::Vertex_handle> handles;
  handles.reserve(nodes.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    handles.push_back(cdt.insert(Point(nodes[i].x(), nodes[i].y())));
    handles.back()->info() = static_cast<int>(i);
  }
  for (int i = 0; i < boundary_count; ++i)
    cdt.insert_constraint(handles[static_cast<std::size_t>(i)],
                          handles[static_cast<std::size_t>((i + 1) % boundary_count)]);
  std::vector<std::array<int, 3>> triangles;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    const std::array<int, 3> t = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    const Vec2 c = (nodes[static_cast<std::size_t>(t[0])] + nodes[static_cast<std::size_t>(t[1])] +
                    nodes[static_cast<std::size_t>(t[2])]) / 3.0;
    if (contains(contour, c)) triangles.push_back(t);
  }
  // Canonical order (faces come in memory order): sorted by their smallest vertex, etc.
  for (auto& t : triangles) std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  std::sort(triangles.begin(), triangles.end());
  return triangles;
}

// Lloyd-like smoothing of the interior nodes: each moves to the area-weighted centroid of the
// triangles around it (Jacobi update, in node order), then the domain is triangulated again.
// Written here rather than using CGAL::lloyd_optimize_mesh_2, whose result depends on heap
// addresses (it differs between two calls on the same input in one process): meshes must be
// reproducible for results not to depend on anything but the input.
void smooth_interior(std::vector<Vec2>& nodes, int boundary_count, const Polygon& contour,
                     int iterations, std::vector<std::array<int, 3>>& triangles) {
  for (int it = 0; it < iterations; ++it) {
    std::vector<Vec2> weighted(nodes.size(), Vec2::Zero());
    std::vector<double> area(nodes.size(), 0.0);
    for (const auto& t : triangles) {
      const Vec2 &a = nodes[static_cast<std::size_t>(t[0])], &b = nodes[static_cast<std::size_t>(t[1])],
                 &c = nodes[static_cast<std::size_t>(t[2])];
      const double tri_area = 0.5 * std::abs(cross(b - a, c - a));
      const Vec2 centre = (a + b + c) / 3.0;
      for (int v : t) {
        weighted[static_cast<std::size_t>(v)] += tri_area * centre;
        area[static_cast<std::size_t>(v)] += tri_area;
      }
    }
    for (std::size_t i = static_cast<std::size_t>(boundary_count); i < nodes.size(); ++i) {
      if (area[i] <= 0.0) continue;
      const Vec2 target = weighted[i] / area[i];
      if (contains(contour, target)) nodes[i] = target;
    }
    triangles = triangulate(nodes, boundary_count, contour);
  }
}
}  // namespace

DomainMesh mesh_domain(const Polygon& boundary, const DomainMeshParams& params,
                       const std::string& body_name) {
  SG_VERIFY(boundary.size() >= 3, "body '" << body_name << "': a contour needs at least 3 points, got "
                                           << boundary.size());
  SG_VERIFY(params.spacing > 0.0, "body '" << body_name << "': node spacing must be positive, got "
                                           << params.spacing);
  SG_VERIFY(!is_self_intersecting(boundary), "body '" << body_name << "': contour is self-intersecting");
  const double area = signed_area(boundary);
  SG_VERIFY(area > 0.0, "body '" << body_name << "': contour is clockwise (signed area " << area
                                 << "); contours must be counter-clockwise");
  const double equivalent_diameter = 2.0 * std::sqrt(area / std::numbers::pi);
  SG_VERIFY(params.spacing <= 0.5 * equivalent_diameter && boundary.size() >= 8,
            "body '" << body_name << "': node spacing h=" << params.spacing
                     << " is too large for a body of equivalent diameter " << equivalent_diameter
                     << " (need h <= " << 0.5 * equivalent_diameter << " and at least 8 contour points, got "
                     << boundary.size() << ")");
  SG_VERIFY(params.boundary_grading == 1.0,
            "body '" << body_name << "': boundary grading " << params.boundary_grading
                     << " is not supported yet (use 1)");
  SG_VERIFY(params.smoothing_iterations >= 0, "body '" << body_name << "': smoothing iterations "
                                                       << params.smoothing_iterations << " < 0");

  Cdt cdt;
  std::vector<Cdt::Vertex_handle> contour;
  for (const Vec2& p : boundary) contour.push_back(cdt.insert(Point(p.x(), p.y())));
  double longest = 0.0;
  for (std::size_t i = 0; i < contour.size(); ++i) {
    cdt.insert_constraint(contour[i], contour[(i + 1) % contour.size()]);
    longest = std::max(longest, (boundary[(i + 1) % boundary.size()] - boundary[i]).norm());
  }
  // Size bound a little above the longest contour edge so the mesher keeps the contour
  // nodes as they are; the shape bound 0.125 is CGAL's default (minimum angle ~20.6 deg).
  Mesher mesher(cdt);
  mesher.set_criteria(Criteria(0.125, 1.4 * std::max(params.spacing, longest)));
  mesher.refine_mesh();

  // Number the vertices: the contour first, in order, walking the domain boundary
  // counter-clockwise from the first input point, then the interior.
  std::map<Cdt::Vertex_handle, int> index;
  std::map<Cdt::Vertex_handle, Cdt::Vertex_handle> next_on_boundary;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    for (int e = 0; e < 3; ++e) {
      const auto neighbour = f->neighbor(e);
      if (!cdt.is_infinite(neighbour) && neighbour->is_in_domain()) continue;
      // The edge opposite vertex e runs from ccw(e) to cw(e) counter-clockwise around f,
      // i.e. with the domain on its left.
      next_on_boundary[f->vertex(Cdt::ccw(e))] = f->vertex(Cdt::cw(e));
    }
  }
  DomainMesh mesh;
  Cdt::Vertex_handle v = contour.front();
  do {
    index[v] = static_cast<int>(mesh.nodes.size());
    mesh.nodes.emplace_back(v->point().x(), v->point().y());
    const auto it = next_on_boundary.find(v);
    SG_VERIFY(it != next_on_boundary.end(), "body '" << body_name << "': meshing produced an open boundary");
    v = it->second;
    SG_VERIFY(mesh.nodes.size() <= next_on_boundary.size(), "body '" << body_name << "': boundary walk does not close");
  } while (v != contour.front());
  mesh.boundary_count = static_cast<int>(mesh.nodes.size());
  // Interior nodes in a canonical order (lexicographic in y then x: rows, which also keeps
  // neighbours close in memory).
  std::vector<Vec2> interior;
  for (auto w = cdt.finite_vertices_begin(); w != cdt.finite_vertices_end(); ++w)
    if (!index.count(w)) interior.emplace_back(w->point().x(), w->point().y());
  std::sort(interior.begin(), interior.end(), [](const Vec2& a, const Vec2& b) {
    return a.y() != b.y() ? a.y() < b.y() : a.x() < b.x();
  });
  mesh.nodes.insert(mesh.nodes.end(), interior.begin(), interior.end());
  const Polygon domain(mesh.nodes.begin(), mesh.nodes.begin() + mesh.boundary_count);
  mesh.triangles = triangulate(mesh.nodes, mesh.boundary_count, domain);
  smooth_interior(mesh.nodes, mesh.boundary_count, domain, params.smoothing_iterations,
                  mesh.triangles);
  return mesh;
}

}  // namespace sg
