#include "io/vtk_writer.h"

#include <cmath>
#include <iomanip>
#include <limits>

#include "core/error.h"
#include "core/parallel.h"
#include "io/atomic_file.h"
#include "io/vtu_document.h"
#include "model/kinematics.h"
#include "scenario/scenario.h"

namespace sg {

namespace {

struct NodalFields {
  std::vector<Vec2> position, displacement, velocity;
  std::vector<CauchyStress> stress;
  std::vector<double> strain_norm, strain_rate, strain_rate_instant;
  std::vector<int> body_id, material_id;
};

Mat2 green_lagrange(const Mat2& F) {
  return 0.5 * (F.transpose() * F - Mat2::Identity());
}

// The rate of the deformation gradient at a node, F' = sum_J v_J (x) grad0 N_J over the
// node's own row (the velocity parameters, as F is built from the displacement parameters).
Mat2 node_deformation_rate(const Model& model, const Body& body, std::size_t node) {
  const ShapeRows& rows = model.node_rows;
  Mat2 rate = Mat2::Zero();
  for (auto k = static_cast<std::size_t>(rows.offset[node]);
       k < static_cast<std::size_t>(rows.offset[node + 1]); ++k) {
    const auto j = static_cast<std::size_t>(body.node_begin + rows.node[k]);
    rate +=
        Vec2(model.nodes.vx[j], model.nodes.vy[j]) * Vec2(rows.dndx[k], rows.dndy[k]).transpose();
  }
  return rate;
}

// d|E|/dt with E = (F^T F - I)/2 and E' = sym(F^T F'): E:E'/|E|, and |E'| where E = 0 (the
// one-sided rate from the undeformed state). Zero for any rigid motion (F^T F' is then skew).
double strain_norm_rate(const Mat2& F, const Mat2& F_rate) {
  const Mat2 E = green_lagrange(F);
  const Mat2 FtFr = F.transpose() * F_rate;
  const Mat2 E_rate = 0.5 * (FtFr + FtFr.transpose());
  const double norm = E.norm();
  return norm > 1e-12 ? (E.array() * E_rate.array()).sum() / norm : E_rate.norm();
}

NodalFields evaluate_fields(const Model& model, double global_strain_rate,
                            const StrainInterval& interval) {
  // Normalized by V/D where the caller knows it (a shear cell), else in 1/time.
  const double rate_unit = global_strain_rate > 0.0 ? global_strain_rate : 1.0;
  SG_VERIFY(interval.previous_norm.empty() || interval.previous_norm.size() == model.node_count(),
            "strain_rate: " << interval.previous_norm.size()
                            << " nodal strain norms of the previous snapshot for "
                            << model.node_count() << " nodes");
  const bool increment = !interval.previous_norm.empty() && interval.length > 0.0;
  NodalFields f;
  const std::size_t n = model.node_count();
  f.position.resize(n);
  f.displacement.resize(n);
  f.velocity.resize(n);
  f.stress.resize(n);
  f.strain_norm.resize(n);
  f.strain_rate.resize(n);
  f.strain_rate_instant.resize(n);
  f.body_id.resize(n);
  f.material_id.resize(n);
  // Each node's values are its own (rows of its own body): in parallel over bodies, the same
  // bits on any number of threads.
  parallel_for(static_cast<int>(model.bodies.size()), [&](int b) {
    const Body& body = model.body(b);
    const MaterialParams& m = model.material(body.material);
    for (int i = body.node_begin; i < body.node_end; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const Vec2 x = node_position(model, i);
      f.position[k] = x;
      f.displacement[k] = x - Vec2(model.nodes.ref_x[k], model.nodes.ref_y[k]);
      f.velocity[k] = node_velocity(model, i);
      const Mat2 grad = node_deformation_gradient(model, i);
      f.stress[k] = grad.determinant() > 0.0 ? cauchy_stress(m, grad) : CauchyStress{0, 0, 0, 0};
      f.strain_norm[k] = green_lagrange(grad).norm();
      f.strain_rate_instant[k] =
          strain_norm_rate(grad, node_deformation_rate(model, body, k)) / rate_unit;
      // The papers' increment over the output interval; the first snapshot: the instant.
      f.strain_rate[k] = increment ? std::abs(f.strain_norm[k] - interval.previous_norm[k]) /
                                         interval.length / rate_unit
                                   : std::abs(f.strain_rate_instant[k]);
      f.body_id[k] = b;
      f.material_id[k] = body.material;
    }
  });
  // Rigid bodies: their contour points, drawn as one polygon each.
  std::vector<Vec2> contour;
  compute_contour_positions(model, contour);
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const Body& body = model.bodies[b];
    if (body.kind != BodyKind::rigid) continue;
    const auto r = static_cast<std::size_t>(body.rigid_index);
    const Vec2 c(model.rigid.x[r], model.rigid.y[r]);
    const double omega = model.rigid.omega[r];
    for (int k = body.contour_begin; k < body.contour_end; ++k) {
      const Vec2 x = contour[static_cast<std::size_t>(k)];
      f.position.push_back(x);
      f.displacement.push_back(Vec2::Zero());
      f.velocity.push_back(Vec2(model.rigid.vx[r], model.rigid.vy[r]) + omega * perp(x - c));
      f.stress.push_back(CauchyStress{0, 0, 0, 0});
      f.strain_norm.push_back(0.0);
      f.strain_rate.push_back(0.0);
      f.strain_rate_instant.push_back(0.0);
      f.body_id.push_back(static_cast<int>(b));
      f.material_id.push_back(body.material);
    }
  }
  return f;
}

}  // namespace

double global_strain_rate(const ScenarioDef& scenario) {
  const auto& cell = scenario.shear_cell;
  if (!cell || cell->normal_load != NormalLoad::gap || !(cell->gap > 0.0))
    return std::numeric_limits<double>::quiet_NaN();
  return cell->velocity / cell->gap;
}

std::vector<double> nodal_strain_norms(const Model& model) {
  std::vector<double> norm(model.node_count());
  parallel_for(static_cast<int>(model.bodies.size()), [&](int b) {
    const Body& body = model.body(b);
    for (int i = body.node_begin; i < body.node_end; ++i)
      norm[static_cast<std::size_t>(i)] =
          green_lagrange(node_deformation_gradient(model, i)).norm();
  });
  return norm;
}

std::vector<int> contour_point_field_index(const Model& model) {
  std::vector<int> index(model.contour_point_count());
  auto next_rigid_point = static_cast<int>(model.node_count());
  for (const Body& body : model.bodies)
    for (int k = body.contour_begin; k < body.contour_end; ++k)
      index[static_cast<std::size_t>(k)] = body.kind == BodyKind::rigid
                                               ? next_rigid_point++
                                               : body.node_begin + (k - body.contour_begin);
  return index;
}

// The cells: the triangles of deformable bodies, then one polygon per rigid body (its contour
// points follow the field nodes in the point list).
std::vector<VtuDataArray> cell_arrays(const Model& model) {
  VtuDataArray connectivity{"connectivity", VtkType::int32, 1, {}};
  VtuDataArray offsets{"offsets", VtkType::int32, 1, {}};
  VtuDataArray types{"types", VtkType::uint8, 1, {}};
  for (const auto& t : model.triangles) {
    connectivity.values.insert(connectivity.values.end(),
                               {double(t[0]), double(t[1]), double(t[2])});
    offsets.values.push_back(static_cast<double>(connectivity.values.size()));
    types.values.push_back(5);  // VTK_TRIANGLE
  }
  auto next_point = static_cast<double>(model.node_count());
  for (const Body& body : model.bodies) {
    if (body.kind != BodyKind::rigid) continue;
    for (int k = 0; k < body.contour_count(); ++k)
      connectivity.values.push_back(next_point++);
    offsets.values.push_back(static_cast<double>(connectivity.values.size()));
    types.values.push_back(7);  // VTK_POLYGON
  }
  return {std::move(connectivity), std::move(offsets), std::move(types)};
}

void write_vtu_snapshot(const Model& model, const std::filesystem::path& path,
                        double global_strain_rate, const StrainInterval& interval,
                        FieldFormat format) {
  const NodalFields f = evaluate_fields(model, global_strain_rate, interval);
  const std::size_t n = f.position.size();
  VtuDocument doc;
  doc.point_count = n;
  doc.points = vector_data_array("position", n, [&](std::size_t i) { return f.position[i]; });
  doc.cells = cell_arrays(model);
  doc.cell_count = doc.cells[2].values.size();
  doc.point_data_attributes = "Scalars=\"von_mises\" Vectors=\"velocity\"";
  auto scalar = [&](const char* name, auto&& get) {
    doc.point_data.push_back(scalar_data_array(name, VtkType::float64, n, get));
  };
  doc.point_data.push_back(
      vector_data_array("displacement", n, [&](std::size_t i) { return f.displacement[i]; }));
  doc.point_data.push_back(
      vector_data_array("velocity", n, [&](std::size_t i) { return f.velocity[i]; }));
  scalar("sigma_xx", [&](std::size_t i) { return f.stress[i].xx; });
  scalar("sigma_yy", [&](std::size_t i) { return f.stress[i].yy; });
  scalar("sigma_xy", [&](std::size_t i) { return f.stress[i].xy; });
  scalar("von_mises", [&](std::size_t i) { return f.stress[i].von_mises(); });
  scalar("pressure", [&](std::size_t i) { return f.stress[i].pressure(); });
  scalar("green_lagrange_norm", [&](std::size_t i) { return f.strain_norm[i]; });
  scalar("strain_rate", [&](std::size_t i) { return f.strain_rate[i]; });
  scalar("strain_rate_instant", [&](std::size_t i) { return f.strain_rate_instant[i]; });
  scalar("body_id", [&](std::size_t i) { return f.body_id[i]; });
  scalar("material_id", [&](std::size_t i) { return f.material_id[i]; });
  write_file_atomically(path, [&](std::ostream& out) { write_vtu_document(doc, format, out); });
}

void PvdCollection::add(double time, const std::string& relative_file) {
  entries_.emplace_back(time, relative_file);
  write();
}

void PvdCollection::restore(std::vector<std::pair<double, std::string>> entries) {
  entries_ = std::move(entries);
  write();
}

void PvdCollection::write() const {
  write_file_atomically(path_, [&](std::ostream& out) {
    out << std::setprecision(12)
        << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <Collection>\n";
    for (const auto& [t, file] : entries_)
      out << "    <DataSet timestep=\"" << t << "\" part=\"0\" file=\"" << file << "\"/>\n";
    out << "  </Collection>\n</VTKFile>\n";
  });
}

}  // namespace sg
