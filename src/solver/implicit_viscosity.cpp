#include "solver/implicit_viscosity.h"

#include <cmath>

#include "core/error.h"
#include "model/internal_forces.h"
#include "model/kinematics.h"

namespace sg {

bool has_implicit_viscosity(const Model& model, BodyId b) {
  const Body& body = model.bodies[static_cast<std::size_t>(b)];
  return body.kind == BodyKind::deformable && body.node_drive < 0 &&
         model.materials[static_cast<std::size_t>(body.material)].damping > 0.0;
}

Eigen::SparseMatrix<double> assemble_damping_stiffness(const Model& model, BodyId b) {
  const Body& body = model.bodies[static_cast<std::size_t>(b)];
  const MaterialParams& m = model.materials[static_cast<std::size_t>(body.material)];
  const ShapeRows& rows = model.gauss_rows;
  const double lambda = m.damping * m.lambda, mu = m.damping * m.mu;
  std::vector<Eigen::Triplet<double>> entries;
  for (int g = body.gauss_begin; g < body.gauss_end; ++g) {
    const double w = model.gauss_weight[static_cast<std::size_t>(g)];
    for (auto a = rows.offset[g]; a < rows.offset[g + 1]; ++a) {
      const int i = rows.node[a];
      const double ax = w * rows.dndx[a], ay = w * rows.dndy[a];
      for (auto c = rows.offset[g]; c < rows.offset[g + 1]; ++c) {
        const int j = rows.node[c];
        const double cx = rows.dndx[c], cy = rows.dndy[c];
        // The force on node i of sigma = lambda tr(eps) I + 2 mu eps, eps = sym(grad v), for a
        // unit velocity of node j along x or y: K_ij = B_i^T D B_j.
        entries.emplace_back(2 * i, 2 * j, (lambda + 2 * mu) * ax * cx + mu * ay * cy);
        entries.emplace_back(2 * i, 2 * j + 1, lambda * ax * cy + mu * ay * cx);
        entries.emplace_back(2 * i + 1, 2 * j, lambda * ay * cx + mu * ax * cy);
        entries.emplace_back(2 * i + 1, 2 * j + 1, (lambda + 2 * mu) * ay * cy + mu * ax * cx);
      }
    }
  }
  const int dofs = 2 * body.node_count();
  Eigen::SparseMatrix<double> k(dofs, dofs);
  k.setFromTriplets(entries.begin(), entries.end());  // duplicates summed, in entry order
  return k;
}

ImplicitViscosity::ImplicitViscosity(const Model& model, double tolerance)
    : tolerance_(tolerance), system_of_body_(model.bodies.size(), -1) {
  SG_VERIFY(tolerance > 0.0 && tolerance < 1.0,
            "imex: the solver tolerance must be in (0, 1), got " << tolerance);
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const auto id = static_cast<BodyId>(b);
    if (!has_implicit_viscosity(model, id)) continue;
    system_of_body_[b] = static_cast<int>(systems_.size());
    BodySystem& s = *systems_.emplace_back(std::make_unique<BodySystem>());
    s.body = id;
    s.stiffness = assemble_damping_stiffness(model, id);
    const Body& body = model.bodies[b];
    s.mass.resize(2 * body.node_count());
    for (int i = 0; i < body.node_count(); ++i) {
      const double m = model.nodes.mass[static_cast<std::size_t>(body.node_begin + i)];
      s.mass[2 * i] = s.mass[2 * i + 1] = m;
    }
    SparseMatrix pattern = s.stiffness;
    pattern.diagonal() += s.mass;
    s.factor.analyzePattern(pattern);
  }
}

void ImplicitViscosity::factorize(BodySystem& s, double h) {
  SparseMatrix a = (0.5 * h) * s.stiffness;
  a.diagonal() += s.mass;
  s.factor.factorize(a);
  SG_VERIFY(s.factor.info() == Eigen::Success,
            "imex: the factorization of M + h/2 alpha K0 failed for body " << s.body);
  s.factor_h = h;
  ++s.statistics.factorizations;
}

namespace {

// v_I <- R^T v_I (transpose) or R v_I for every node's pair of DOFs.
void rotate_pairs(const Mat2& r, bool transpose, Eigen::VectorXd& v) {
  const Mat2 q = transpose ? Mat2(r.transpose()) : r;
  for (Eigen::Index i = 0; i + 1 < v.size(); i += 2) {
    const double x = v[i], y = v[i + 1];
    v[i] = q(0, 0) * x + q(0, 1) * y;
    v[i + 1] = q(1, 0) * x + q(1, 1) * y;
  }
}

}  // namespace

void ImplicitViscosity::apply_preconditioner(BodySystem& s, const Mat2& rotation,
                                             const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  s.work_x = r;
  rotate_pairs(rotation, true, s.work_x);
  z = s.factor.solve(s.work_x);
  rotate_pairs(rotation, false, z);
}

void ImplicitViscosity::apply_operator(const Model& model, BodySystem& s, double h,
                                       const Mat2& rotation, const Eigen::VectorXd& x,
                                       Eigen::VectorXd& q) const {
  const int n = model.bodies[static_cast<std::size_t>(s.body)].node_count();
  s.work_x.resize(n);
  s.work_y.resize(n);
  Eigen::VectorXd& cx = s.work_x;
  Eigen::VectorXd& cy = s.work_y;
  // x is interleaved (x0, y0, x1, y1, ...): split it for the kernel.
  Eigen::VectorXd& xs = s.split_x;
  Eigen::VectorXd& ys = s.split_y;
  xs.resize(n);
  ys.resize(n);
  for (int i = 0; i < n; ++i) {
    xs[i] = x[2 * i];
    ys[i] = x[2 * i + 1];
  }
  apply_viscous_operator(model, s.body, s.gradients, rotation, xs.data(), ys.data(), cx.data(),
                         cy.data());
  q.resize(2 * n);
  for (int i = 0; i < n; ++i) {
    q[2 * i] = s.mass[2 * i] * x[2 * i] + 0.5 * h * cx[i];
    q[2 * i + 1] = s.mass[2 * i + 1] * x[2 * i + 1] + 0.5 * h * cy[i];
  }
}

void ImplicitViscosity::solve(const Model& model, BodyId b, double h, const double* ux,
                              const double* uy, const double* fx, const double* fy, double* dvx,
                              double* dvy) {
  const int index = system_of_body_[static_cast<std::size_t>(b)];
  SG_ASSERT(index >= 0, "body " << b << " has no implicit viscosity");
  BodySystem& s = *systems_[static_cast<std::size_t>(index)];
  const Body& body = model.bodies[static_cast<std::size_t>(b)];
  const MaterialParams& material = model.materials[static_cast<std::size_t>(body.material)];
  const int n = body.node_count();
  if (s.factor_h != h) factorize(s, h);
  s.rhs.resize(2 * n);
  for (int i = 0; i < n; ++i) {
    s.rhs[2 * i] = h * fx[i];
    s.rhs[2 * i + 1] = h * fy[i];
  }
  const Mat2 rotation = material.damping_model == DampingModel::reference_stiffness
                            ? Mat2::Identity()
                            : body_rotation(model, body, ux, uy).matrix();
  // Exact for the reference-stiffness and corotational operators; the objective one's start.
  apply_preconditioner(s, rotation, s.rhs, s.x);
  ++s.statistics.solves;
  if (material.damping_model == DampingModel::objective) {
    // Preconditioned conjugate gradients on (M + h/2 C(F)) dv = h F.
    body_deformation_gradients(model, b, ux, uy, s.gradients);
    apply_operator(model, s, h, rotation, s.x, s.q);
    s.r = s.rhs - s.q;
    const double target = tolerance_ * s.rhs.norm();
    constexpr int kMaxIterations = 1000;
    int iterations = 0;
    if (s.r.norm() > target) {
      apply_preconditioner(s, rotation, s.r, s.z);
      s.p = s.z;
      double rz = s.r.dot(s.z);
      for (; iterations < kMaxIterations && s.r.norm() > target; ++iterations) {
        apply_operator(model, s, h, rotation, s.p, s.q);
        const double step = rz / s.p.dot(s.q);
        s.x += step * s.p;
        s.r -= step * s.q;
        apply_preconditioner(s, rotation, s.r, s.z);
        const double rz_next = s.r.dot(s.z);
        s.p = s.z + (rz_next / rz) * s.p;
        rz = rz_next;
      }
    }
    s.statistics.iterations += iterations;
    SG_VERIFY(s.r.norm() <= target,
              "body '" << body.name << "': the implicit viscous solve did not converge in "
                       << kMaxIterations << " iterations (relative residual "
                       << s.r.norm() / s.rhs.norm() << ", tolerance " << tolerance_ << ")");
  }
  for (int i = 0; i < n; ++i) {
    dvx[i] = s.x[2 * i];
    dvy[i] = s.x[2 * i + 1];
  }
}

ViscousSolveStatistics ImplicitViscosity::statistics() const {
  ViscousSolveStatistics total;
  for (const auto& s : systems_) {
    total.solves += s->statistics.solves;
    total.iterations += s->statistics.iterations;
    total.factorizations += s->statistics.factorizations;
  }
  return total;
}

}  // namespace sg
