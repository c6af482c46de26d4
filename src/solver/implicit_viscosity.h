#pragma once
// The implicit half of the IMEX integrator ([time] integrator = "imex"): the Kelvin-Voigt
// damping of each deformable body integrated implicitly in the velocity, so that the step is
// set by the undamped wave speed and no longer by the viscosity (docs/method.md "IMEX").
//
// Central difference with the viscous force at the full-step velocity (trapezoidal /
// Crank-Nicolson in v, theta = 1/2):
//   M (v_n+1/2 - v_n-1/2) = h_n (f_el(u_n) + f_ext + f_c - C (v_n-1/2 + v_n+1/2) / 2),
// i.e., with F_n the force the explicit phases computed (its viscous part -C v_n-1/2 at the
// old velocity, model/internal_forces.h) and dv = v_n+1/2 - v_n-1/2,
//   (M + h/2 C) dv = h F_n.
// For a damped mode (omega, xi = alpha omega / 2) the update is stable for omega dt <= 2 at any
// xi (the explicit one needs omega dt <= 2 (sqrt(1 + xi^2) - xi)), and it is second order
// (time-symmetric), where the explicit damping at v_n-1/2 is first order in the damping term.
//
// The operator C of each damping model (material/material.h DampingModel):
//   reference_stiffness  C = alpha K0, constant: a stored sparse LDL^T factor of
//                        A0 = M + h/2 alpha K0 solves exactly (refactored when h changes);
//   corotational         C = R alpha K0 R^T with R the body's mean rotation at u_n; the lumped
//                        mass is isotropic per node, so M + h/2 C = R A0 R^T: the same factor
//                        after turning the right-hand side, exact;
//   objective            C(F) from S_v = alpha C0 : sym(F^T F_dot), P_v = F S_v, applied
//                        matrix-free (model/internal_forces.h apply_viscous_operator) and solved
//                        by conjugate gradients, preconditioned with a factor of the exact
//                        operator A_ref = M + h/2 C(F_ref) assembled at a reference state of
//                        the body (assemble_objective_damping) and turned with the body's mean
//                        rotation since then, Q = R R_ref^T: C(Q F) = Q C(F) Q^T, so a body that
//                        only turns keeps an exact preconditioner. The factor is refreshed when
//                        the body's stretch has moved on, max_g |Q^T F_g - F_ref,g| > delta
//                        (`refactor_threshold`, docs/scenario.md gives the measured cost of
//                        delta), when h changes, and at the first step after a checkpoint
//                        (refresh_preconditioners), so that a resumed run repeats the same
//                        factors as an uninterrupted one.
//   objective, split     (imex_objective = "split", the scenarios' default) no iterations: the
//                        implicit operator is the preconditioner's, C_imp = (1 + beta) Q C(F_ref)
//                        Q^T, solved once with the stored factor, and the rest of C(F) stays
//                        explicit. F_n already holds -C(F) v_n-1/2, so (M + h/2 C_imp) dv = h F_n
//                        applies the viscous force -C(F) v_n-1/2 - C_imp dv / 2: the exact
//                        objective force at the old velocity, plus an implicit increment. Its
//                        stability, damping alone, for a mode of mass m, damping c and c_imp
//                        under C_imp: the velocity's amplification is 1 - h c / (m + h c_imp / 2),
//                        within [-1, 1] iff c <= c_imp + 2 m / h. The top modes of a grain are
//                        heavily damped (h c >> m: at alpha = 0.3 on bench/scenes/imex-cell.toml,
//                        2 m / h is under 1% of c), so C_imp must not fall below C(F). B(F) is
//                        linear in F and |Q^T F - F_ref| <= delta between reassemblies, so C(F)
//                        stays within about (1 + delta)^2 C(F_ref): beta = (1 + delta)^2 - 1
//                        (0.21 at the default delta = 0.1). Measured on that cell: with beta = 0
//                        the alpha = 0.3 run's bulk dissipation share p_wb rose by 3.7% (the
//                        growing top modes, damped again at each reassembly), with beta it is
//                        within 0.2% of the exact solve (docs/scenario.md "Integrators"). A rigid
//                        rotation stays undamped to second order (its dv is radial, of size
//                        h omega^2); the increment's error (C_imp - C) dv / 2 makes the step
//                        first order in the damping, as the explicit integrator is, with a
//                        constant about beta + 2 delta times the explicit one's.
// Eigen factors A0 and A_ref; no hand-written factorization. A grain's factor is nearly dense:
// each node couples with the ~12 of its MLS supports, and the fill of a sparse LDL^T (AMD
// ordering) of a 73-node grain is 59% of the lower triangle, of the papers' 109-211-node grains
// 35-50%. Bodies whose sparse factor would be full enough (below; at most `dense_factor_limit`
// DOFs) keep a dense one instead:
//   - the solves done once per step (reference_stiffness, corotational, the split solve), from
//     a third full (prefers_dense_factor: the bytes read per solve): a Cholesky factor computed
//     in double precision and kept in single precision, whose triangular solves read fewer bytes
//     than the sparse double-precision factor (42 kB of the lower triangle of a 73-node grain,
//     against 77 kB); the factor comes from memory at each step. The increment moves by about
//     1e-7 relative. On bench/scenes/imex-cell.toml (60 grains, 2 threads) whole
//     reference_stiffness and corotational runs 1.16 and 1.20 times faster, mu within 2.7e-4
//     relative of the sparse factors (bench/results/debian12-2core/dense_factor_single_*.csv).
//     The factor is kept over its envelope in a reverse Cuthill-McKee ordering, in 8 x 8 tiles
//     solved a block of rows at a time (EnvelopeCholeskyFactor: Eigen has neither envelope
//     storage nor that ordering); the sparse factors (0.5 GB for the 2,000 grains of
//     examples/shear-cell-full.toml) are released;
//   - the exact objective solve's preconditioner, from half full: Eigen::LDLT in double
//     precision, which its conjugate gradients apply 2 to 4 times per step while it is in
//     cache: 6.6 against 10.4 us per solve and 164 against 194 us per factorization
//     (dense_factor.csv), the objective step 8-24% cheaper; results differ from sparse factors
//     in the last bits.
// dense_factor_limit = 0: sparse double-precision factors everywhere.
//
// The force the update applied is F* = M dv / h (exactly what moved the velocities, whatever
// the solve's residual), and the viscous force booked by the ledger is f_v* = f_v(v_n-1/2) +
// F* - F_n = -C (v_n-1/2 + v_n+1/2) / 2: the ledger (solver/stepper.h) stays closed.
//
// Bodies with driven nodes (the back faces of deformable strips) keep the explicit viscous
// update: their driven components would be constraints of the solve.
//
// The viscous force carried by the solve (reference_stiffness, standard formulation: C = alpha
// K0 constant). F_n holds f_v(v_n-1/2) = -C v_n-1/2, which the force kernel computes at every
// Gauss point from v. The solve gives it for the next step at no cost: (M + h/2 C) dv = h F_n is
// C dv = 2 (F_n - F*), so
//   -C v_n+1/2 = f_v(v_n-1/2) + 2 (F* - F_n),
// node by node, exact for the operator the solve applied (solver/node_update.cpp). The next
// step's force phase then runs the kernel without the viscosity and adds this force
// (CarriedViscousForce), if the velocities are still the ones it was carried to, bit for bit:
// a rejected step restored, a checkpoint read, a caller's change of the velocities all make
// the kernel compute it again. So does a change of h (the factor of the new operator rounds
// differently) and every kCarriedSteps steps: a single-precision factor applies C to about
// 1e-7 relative (its rounding), and each solve's rounding would otherwise add up. The carried
// force is not the kernel's to the bit, so these runs differ from runs that compute f_v at
// every step in the last digits (bench/results/debian12-2core/carried_viscous_force_*.csv);
// they do not depend on the thread count, and a resumed run repeats an uninterrupted one
// (drop_history at each checkpoint). Measured: the step of examples/shear-cell-full.toml 8%
// cheaper (median of 5 paired `info` rounds, 2 threads); on the 400-grain cell the loop 1%
// (within the noise): alone the kernel costs 1.3 times more with the viscosity, but inside a
// step its row loops, not the stress, take the time (carried_viscous_force_speed.csv).
//
// Where the force is carried, f_v . v_n-1/2 = -v C v, the damping power the kernel would
// give, is summed over the nodes.
#include <Eigen/Dense>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <memory>
#include <vector>

#include "model/model.h"
#include "solver/envelope_cholesky_factor.h"
#include "solver/integrator_params.h"

namespace sg {

// Which bodies the IMEX integrator treats implicitly: the damped ones (Model::is_damped)
// without node drives.
bool has_implicit_viscosity(const Model& model, BodyId body);

struct ViscousSolveStatistics {
  long solves = 0;          // body solves
  long iterations = 0;      // conjugate-gradient iterations (objective model)
  long factorizations = 0;  // numeric factorizations of A0 or A_ref
  long reassemblies = 0;    // objective model: assemblies of C(F_ref) at a new reference
  long dense_bodies = 0;    // bodies whose factor is dense
  long carried_forces = 0;  // body force evaluations that used a carried viscous force
  // The bytes the factors (once factored: after the first solve) and the stored operators
  // hold, values and indices (not the per-body vectors: a few times 2 n doubles).
  double matrix_bytes = 0.0;
};

// -C v of one body, carried from the last solve (header): valid for the velocities vx, vy of
// its nodes and the velocity interval h.
struct CarriedViscousForce {
  std::vector<double> fx, fy, vx, vy;  // per node of the body
  double h = 0.0;
  int age = 0;         // solves since the kernel last computed the force
  long uses = 0;       // force evaluations that used it
  bool valid = false;  // false until a solve carries it
  // Whether the force may be used at velocities (vx, vy) (the body's nodes) and interval h:
  // if so the use is counted; if not, the kernel computes the force now (age back to 0).
  bool use_at(const double* velocity_x, const double* velocity_y, double interval);
  // After a solve that wrote fx, fy: the force now holds at these velocities and interval.
  void carried_to(const double* velocity_x, const double* velocity_y, double interval);
};

class ImplicitViscosity {
 public:
  // How many solves in a row carry a body's viscous force before the kernel computes it again.
  static constexpr int kCarriedSteps = 100;
  // `tolerance`: relative residual |r| / |h F| at which conjugate gradients stop.
  // `refactor_threshold`: the objective model's delta (above). `dense_factor_limit`: the largest
  // body (in DOFs) whose factor may be dense (above; 0: none).
  // `objective_split`: the objective model's split solve (above) instead of the exact one.
  ImplicitViscosity(const Model& model, double tolerance,
                    double refactor_threshold = kDefaultRefactorThreshold,
                    int dense_factor_limit = IntegratorParams::kDefaultDenseFactorLimit,
                    bool objective_split = false);
  static constexpr double kDefaultRefactorThreshold = 0.1;

  // The objective model's next solve of every body assembles and factors its operator anew.
  void refresh_preconditioners();
  // What the solves carry from one step to the next is dropped: the objective model's
  // preconditioners (refresh_preconditioners) and the carried viscous forces. Called where a
  // checkpoint is written, so that a resumed run repeats an uninterrupted one bit for bit.
  void drop_history();

  // The viscous force carried for `body` (header), or null if its operator is not constant
  // (not reference_stiffness, or F-bar): it is then the kernel's at every step. Thread-safe for
  // different bodies.
  CarriedViscousForce* carried_viscous_force(BodyId body);

  // The velocity increment dv of `body` (local numbering) for the step with velocity interval
  // h: solves (M + h/2 C) dv = h F with F = fx, fy (the body's total force, local numbering)
  // at displacement parameters ux, uy. Thread-safe for different bodies. `gradients_given`:
  // the force kernel has just written F at ux, uy where gradient_outputs() points (the
  // stepper's force phase), so the objective model does not compute them again.
  void solve(const Model& model, BodyId body, double h, const double* ux, const double* uy,
             const double* fx, const double* fy, double* dvx, double* dvy,
             bool gradients_given = false);

  // Per body of the model: where the force kernel may leave its F for solve() (objective
  // model, standard formulation), else null (add_internal_forces' `gradients`). A body whose
  // entry is null computes its F in solve() whatever `gradients_given` says.
  const std::vector<Mat2*>& gradient_outputs() const { return gradient_outputs_; }

  ViscousSolveStatistics statistics() const;  // summed over bodies in body order

 private:
  using SparseMatrix = Eigen::SparseMatrix<double>;
  struct BodySystem {
    BodyId body = -1;
    DampingModel model = DampingModel::objective;
    // alpha K0, or C(F_ref) for the objective model: DOF 2 i (x) and 2 i + 1 (y) of node i
    // (empty for the objective model's dense bodies)
    SparseMatrix damping;
    Eigen::VectorXd mass;  // lumped mass per DOF
    // Of M + h/2 damping (sparse bodies; released for dense ones: half a gigabyte for the
    // 2,000 grains of examples/shear-cell-full.toml).
    std::unique_ptr<Eigen::SimplicialLDLT<SparseMatrix>> factor =
        std::make_unique<Eigen::SimplicialLDLT<SparseMatrix>>();
    bool dense = false;  // the factor is dense: single_factor, or dense_factor (exact solve)
    Eigen::LDLT<Eigen::MatrixXd> dense_factor;
    Eigen::MatrixXd dense_damping;  // C(F_ref) (exact solve)
    // The dense bodies of the solves done once per step: the Cholesky factor L of M + h/2
    // alpha K0 or of M + h/2 (1 + beta) C(F_ref) (split) in its lower triangle, single
    // precision; `single`: a vector of that precision (scratch).
    EnvelopeCholeskyFactor single_factor;
    Eigen::VectorXf single;
    double factor_h = 0.0;
    std::unique_ptr<CarriedViscousForce> carried;  // reference_stiffness, standard (header)
    std::vector<Mat2> gradients;                   // objective model: F per Gauss point
    std::vector<Mat2> reference_gradients;         // F_ref, empty until the first assembly
    Mat2 reference_rotation = Mat2::Identity();
    Eigen::VectorXd rhs, x, r, z, p, q, work_x, work_y, split_x, split_y;  // scratch
    // Objective model, the first guess (solve()): the preconditioned right-hand side, and the
    // corrections CG added to it at the last two solves with the current reference (how many).
    Eigen::VectorXd preconditioned, correction, older_correction;
    int corrections = 0;
    ViscousSolveStatistics statistics;
  };
  double tolerance_, refactor_threshold_;
  bool objective_split_;
  double split_margin_;              // beta of the split solve: (1 + refactor_threshold)^2 - 1
  std::vector<int> system_of_body_;  // index into systems_, or -1 (explicit)
  std::vector<std::unique_ptr<BodySystem>> systems_;  // (Eigen's factors cannot be moved)
  std::vector<Mat2*> gradient_outputs_;

  void factorize(const Model& model, BodySystem& system, double h);
  // ViscousSolveStatistics::matrix_bytes of one body.
  double matrix_bytes(const BodySystem& system) const;
  // Whether `system`'s increment is one solve with its stored factor (reference_stiffness,
  // corotational, the split solve), not conjugate gradients (the exact objective solve).
  bool solved_once_per_step(const BodySystem& system) const;
  // Whether `system` keeps a single-precision Cholesky factor: a dense body solved once per
  // step (the exact solve's preconditioner and the sparse bodies keep double precision).
  bool single_precision_factor(const BodySystem& system) const;
  // Whether `system`'s body (its operator's pattern `a`) gets a dense factor.
  bool prefers_dense_factor(BodySystem& system, const SparseMatrix& a, int limit) const;
  // Objective model: C(F_ref) assembled anew (and factored) when refresh_preconditioners()
  // asked for it or the stretch has moved on by more than the threshold; true if it was.
  bool update_reference(const Model& model, BodySystem& system, const Mat2& rotation, double h);
  // The objective model's conjugate gradients from system.x, preconditioned with the factor
  // turned by `turn` (R R_ref^T); returns the iteration count.
  int conjugate_gradients(const Model& model, BodySystem& system, double h, const Mat2& turn);
  // z = R (M + h/2 damping)^-1 R^T r (R block-diagonal per node).
  void apply_preconditioner(BodySystem& system, const Mat2& rotation, const Eigen::VectorXd& r,
                            Eigen::VectorXd& z) const;
  // q = (M + h/2 C(F)) x, the objective C applied matrix-free at system.gradients.
  void apply_operator(const Model& model, BodySystem& system, double h, const Eigen::VectorXd& x,
                      Eigen::VectorXd& q) const;
};

// alpha K0 of a deformable body: the small-strain plane-strain stiffness of its reference
// configuration times its damping coefficient, assembled from its Gauss rows
// (K0_IJ = sum_g w_g B_I^T D B_J), DOF 2 i (x) and 2 i + 1 (y) of local node i.
Eigen::SparseMatrix<double> assemble_damping_stiffness(const Model& model, BodyId body);

// C(F) of the objective model at the deformation gradients F_g of `body`'s Gauss points
// (body_deformation_gradients): f_v = C v with P_v = F S_v, S_v = alpha C0 : sym(F^T F_dot),
// i.e. C = sum_g w_g B_g(F)^T D B_g(F) with B(F) v = sym(F^T grad v) in Voigt form. The same
// sparsity pattern and entry order as assemble_damping_stiffness, which it equals at F = I.
Eigen::SparseMatrix<double> assemble_objective_damping(const Model& model, BodyId body,
                                                       const std::vector<Mat2>& gradients);
// The same into the values of `c`, which has that pattern already (compressed). Bodies of up
// to `largest_tabulated` nodes find the entries' places in a table of n^2 positions, larger
// ones by binary search (the same values either way).
void reassemble_objective_damping(const Model& model, BodyId body,
                                  const std::vector<Mat2>& gradients,
                                  Eigen::SparseMatrix<double>& c,
                                  std::size_t largest_tabulated = 1024);
// The same into a dense matrix (the bodies whose factor is dense), the same values;
// `lower_only`: only the node blocks on and below the diagonal, the rest zero (what a Cholesky
// factorization reads).
void reassemble_objective_damping(const Model& model, BodyId body,
                                  const std::vector<Mat2>& gradients, Eigen::MatrixXd& c,
                                  bool lower_only = false);

}  // namespace sg
