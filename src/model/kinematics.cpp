#include "model/kinematics.h"

#include <cmath>

namespace sg {

namespace {
template <typename F>
void for_row(const ShapeRows& rows, std::size_t point, F&& visit) {
  for (auto k = rows.offset[point]; k < rows.offset[point + 1]; ++k)
    visit(static_cast<std::size_t>(k));
}
}  // namespace

Vec2 reference_mass_centroid(const Model& model, BodyId body) {
  const Body& b = model.body(body);
  double m = 0.0;
  Vec2 c(0, 0);
  for (int i = b.node_begin; i < b.node_end; ++i) {
    const auto k = static_cast<std::size_t>(i);
    m += model.nodes.mass[k];
    c += model.nodes.mass[k] * Vec2(model.nodes.ref_x[k], model.nodes.ref_y[k]);
  }
  return c / m;
}

void set_rigid_velocity(Model& model, BodyId body, const Vec2& velocity, double angular_velocity) {
  const Body& b = model.body(body);
  // About the current (parameter) positions X + u: the field v + omega x (x - c) is linear
  // in the current position, hence reproduced exactly by MLS, whatever the deformation.
  double m = 0.0;
  Vec2 c(0, 0);
  for (int i = b.node_begin; i < b.node_end; ++i) {
    const auto k = static_cast<std::size_t>(i);
    m += model.nodes.mass[k];
    c += model.nodes.mass[k] *
         Vec2(model.nodes.ref_x[k] + model.nodes.ux[k], model.nodes.ref_y[k] + model.nodes.uy[k]);
  }
  c /= m;
  for (int i = b.node_begin; i < b.node_end; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec2 r =
        Vec2(model.nodes.ref_x[k] + model.nodes.ux[k], model.nodes.ref_y[k] + model.nodes.uy[k]) -
        c;
    model.nodes.vx[k] = velocity.x() - angular_velocity * r.y();
    model.nodes.vy[k] = velocity.y() + angular_velocity * r.x();
  }
}

void set_affine_deformation(Model& model, BodyId body, const Mat2& deformation_gradient) {
  const Body& b = model.body(body);
  const Vec2 c = reference_mass_centroid(model, body);
  const Mat2 g = deformation_gradient - Mat2::Identity();
  for (int i = b.node_begin; i < b.node_end; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vec2 u = g * (Vec2(model.nodes.ref_x[k], model.nodes.ref_y[k]) - c);
    model.nodes.ux[k] = u.x();
    model.nodes.uy[k] = u.y();
  }
}

namespace {
int body_of_node(const Model& model, int node) {
  // Bodies are few relative to nodes and sorted by range: binary search.
  int lo = 0, hi = static_cast<int>(model.bodies.size()) - 1;
  while (lo < hi) {
    const int mid = (lo + hi + 1) / 2;
    if (model.body(mid).node_begin <= node)
      lo = mid;
    else
      hi = mid - 1;
  }
  return lo;
}
}  // namespace

Vec2 BodyRotation::rotate(const Vec2& d) const {
  const double r = std::sqrt(r2()), c = a / r, s = b / r;
  return Vec2(c * d.x() - s * d.y(), s * d.x() + c * d.y());
}

Mat2 BodyRotation::matrix() const {
  const double r = std::sqrt(r2()), c = a / r, s = b / r;
  Mat2 q;
  q << c, -s, s, c;
  return q;
}

BodyRotation body_rotation(const Model& model, BodyId body) {
  const Body& b = model.body(body);
  if (b.kind != BodyKind::deformable) return BodyRotation{};
  const auto first = static_cast<std::size_t>(b.node_begin);
  return body_rotation(model, b, model.nodes.ux.data() + first, model.nodes.uy.data() + first);
}

BodyRotation body_rotation(const Model& model, const Body& body, const double* ux,
                           const double* uy) {
  BodyRotation q;
  for (int i = 0; i < body.node_count(); ++i) {
    const auto j = static_cast<std::size_t>(body.node_begin + i);
    const double cx = model.mean_gradient_x[j], cy = model.mean_gradient_y[j];
    q.a += ux[i] * cx + uy[i] * cy;  // F11 + F22 - 2
    q.b += uy[i] * cx - ux[i] * cy;  // F21 - F12
  }
  return q;
}

namespace {

// The hat offset of `node` if it is a contour node of a deformable body, else zero.
Vec2 hat_offset(const Model& model, const Body& body, int node) {
  if (body.kind != BodyKind::deformable || node >= body.boundary_end) return Vec2::Zero();
  return model
      .contour_hat_offset[static_cast<std::size_t>(body.contour_begin + node - body.node_begin)];
}

Vec2 row_position(const Model& model, int base, int node) {
  const auto n = static_cast<std::size_t>(node);
  Vec2 x(model.nodes.ref_x[n], model.nodes.ref_y[n]);
  for_row(model.node_rows, n, [&](std::size_t k) {
    const auto j = static_cast<std::size_t>(base + model.node_rows.node[k]);
    x += model.node_rows.value[k] * Vec2(model.nodes.ux[j], model.nodes.uy[j]);
  });
  return x;
}

}  // namespace

Vec2 contour_node_position(const Model& model, const Body& body, int node,
                           const BodyRotation& rotation) {
  const Vec2 d = hat_offset(model, body, node);
  return row_position(model, body.node_begin, node) + (rotation.rotate(d) - d);
}

Vec2 node_position(const Model& model, int node) {
  const int b = body_of_node(model, node);
  const Body& body = model.body(b);
  if (hat_offset(model, body, node) == Vec2::Zero())
    return row_position(model, body.node_begin, node);
  return contour_node_position(model, body, node, body_rotation(model, b));
}

Vec2 node_velocity(const Model& model, int node) {
  const int b = body_of_node(model, node);
  const Body& body = model.body(b);
  const int base = body.node_begin;
  Vec2 v(0, 0);
  for_row(model.node_rows, static_cast<std::size_t>(node), [&](std::size_t k) {
    const auto j = static_cast<std::size_t>(base + model.node_rows.node[k]);
    v += model.node_rows.value[k] * Vec2(model.nodes.vx[j], model.nodes.vy[j]);
  });
  const Vec2 d = hat_offset(model, body, node);
  if (d != Vec2::Zero()) {
    // d/dt (Q d) = theta_dot perp(Q d), theta_dot = sum_J dtheta/du_J . v_J.
    const BodyRotation q = body_rotation(model, b);
    double theta_dot = 0.0;
    for (int i = body.node_begin; i < body.node_end; ++i) {
      const auto j = static_cast<std::size_t>(i);
      const double cx = model.mean_gradient_x[j], cy = model.mean_gradient_y[j];
      theta_dot +=
          (-q.a * cy - q.b * cx) * model.nodes.vx[j] + (q.a * cx - q.b * cy) * model.nodes.vy[j];
    }
    v += (theta_dot / q.r2()) * perp(q.rotate(d));
  }
  return v;
}

double add_contour_node_force(Model& model, const Body& body, int node, const Vec2& f,
                              const BodyRotation& rotation) {
  const auto n = static_cast<std::size_t>(node);
  const ShapeRows& rows = model.node_rows;
  NodeState& nodes = model.nodes;
  for_row(rows, n, [&](std::size_t k) {
    const auto j = static_cast<std::size_t>(body.node_begin + rows.node[k]);
    nodes.fx[j] += rows.value[k] * f.x();
    nodes.fy[j] += rows.value[k] * f.y();
  });
  const Vec2 d = hat_offset(model, body, node);
  if (d == Vec2::Zero()) return 0.0;
  return f.dot(perp(rotation.rotate(d)));  // f . d(Q d)/dtheta
}

void add_body_rotation_moment(Model& model, const Body& body, double moment,
                              const BodyRotation& rotation) {
  if (moment == 0.0) return;
  // theta = atan2(b, a): dtheta = (a db - b da) / r^2, with da/du_J = c_J and
  // db/dux_J = -c_Jy, db/duy_J = c_Jx.
  const double m = moment / rotation.r2(), a = rotation.a, b = rotation.b;
  NodeState& nodes = model.nodes;
  for (int i = body.node_begin; i < body.node_end; ++i) {
    const auto j = static_cast<std::size_t>(i);
    const double cx = model.mean_gradient_x[j], cy = model.mean_gradient_y[j];
    nodes.fx[j] += m * (-a * cy - b * cx);
    nodes.fy[j] += m * (a * cx - b * cy);
  }
}

namespace {
// F = I + sum_J u_J (x) grad N_J over one row of `rows`, node indices offset by `base`.
Mat2 row_deformation_gradient(const Model& model, const ShapeRows& rows, std::size_t point,
                              int base) {
  Mat2 f = Mat2::Identity();
  for_row(rows, point, [&](std::size_t k) {
    const auto j = static_cast<std::size_t>(base + rows.node[k]);
    f += Vec2(model.nodes.ux[j], model.nodes.uy[j]) * Vec2(rows.dndx[k], rows.dndy[k]).transpose();
  });
  return f;
}
}  // namespace

Mat2 node_deformation_gradient(const Model& model, int node) {
  const int base = model.body(body_of_node(model, node)).node_begin;
  return row_deformation_gradient(model, model.node_rows, static_cast<std::size_t>(node), base);
}

Mat2 gauss_deformation_gradient(const Model& model, BodyId body, int g) {
  return row_deformation_gradient(model, model.gauss_rows, static_cast<std::size_t>(g),
                                  model.body(body).node_begin);
}

Vec2 gauss_reference_position(const Model& model, BodyId body, int g) {
  const int base = model.body(body).node_begin;
  Vec2 x(0, 0);
  for_row(model.gauss_rows, static_cast<std::size_t>(g), [&](std::size_t k) {
    const auto j = static_cast<std::size_t>(base + model.gauss_rows.node[k]);
    x += model.gauss_rows.value[k] * Vec2(model.nodes.ref_x[j], model.nodes.ref_y[j]);
  });
  return x;
}

void compute_contour_positions(const Model& model, std::vector<Vec2>& positions,
                               std::vector<BodyRotation>* rotations) {
  positions.resize(model.contour_point_count());
  if (rotations != nullptr) rotations->assign(model.bodies.size(), BodyRotation{});
  const int count = static_cast<int>(model.bodies.size());
  // Static: a body's contour is computed by the same thread from one step to the next, mostly
  // the one that moved its nodes (the step's loop over bodies gives each thread a contiguous
  // range of bodies, solver/node_update.cpp); a dynamic schedule sent about half the bodies'
  // nodes from one core's cache to the other's at every step.
#pragma omp parallel for schedule(static)
  for (int b = 0; b < count; ++b) {
    const Body& body = model.body(b);
    if (body.kind == BodyKind::rigid) {
      const auto r = static_cast<std::size_t>(body.rigid_index);
      const Mat2 rot = rotation(model.rigid.theta[r]);
      const Vec2 c(model.rigid.x[r], model.rigid.y[r]);
      for (int k = body.contour_begin; k < body.contour_end; ++k)
        positions[static_cast<std::size_t>(k)] =
            c + rot * model.rigid_contour_offset[static_cast<std::size_t>(k)];
    } else {
      const BodyRotation q = body_rotation(model, b);
      if (rotations != nullptr) (*rotations)[static_cast<std::size_t>(b)] = q;
      for (int k = body.contour_begin; k < body.contour_end; ++k)
        positions[static_cast<std::size_t>(k)] =
            contour_node_position(model, body, body.node_begin + (k - body.contour_begin), q);
    }
  }
}

double total_mass(const Model& model) {
  double m = 0.0;
  for (double mi : model.nodes.mass)
    m += mi;
  return m;
}

Vec2 linear_momentum(const Model& model) {
  Vec2 p(0, 0);
  for (std::size_t i = 0; i < model.nodes.size(); ++i)
    p += model.nodes.mass[i] * Vec2(model.nodes.vx[i], model.nodes.vy[i]);
  return p;
}

double angular_momentum(const Model& model) {
  // sum_I m_I (X_I + u_I) x v_I, with the parameters: this is the quantity the semi-discrete
  // equations conserve, since internal forces f_I = -sum_gp w P grad N_I have zero total
  // moment about any point in the parameter coordinates X_I + u_I (P F^T symmetric).
  double l = 0.0;
  for (std::size_t i = 0; i < model.nodes.size(); ++i) {
    const Vec2 x(model.nodes.ref_x[i] + model.nodes.ux[i],
                 model.nodes.ref_y[i] + model.nodes.uy[i]);
    l += model.nodes.mass[i] * cross(x, Vec2(model.nodes.vx[i], model.nodes.vy[i]));
  }
  return l;
}

double kinetic_energy(const Model& model) {
  double k = 0.0;
  for (std::size_t i = 0; i < model.nodes.size(); ++i)
    k += 0.5 * model.nodes.mass[i] *
         (model.nodes.vx[i] * model.nodes.vx[i] + model.nodes.vy[i] * model.nodes.vy[i]);
  return k;
}

}  // namespace sg
