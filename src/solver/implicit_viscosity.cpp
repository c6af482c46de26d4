#include "solver/implicit_viscosity.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/error.h"
#include "model/internal_forces.h"
#include "model/kinematics.h"

namespace sg {

bool has_implicit_viscosity(const Model& model, BodyId b) {
  return model.is_damped(b) && model.body(b).node_drive < 0;
}

namespace {

// Sums, over the Gauss points of `body`, the 2x2 block block(g, a, c) (row entries a, c of
// point g) into the DOFs (2 i, 2 i + 1) x (2 j, 2 j + 1) of the entries' local nodes i, j.
template <class Block>
Eigen::SparseMatrix<double> assemble_gauss_blocks(const Model& model, BodyId b, Block&& block) {
  const Body& body = model.body(b);
  const ShapeRows& rows = model.gauss_rows;
  std::vector<Eigen::Triplet<double>> entries;
  for (int g = body.gauss_begin; g < body.gauss_end; ++g) {
    for (auto a = rows.offset[g]; a < rows.offset[g + 1]; ++a) {
      const int i = rows.node[a];
      for (auto c = rows.offset[g]; c < rows.offset[g + 1]; ++c) {
        const int j = rows.node[c];
        const Mat2 k = block(g, a, c);
        entries.emplace_back(2 * i, 2 * j, k(0, 0));
        entries.emplace_back(2 * i, 2 * j + 1, k(0, 1));
        entries.emplace_back(2 * i + 1, 2 * j, k(1, 0));
        entries.emplace_back(2 * i + 1, 2 * j + 1, k(1, 1));
      }
    }
  }
  const int dofs = 2 * body.node_count();
  Eigen::SparseMatrix<double> k(dofs, dofs);
  k.setFromTriplets(entries.begin(), entries.end());  // duplicates summed, in entry order
  return k;
}

}  // namespace

Eigen::SparseMatrix<double> assemble_damping_stiffness(const Model& model, BodyId b) {
  const MaterialParams& m = model.material_of(b);
  const ShapeRows& rows = model.gauss_rows;
  const double lambda = m.damping * m.lambda, mu = m.damping * m.mu;
  return assemble_gauss_blocks(model, b, [&](int g, auto a, auto c) {
    const double w = model.gauss_weight[static_cast<std::size_t>(g)];
    const double ax = w * rows.dndx[a], ay = w * rows.dndy[a];
    const double cx = rows.dndx[c], cy = rows.dndy[c];
    // The force on node i of sigma = lambda tr(eps) I + 2 mu eps, eps = sym(grad v), for a
    // unit velocity of node j along x or y: K_ij = B_i^T D B_j.
    Mat2 k;
    k << (lambda + 2 * mu) * ax * cx + mu * ay * cy, lambda * ax * cy + mu * ay * cx,
        lambda * ay * cx + mu * ax * cy, (lambda + 2 * mu) * ay * cy + mu * ax * cx;
    return k;
  });
}

namespace {

// The 2x2 blocks of C(F) (header), emit(i, j, block) for every pair of row entries of every
// Gauss point of `body`, in the order of assemble_gauss_blocks; `lower_only`: only the pairs
// with i >= j (half the work, for a factorization that reads the lower triangle).
template <class Emit>
void objective_damping_blocks(const Model& model, BodyId b, const std::vector<Mat2>& gradients,
                              Emit&& emit, bool lower_only = false) {
  const Body& body = model.body(b);
  const MaterialParams& m = model.material_of(b);
  const ShapeRows& rows = model.gauss_rows;
  const double lambda = m.damping * m.lambda, mu = m.damping * m.mu;
  Eigen::Matrix3d d;  // alpha C0, plane strain, engineering shear strain
  d << lambda + 2 * mu, lambda, 0, lambda, lambda + 2 * mu, 0, 0, 0, mu;
  // B(F) of a row entry with reference gradient G: the Voigt strain rate (E_xx, E_yy, 2 E_xy)
  // of sym(F^T grad v) for a unit nodal velocity e_d is (F_d0 G_x, F_d1 G_y, F_d0 G_y + F_d1 G_x).
  using Voigt = Eigen::Matrix<double, 3, 2>;
  std::vector<Voigt> strain, stress;  // B_k and w D B_k of the point's entries
  for (int g = body.gauss_begin; g < body.gauss_end; ++g) {
    const Mat2& f = gradients[static_cast<std::size_t>(g - body.gauss_begin)];
    const double w = model.gauss_weight[static_cast<std::size_t>(g)];
    const auto begin = rows.offset[g], end = rows.offset[g + 1];
    strain.resize(static_cast<std::size_t>(end - begin));
    stress.resize(strain.size());
    for (auto k = begin; k < end; ++k) {
      const double gx = rows.dndx[k], gy = rows.dndy[k];
      Voigt& bk = strain[static_cast<std::size_t>(k - begin)];
      bk << f(0, 0) * gx, f(1, 0) * gx, f(0, 1) * gy, f(1, 1) * gy, f(0, 0) * gy + f(0, 1) * gx,
          f(1, 0) * gy + f(1, 1) * gx;
      stress[static_cast<std::size_t>(k - begin)] = w * (d * bk);
    }
    for (auto a = begin; a < end; ++a)
      for (auto c = begin; c < end; ++c)
        if (!lower_only || rows.node[a] >= rows.node[c])
          emit(rows.node[a], rows.node[c],
               Mat2(strain[static_cast<std::size_t>(a - begin)].transpose() *
                    stress[static_cast<std::size_t>(c - begin)]));
  }
}

}  // namespace

Eigen::SparseMatrix<double> assemble_objective_damping(const Model& model, BodyId b,
                                                       const std::vector<Mat2>& gradients) {
  std::vector<Eigen::Triplet<double>> entries;
  objective_damping_blocks(model, b, gradients, [&](int i, int j, const Mat2& k) {
    entries.emplace_back(2 * i, 2 * j, k(0, 0));
    entries.emplace_back(2 * i, 2 * j + 1, k(0, 1));
    entries.emplace_back(2 * i + 1, 2 * j, k(1, 0));
    entries.emplace_back(2 * i + 1, 2 * j + 1, k(1, 1));
  });
  const int dofs = 2 * model.body(b).node_count();
  Eigen::SparseMatrix<double> c(dofs, dofs);
  c.setFromTriplets(entries.begin(), entries.end());  // duplicates summed, in entry order
  return c;
}

void reassemble_objective_damping(const Model& model, BodyId b, const std::vector<Mat2>& gradients,
                                  Eigen::SparseMatrix<double>& c, std::size_t largest_tabulated) {
  // In place, in c's fixed pattern (that of K0: the blocks of every pair of nodes sharing a
  // Gauss row, both DOFs): no triplet list, no sort. Each slot receives its terms in the
  // order of the triplet assembly (Gauss point by Gauss point), so the values are the same.
  SG_ASSERT(c.isCompressed(), "reassemble_objective_damping needs a compressed matrix");
  std::fill(c.valuePtr(), c.valuePtr() + c.nonZeros(), 0.0);
  const auto* outer = c.outerIndexPtr();
  const auto* inner = c.innerIndexPtr();
  double* values = c.valuePtr();
  // Position of row 2 i in column 2 j; row 2 i + 1 follows it, and column 2 j + 1 holds the
  // same rows, outer[2 j + 1] - outer[2 j] further on. For a grain (n up to a few hundred
  // nodes) a table of the n^2 positions, filled in one pass over the pattern, replaces two
  // binary searches per block (the reassembly took 4 times longer with them); a large body
  // (a deformable first body) searches.
  const auto n = static_cast<std::size_t>(c.cols() / 2);
  thread_local std::vector<std::int32_t> table;
  if (n <= largest_tabulated) {
    table.assign(n * n, -1);
    for (std::size_t j = 0; j < n; ++j)
      for (auto k = outer[2 * j]; k < outer[2 * j + 1]; k += 2)
        table[static_cast<std::size_t>(inner[k] / 2) * n + j] = static_cast<std::int32_t>(k);
  }
  const auto slot = [&](std::size_t i, std::size_t j) {
    if (n <= largest_tabulated) return static_cast<std::size_t>(table[i * n + j]);
    const auto* first = inner + outer[2 * j];
    return static_cast<std::size_t>(
        std::lower_bound(first, inner + outer[2 * j + 1], static_cast<int>(2 * i)) - inner);
  };
  objective_damping_blocks(model, b, gradients, [&](int i, int j, const Mat2& k) {
    const auto col = static_cast<std::size_t>(j);
    const std::size_t x = slot(static_cast<std::size_t>(i), col);
    const std::size_t y = x + static_cast<std::size_t>(outer[2 * col + 1] - outer[2 * col]);
    values[x] += k(0, 0);
    values[x + 1] += k(1, 0);
    values[y] += k(0, 1);
    values[y + 1] += k(1, 1);
  });
}

void reassemble_objective_damping(const Model& model, BodyId b, const std::vector<Mat2>& gradients,
                                  Eigen::MatrixXd& c, bool lower_only) {
  // Each entry receives its terms in the order of the sparse assembly: the same values.
  const int dofs = 2 * model.body(b).node_count();
  c.setZero(dofs, dofs);
  objective_damping_blocks(
      model, b, gradients,
      [&](int i, int j, const Mat2& k) {
        c(2 * i, 2 * j) += k(0, 0);
        c(2 * i + 1, 2 * j) += k(1, 0);
        c(2 * i, 2 * j + 1) += k(0, 1);
        c(2 * i + 1, 2 * j + 1) += k(1, 1);
      },
      lower_only);
}

ImplicitViscosity::ImplicitViscosity(const Model& model, double tolerance,
                                     double refactor_threshold, int dense_factor_limit,
                                     bool objective_split)
    : tolerance_(tolerance),
      refactor_threshold_(refactor_threshold),
      objective_split_(objective_split),
      split_margin_((1.0 + refactor_threshold) * (1.0 + refactor_threshold) - 1.0),
      system_of_body_(model.bodies.size(), -1),
      gradient_outputs_(model.bodies.size(), nullptr) {
  SG_VERIFY(tolerance > 0.0 && tolerance < 1.0,
            "imex: the solver tolerance must be in (0, 1), got " << tolerance);
  SG_VERIFY(refactor_threshold >= 0.0,
            "imex: the refactorization threshold must be >= 0, got " << refactor_threshold);
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const auto id = static_cast<BodyId>(b);
    if (!has_implicit_viscosity(model, id)) continue;
    system_of_body_[b] = static_cast<int>(systems_.size());
    BodySystem& s = *systems_.emplace_back(std::make_unique<BodySystem>());
    s.body = id;
    s.model = model.material_of(id).damping_model;
    // The objective model's C(F_ref) has the pattern of K0 (and is K0 until a first assembly).
    s.damping = assemble_damping_stiffness(model, id);
    const Body& body = model.bodies[b];
    s.mass.resize(2 * body.node_count());
    for (int i = 0; i < body.node_count(); ++i) {
      const double m = model.nodes.mass[static_cast<std::size_t>(body.node_begin + i)];
      s.mass[2 * i] = s.mass[2 * i + 1] = m;
    }
    if (s.model == DampingModel::reference_stiffness &&
        model.material_of(id).volumetric == VolumetricFormulation::standard) {
      s.carried = std::make_unique<CarriedViscousForce>();
      for (auto* field : {&s.carried->fx, &s.carried->fy, &s.carried->vx, &s.carried->vy})
        field->resize(static_cast<std::size_t>(body.node_count()));
    }
    if (s.model == DampingModel::objective &&
        model.material_of(id).volumetric == VolumetricFormulation::standard) {
      s.gradients.resize(static_cast<std::size_t>(body.gauss_end - body.gauss_begin));
      gradient_outputs_[b] = s.gradients.data();
    }
    SparseMatrix pattern = s.damping;
    pattern.diagonal() += s.mass;
    s.factor->analyzePattern(pattern);
    s.dense = prefers_dense_factor(s, pattern, dense_factor_limit);
    if (s.dense) s.factor.reset();
    if (single_precision_factor(s)) s.single_factor.order(pattern);
    if (s.dense && s.model == DampingModel::objective) {
      // A dense body's objective operator is assembled dense (reassemble_objective_damping),
      // for the split solve only when it is factored: the sparse one is not kept. (The other
      // models keep their sparse alpha K0, the smaller, for the refactorizations when h
      // changes.)
      if (!objective_split_) s.dense_damping = Eigen::MatrixXd(s.damping);
      s.damping = SparseMatrix();
    }
  }
}

bool ImplicitViscosity::prefers_dense_factor(BodySystem& s, const SparseMatrix& a,
                                             int limit) const {
  const Eigen::Index n = a.rows();
  if (n > limit) return false;
  // The fill of the sparse factor, from one factorization of a matrix of the pattern (M + K0
  // is one: symmetric positive definite; Eigen gives L only once factored).
  s.factor->factorize(a);
  if (s.factor->info() != Eigen::Success) return false;
  const double fill = static_cast<double>(s.factor->matrixL().nestedExpression().nonZeros());
  // A single-precision dense factor (the solves done once per step) reads 4 bytes per entry of
  // the lower triangle, the sparse double one 12 per entry of its fill (value and row index):
  // dense from a third full. On the 2,000 grains of examples/shear-cell-full.toml (fill 35-50%,
  // 109-211 nodes) the velocity phase took 31% less time with them, the whole step 1.21-1.27
  // times less (bench/results/debian12-2core/dense_factor_single_paper_scale.csv). The exact
  // solve's double-precision preconditioner stays dense from half full (dense_factor.csv).
  return fill > (solved_once_per_step(s) ? 1.0 / 3.0 : 0.5) * static_cast<double>(n * (n - 1) / 2);
}

void ImplicitViscosity::refresh_preconditioners() {
  for (auto& s : systems_)
    s->reference_gradients.clear();
}

void ImplicitViscosity::drop_history() {
  refresh_preconditioners();
  for (auto& s : systems_)
    if (s->carried) s->carried->valid = false;
}

CarriedViscousForce* ImplicitViscosity::carried_viscous_force(BodyId b) {
  const int index = system_of_body_[static_cast<std::size_t>(b)];
  return index < 0 ? nullptr : systems_[static_cast<std::size_t>(index)]->carried.get();
}

bool CarriedViscousForce::use_at(const double* velocity_x, const double* velocity_y,
                                 double interval) {
  const std::size_t bytes = vx.size() * sizeof(double);
  const bool holds = valid && interval == h && age < ImplicitViscosity::kCarriedSteps &&
                     std::memcmp(vx.data(), velocity_x, bytes) == 0 &&
                     std::memcmp(vy.data(), velocity_y, bytes) == 0;
  if (holds)
    ++uses;
  else
    age = 0;
  return holds;
}

void CarriedViscousForce::carried_to(const double* velocity_x, const double* velocity_y,
                                     double interval) {
  std::copy(velocity_x, velocity_x + vx.size(), vx.begin());
  std::copy(velocity_y, velocity_y + vy.size(), vy.begin());
  h = interval;
  ++age;
  valid = true;
}

bool ImplicitViscosity::solved_once_per_step(const BodySystem& s) const {
  return s.model != DampingModel::objective || objective_split_;
}

bool ImplicitViscosity::single_precision_factor(const BodySystem& s) const {
  return s.dense && solved_once_per_step(s);
}

void ImplicitViscosity::factorize(const Model& model, BodySystem& s, double h) {
  // The split solve's implicit operator is (1 + beta) C(F_ref) (header).
  const bool split = objective_split_ && s.model == DampingModel::objective;
  const double scale = 0.5 * h * (split ? 1.0 + split_margin_ : 1.0);
  bool factored = false;
  thread_local Eigen::MatrixXd a;  // a dense body's M + h/2 C (scratch)
  if (single_precision_factor(s)) {
    // C dense, on and below the diagonal: the objective one assembled at the reference, alpha
    // K0 from its sparse matrix. Factored in double precision (Cholesky: the operator is
    // symmetric positive definite) in the body's ordering, kept in single precision (header).
    if (split)
      reassemble_objective_damping(model, s.body, s.reference_gradients, a, true);
    else
      a = s.damping;
    a *= scale;
    a.diagonal() += s.mass;
    factored = s.single_factor.factor(a);
  } else if (s.dense) {
    a.noalias() = scale * s.dense_damping;
    a.diagonal() += s.mass;
    s.dense_factor.compute(a);
    factored = s.dense_factor.info() == Eigen::Success && s.dense_factor.isPositive();
  } else {
    SparseMatrix sparse = scale * s.damping;
    sparse.diagonal() += s.mass;
    s.factor->factorize(sparse);
    factored = s.factor->info() == Eigen::Success;
  }
  SG_VERIFY(factored, "imex: the factorization of M + h/2 C failed for body " << s.body);
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

// The interleaved solution x = (dv_x0, dv_y0, dv_x1, ...) into dvx, dvy.
void copy_increment(const Eigen::VectorXd& x, int n, double* dvx, double* dvy) {
  for (int i = 0; i < n; ++i) {
    dvx[i] = x[2 * i];
    dvy[i] = x[2 * i + 1];
  }
}

// max_g max_ij |(Q^T F_g - F_ref,g)_ij|: how far the body's stretch has moved from the
// reference once its rotation since then is taken out.
double stretch_change(const std::vector<Mat2>& gradients, const std::vector<Mat2>& reference,
                      const Mat2& turn) {
  double change = 0.0;
  for (std::size_t g = 0; g < gradients.size(); ++g)
    change =
        std::max(change, (turn.transpose() * gradients[g] - reference[g]).cwiseAbs().maxCoeff());
  return change;
}

}  // namespace

void ImplicitViscosity::apply_preconditioner(BodySystem& s, const Mat2& rotation,
                                             const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  s.work_x = r;
  rotate_pairs(rotation, true, s.work_x);
  if (single_precision_factor(s)) {
    s.single = s.work_x.cast<float>();
    s.single_factor.solve_in_place(s.single);
    z = s.single.cast<double>();
    rotate_pairs(rotation, false, z);
    return;
  }
  if (s.dense) {
    z.noalias() = s.dense_factor.solve(s.work_x);
    rotate_pairs(rotation, false, z);
    return;
  }
  // Eigen's factor.solve() step by step, with the last permutation into a scratch vector:
  // the same arithmetic, without the mask its in-place permutation allocates at every solve
  // (3% of the objective model's step).
  z = s.factor->permutationP() * s.work_x;
  s.factor->matrixL().solveInPlace(z);
  z = s.factor->vectorD().asDiagonal().inverse() * z;
  s.factor->matrixU().solveInPlace(z);
  s.work_x.noalias() = s.factor->permutationPinv() * z;
  z.swap(s.work_x);
  rotate_pairs(rotation, false, z);
}

void ImplicitViscosity::apply_operator(const Model& model, BodySystem& s, double h,
                                       const Eigen::VectorXd& x, Eigen::VectorXd& q) const {
  const int n = model.body(s.body).node_count();
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
  // (The objective operator needs no body rotation: C(F) has it in F.)
  apply_viscous_operator(model, s.body, s.gradients, Mat2::Identity(), xs.data(), ys.data(),
                         cx.data(), cy.data());
  q.resize(2 * n);
  for (int i = 0; i < n; ++i) {
    q[2 * i] = s.mass[2 * i] * x[2 * i] + 0.5 * h * cx[i];
    q[2 * i + 1] = s.mass[2 * i + 1] * x[2 * i + 1] + 0.5 * h * cy[i];
  }
}

bool ImplicitViscosity::update_reference(const Model& model, BodySystem& s, const Mat2& rotation,
                                         double h) {
  const bool stale =
      s.reference_gradients.empty() ||
      stretch_change(s.gradients, s.reference_gradients,
                     rotation * s.reference_rotation.transpose()) > refactor_threshold_;
  if (stale) {
    // (The split solve's dense bodies assemble when they factor.)
    if (s.dense && !objective_split_)
      reassemble_objective_damping(model, s.body, s.gradients, s.dense_damping);
    else if (!s.dense)
      reassemble_objective_damping(model, s.body, s.gradients, s.damping);
    s.reference_gradients = s.gradients;
    s.reference_rotation = rotation;
    ++s.statistics.reassemblies;
  }
  if (stale || s.factor_h != h) factorize(model, s, h);
  return stale;
}

int ImplicitViscosity::conjugate_gradients(const Model& model, BodySystem& s, double h,
                                           const Mat2& turn) {
  apply_operator(model, s, h, s.x, s.q);
  s.r = s.rhs - s.q;
  const double target = tolerance_ * s.rhs.norm();
  constexpr int kMaxIterations = 1000;
  // Preconditioned CG with the test before the preconditioner: the residual that meets the
  // tolerance is not preconditioned (that solve, one per iterating body solve, changed
  // nothing and was a quarter of the preconditioner's solves while a cell shears).
  int iterations = 0;
  double rz = 0.0;
  for (; iterations < kMaxIterations && s.r.norm() > target; ++iterations) {
    apply_preconditioner(s, turn, s.r, s.z);
    const double rz_next = s.r.dot(s.z);
    if (iterations == 0)
      s.p = s.z;
    else
      s.p = s.z + (rz_next / rz) * s.p;
    rz = rz_next;
    apply_operator(model, s, h, s.p, s.q);
    const double step = rz / s.p.dot(s.q);
    s.x += step * s.p;
    s.r -= step * s.q;
  }
  const Body& body = model.body(s.body);
  SG_VERIFY(s.r.norm() <= target,
            "body '" << body.name << "': the implicit viscous solve did not converge in "
                     << kMaxIterations << " iterations (relative residual "
                     << s.r.norm() / s.rhs.norm() << ", tolerance " << tolerance_ << ")");
  return iterations;
}

void ImplicitViscosity::solve(const Model& model, BodyId b, double h, const double* ux,
                              const double* uy, const double* fx, const double* fy, double* dvx,
                              double* dvy, bool gradients_given) {
  const int index = system_of_body_[static_cast<std::size_t>(b)];
  SG_ASSERT(index >= 0, "body " << b << " has no implicit viscosity");
  BodySystem& s = *systems_[static_cast<std::size_t>(index)];
  const Body& body = model.body(b);
  const int n = body.node_count();
  s.rhs.resize(2 * n);
  for (int i = 0; i < n; ++i) {
    s.rhs[2 * i] = h * fx[i];
    s.rhs[2 * i + 1] = h * fy[i];
  }
  const Mat2 rotation = s.model == DampingModel::reference_stiffness
                            ? Mat2::Identity()
                            : body_rotation(model, body, ux, uy).matrix();
  ++s.statistics.solves;
  if (s.model == DampingModel::objective) {
    if (!gradients_given || gradient_outputs_[static_cast<std::size_t>(b)] == nullptr)
      body_deformation_gradients(model, b, ux, uy, s.gradients);
    if (update_reference(model, s, rotation, h)) s.corrections = 0;
    // The preconditioner's factor is of Q A_ref Q^T with Q the rotation since the reference.
    const Mat2 turn = rotation * s.reference_rotation.transpose();
    if (objective_split_) {
      // The split solve (header): the stored factor's solve is the increment.
      apply_preconditioner(s, turn, s.rhs, s.x);
      copy_increment(s.x, n, dvx, dvy);
      return;
    }
    // The first guess: the preconditioned right-hand side plus the correction the iterations
    // added to it, extrapolated from the body's last two solves with the same reference (the
    // operator and the forces change little from one step to the next, and so does that
    // correction). After a new reference (so after a checkpoint: refresh_preconditioners)
    // there is none, so that a resumed run repeats an uninterrupted one bit for bit. Measured
    // on bench/scenes/imex-cell.toml (60 grains, alpha = 0.02; 3 time units of compaction and
    // 2 of shear): 1.45 iterations per solve from the preconditioned right-hand side alone,
    // 1.19 with the last correction added, 1.05 with the extrapolation.
    apply_preconditioner(s, turn, s.rhs, s.preconditioned);
    s.x = s.preconditioned;
    if (s.corrections == 1) s.x += s.correction;
    if (s.corrections == 2) s.x += 2.0 * s.correction - s.older_correction;
    s.statistics.iterations += conjugate_gradients(model, s, h, turn);
    s.corrections = std::min(s.corrections + 1, 2);
    s.older_correction.swap(s.correction);
    s.correction = s.x - s.preconditioned;
  } else {
    if (s.factor_h != h) factorize(model, s, h);
    // Exact for the reference-stiffness and corotational operators.
    apply_preconditioner(s, rotation, s.rhs, s.x);
  }
  copy_increment(s.x, n, dvx, dvy);
}

namespace {

// Values (double) and row indices (int) of a compressed sparse matrix.
double sparse_bytes(const Eigen::SparseMatrix<double>& m) {
  return static_cast<double>(m.nonZeros()) * (sizeof(double) + sizeof(int)) +
         static_cast<double>(m.outerSize() + 1) * sizeof(int);
}

double dense_bytes(const Eigen::MatrixXd& m) {
  return static_cast<double>(m.size()) * sizeof(double);
}

}  // namespace

double ImplicitViscosity::matrix_bytes(const BodySystem& s) const {
  double bytes = sparse_bytes(s.damping) + dense_bytes(s.dense_damping);
  if (s.factor_h == 0.0) return bytes;  // not factored yet (the first solve factors)
  if (single_precision_factor(s)) return bytes + static_cast<double>(s.single_factor.bytes());
  if (s.dense) return bytes + dense_bytes(s.dense_factor.matrixLDLT());
  return bytes + sparse_bytes(s.factor->matrixL().nestedExpression());
}

ViscousSolveStatistics ImplicitViscosity::statistics() const {
  ViscousSolveStatistics total;
  for (const auto& s : systems_) {
    total.solves += s->statistics.solves;
    total.iterations += s->statistics.iterations;
    total.factorizations += s->statistics.factorizations;
    total.reassemblies += s->statistics.reassemblies;
    total.dense_bodies += s->dense ? 1 : 0;
    if (s->carried) total.carried_forces += s->carried->uses;
    total.matrix_bytes += matrix_bytes(*s);
  }
  return total;
}

}  // namespace sg
