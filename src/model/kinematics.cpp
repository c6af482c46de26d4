#include "model/kinematics.h"

namespace sg {

namespace {
template <typename F>
void for_row(const ShapeRows& rows, std::size_t point, F&& visit) {
  for (auto k = rows.offset[point]; k < rows.offset[point + 1]; ++k)
    visit(static_cast<std::size_t>(k));
}
}  // namespace

Vec2 reference_mass_centroid(const Model& model, BodyId body) {
  const Body& b = model.bodies[static_cast<std::size_t>(body)];
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
  const Body& b = model.bodies[static_cast<std::size_t>(body)];
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
  const Body& b = model.bodies[static_cast<std::size_t>(body)];
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
    if (model.bodies[static_cast<std::size_t>(mid)].node_begin <= node)
      lo = mid;
    else
      hi = mid - 1;
  }
  return lo;
}
}  // namespace

Vec2 node_position(const Model& model, int node) {
  const int base = model.bodies[static_cast<std::size_t>(body_of_node(model, node))].node_begin;
  const auto n = static_cast<std::size_t>(node);
  Vec2 x(model.nodes.ref_x[n], model.nodes.ref_y[n]);
  for_row(model.node_rows, n, [&](std::size_t k) {
    const auto j = static_cast<std::size_t>(base + model.node_rows.node[k]);
    x += model.node_rows.value[k] * Vec2(model.nodes.ux[j], model.nodes.uy[j]);
  });
  return x;
}

Vec2 node_velocity(const Model& model, int node) {
  const int base = model.bodies[static_cast<std::size_t>(body_of_node(model, node))].node_begin;
  Vec2 v(0, 0);
  for_row(model.node_rows, static_cast<std::size_t>(node), [&](std::size_t k) {
    const auto j = static_cast<std::size_t>(base + model.node_rows.node[k]);
    v += model.node_rows.value[k] * Vec2(model.nodes.vx[j], model.nodes.vy[j]);
  });
  return v;
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
  const int base = model.bodies[static_cast<std::size_t>(body_of_node(model, node))].node_begin;
  return row_deformation_gradient(model, model.node_rows, static_cast<std::size_t>(node), base);
}

Mat2 gauss_deformation_gradient(const Model& model, BodyId body, int g) {
  return row_deformation_gradient(model, model.gauss_rows, static_cast<std::size_t>(g),
                                  model.bodies[static_cast<std::size_t>(body)].node_begin);
}

Vec2 gauss_reference_position(const Model& model, BodyId body, int g) {
  const int base = model.bodies[static_cast<std::size_t>(body)].node_begin;
  Vec2 x(0, 0);
  for_row(model.gauss_rows, static_cast<std::size_t>(g), [&](std::size_t k) {
    const auto j = static_cast<std::size_t>(base + model.gauss_rows.node[k]);
    x += model.gauss_rows.value[k] * Vec2(model.nodes.ref_x[j], model.nodes.ref_y[j]);
  });
  return x;
}

void compute_contour_positions(const Model& model, std::vector<Vec2>& positions) {
  positions.resize(model.contour_point_count());
  const int count = static_cast<int>(model.bodies.size());
#pragma omp parallel for schedule(dynamic, 16)
  for (int b = 0; b < count; ++b) {
    const Body& body = model.bodies[static_cast<std::size_t>(b)];
    if (body.kind == BodyKind::rigid) {
      const auto r = static_cast<std::size_t>(body.rigid_index);
      const Mat2 rot = rotation(model.rigid.theta[r]);
      const Vec2 c(model.rigid.x[r], model.rigid.y[r]);
      for (int k = body.contour_begin; k < body.contour_end; ++k)
        positions[static_cast<std::size_t>(k)] =
            c + rot * model.rigid_contour_offset[static_cast<std::size_t>(k)];
    } else {
      for (int k = body.contour_begin; k < body.contour_end; ++k)
        positions[static_cast<std::size_t>(k)] =
            node_position(model, body.node_begin + (k - body.contour_begin));
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
