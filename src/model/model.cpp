#include "model/model.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "model/gauss_patches.h"

namespace sg {

void NodeState::resize(std::size_t n) {
  for (auto* a : {&ref_x, &ref_y, &ux, &uy, &vx, &vy, &fx, &fy, &viscous_fx, &viscous_fy, &mass,
                  &inverse_mass})
    a->resize(n, 0.0);
  drive.resize(n, -1);
}

bool Model::is_damped(BodyId id) const {
  return body(id).kind == BodyKind::deformable && material_of(id).damping > 0.0;
}

MaterialId Model::add_material(const MaterialDef& def) {
  for (const MaterialDef& m : material_defs)
    SG_VERIFY(m.name != def.name, "material '" << def.name << "' is defined twice");
  materials.push_back(make_material_params(def));
  material_defs.push_back(def);
  return static_cast<MaterialId>(materials.size() - 1);
}

BodyId Model::add_deformable_body(const std::string& name, const Polygon& contour,
                                  MaterialId material, const DiscretizationParams& params) {
  return add_deformable_body(name, discretize_body(contour, params, name), material);
}

BodyId Model::add_deformable_body(const std::string& name, const BodyDiscretization& d,
                                  MaterialId material) {
  check_new_body(name, material);
  Body body;
  body.name = name;
  body.kind = BodyKind::deformable;
  body.material = material;
  body.node_begin = static_cast<int>(nodes.size());
  body.node_end = body.node_begin + static_cast<int>(d.mesh.nodes.size());
  body.boundary_end = body.node_begin + d.mesh.boundary_count;
  body.gauss_begin = static_cast<int>(gauss_weight.size());
  body.gauss_end = body.gauss_begin + static_cast<int>(d.gauss_weight.size());
  body.triangle_begin = static_cast<int>(triangles.size());
  body.triangle_end = body.triangle_begin + static_cast<int>(d.mesh.triangles.size());
  for (double w : d.gauss_weight)
    body.reference_area += w;
  body.contour_begin = static_cast<int>(contour_body.size());
  body.contour_end = body.contour_begin + d.mesh.boundary_count;
  contour_body.insert(contour_body.end(), static_cast<std::size_t>(d.mesh.boundary_count),
                      static_cast<BodyId>(bodies.size()));
  rigid_contour_offset.insert(rigid_contour_offset.end(),
                              static_cast<std::size_t>(d.mesh.boundary_count), Vec2::Zero());
  // A discretization assembled by hand (tests) may come without offsets: point rows.
  if (d.contour_offset.size() == static_cast<std::size_t>(d.mesh.boundary_count))
    contour_hat_offset.insert(contour_hat_offset.end(), d.contour_offset.begin(),
                              d.contour_offset.end());
  else
    contour_hat_offset.insert(contour_hat_offset.end(),
                              static_cast<std::size_t>(d.mesh.boundary_count), Vec2::Zero());

  const double density = this->material(material).density;
  nodes.resize(static_cast<std::size_t>(body.node_end));
  for (std::size_t i = 0; i < d.mesh.nodes.size(); ++i) {
    const std::size_t g = static_cast<std::size_t>(body.node_begin) + i;
    nodes.ref_x[g] = d.mesh.nodes[i].x();
    nodes.ref_y[g] = d.mesh.nodes[i].y();
    nodes.mass[g] = density * d.lumped_volume[i];
    nodes.inverse_mass[g] = 1.0 / nodes.mass[g];
  }
  // Mean gradient weights c_J (Gauss quadrature of grad N_J over the body, over its area).
  mean_gradient_x.resize(nodes.size(), 0.0);
  mean_gradient_y.resize(nodes.size(), 0.0);
  double area = 0.0;
  for (double w : d.gauss_weight)
    area += w;
  for (std::size_t g = 0; g < d.gauss_rows.points(); ++g)
    for (auto k = d.gauss_rows.offset[g]; k < d.gauss_rows.offset[g + 1]; ++k) {
      const auto e = static_cast<std::size_t>(k);
      const auto j = static_cast<std::size_t>(body.node_begin + d.gauss_rows.node[e]);
      mean_gradient_x[j] += d.gauss_weight[g] / area * d.gauss_rows.dndx[e];
      mean_gradient_y[j] += d.gauss_weight[g] / area * d.gauss_rows.dndy[e];
    }
  gauss_rows.append(d.gauss_rows);
  gauss_weight.insert(gauss_weight.end(), d.gauss_weight.begin(), d.gauss_weight.end());
  const GaussPatches patches = gauss_patches(d);
  gauss_patch.insert(gauss_patch.end(), patches.patch.begin(), patches.patch.end());
  body.patch_count = patches.count;
  node_rows.append(d.node_rows);
  for (const auto& t : d.mesh.triangles)
    triangles.push_back({t[0] + body.node_begin, t[1] + body.node_begin, t[2] + body.node_begin});
  bodies.push_back(body);
  return static_cast<BodyId>(bodies.size() - 1);
}

BodyId Model::add_deformable_strip(const std::string& name, const Polygon& surface,
                                   double closing_shift_x, double back_y, MaterialId material,
                                   const DiscretizationParams& params) {
  return add_deformable_strip(
      name, discretize_periodic_strip(surface, closing_shift_x, back_y, params, name), material);
}

BodyId Model::add_deformable_strip(const std::string& name,
                                   const PeriodicStripDiscretization& strip, MaterialId material) {
  SG_VERIFY(strip.closing_shift_x != 0.0,
            "body '" << name << "': a strip needs a closing shift (the period)");
  // Its rows see images one period away: that period must be the cell's.
  SG_VERIFY(!periodic_x || std::abs(std::abs(strip.closing_shift_x) - (x_max - x_min)) <=
                               1e-12 * (x_max - x_min),
            "body '" << name << "': strip period " << std::abs(strip.closing_shift_x)
                     << " differs from the periodic cell's " << x_max - x_min);
  const BodyId id = add_deformable_body(name, strip.body, material);
  Body& body = this->body(id);
  body.open_contour = true;
  body.closing_shift_x = strip.closing_shift_x;
  NodeDrive drive;
  drive.body = id;
  for (int local : strip.back_nodes)
    drive.nodes.push_back(body.node_begin + local);
  std::sort(drive.nodes.begin(), drive.nodes.end());
  body.node_drive = static_cast<int>(node_drives.size());
  for (int i : drive.nodes)
    nodes.drive[static_cast<std::size_t>(i)] = body.node_drive;
  node_drives.push_back(std::move(drive));
  return id;
}

void Model::check_new_body(const std::string& name, MaterialId material) const {
  SG_VERIFY(material >= 0 && static_cast<std::size_t>(material) < materials.size(),
            "body '" << name << "': unknown material index " << material);
  for (const Body& b : bodies)
    SG_VERIFY(b.name != name, "body name '" << name << "' is used twice");
}

BodyId Model::add_rigid_body(const std::string& name, const Polygon& contour, MaterialId material) {
  check_new_body(name, material);
  SG_VERIFY(contour.size() >= 3u,
            "body '" << name << "': a contour needs at least 3 points, got " << contour.size());
  SG_VERIFY(!is_self_intersecting(contour), "body '" << name << "': contour is self-intersecting");
  const double area = signed_area(contour);
  SG_VERIFY(area > 0.0, "body '" << name << "': contour must be counter-clockwise (signed area "
                                 << area << ")");
  const double density = this->material(material).density;
  Body body;
  body.reference_area = area;
  return append_rigid(body, name, contour, material, centroid(contour), density * area,
                      density * polar_second_moment(contour));
}

BodyId Model::add_rigid_strip(const std::string& name, const Polygon& surface, MaterialId material,
                              double closing_shift_x, double mass, double inertia) {
  check_new_body(name, material);
  SG_VERIFY(surface.size() >= 2, "body '" << name << "': a strip needs at least 2 points");
  SG_VERIFY(closing_shift_x != 0.0,
            "body '" << name << "': a strip needs a closing shift (the period)");
  SG_VERIFY(mass > 0.0 && inertia > 0.0,
            "body '" << name << "': mass and inertia must be positive");
  Vec2 c(0, 0);
  for (const Vec2& p : surface)
    c += p;
  c /= static_cast<double>(surface.size());
  Body body;
  body.open_contour = true;
  body.closing_shift_x = closing_shift_x;
  body.reference_area = mass / this->material(material).density;
  return append_rigid(body, name, surface, material, c, mass, inertia);
}

BodyId Model::append_rigid(Body body, const std::string& name, const Polygon& points,
                           MaterialId material, const Vec2& reference, double mass,
                           double inertia) {
  body.name = name;
  body.kind = BodyKind::rigid;
  body.material = material;
  body.node_begin = body.node_end = body.boundary_end = static_cast<int>(nodes.size());
  body.gauss_begin = body.gauss_end = static_cast<int>(gauss_weight.size());
  body.triangle_begin = body.triangle_end = static_cast<int>(triangles.size());
  body.contour_begin = static_cast<int>(contour_body.size());
  body.contour_end = body.contour_begin + static_cast<int>(points.size());
  body.rigid_index = static_cast<int>(rigid.size());
  for (const Vec2& p : points) {
    rigid_contour_offset.push_back(p - reference);
    contour_hat_offset.push_back(Vec2::Zero());
    contour_body.push_back(static_cast<BodyId>(bodies.size()));
  }
  for (auto* a : {&rigid.x, &rigid.y, &rigid.theta, &rigid.vx, &rigid.vy, &rigid.omega, &rigid.fx,
                  &rigid.fy, &rigid.torque, &rigid.mass, &rigid.inertia})
    a->push_back(0.0);
  const std::size_t r = rigid.size() - 1;
  rigid.x[r] = reference.x();
  rigid.y[r] = reference.y();
  rigid.mass[r] = mass;
  rigid.inertia[r] = inertia;
  rigid.mass_scale.push_back(1.0);
  rigid.drive.emplace_back();
  bodies.push_back(body);
  return static_cast<BodyId>(bodies.size() - 1);
}

double PiecewiseLinear::operator()(double t) const {
  if (values.empty()) return 0.0;
  if (t <= times.front()) return values.front();
  if (t >= times.back()) return values.back();
  const auto it = std::upper_bound(times.begin(), times.end(), t);
  const std::size_t i = static_cast<std::size_t>(it - times.begin());
  const double s = (t - times[i - 1]) / (times[i] - times[i - 1]);
  return values[i - 1] + s * (values[i] - values[i - 1]);
}

}  // namespace sg
