#pragma once
// Constitutive laws of deformable grains, as values (docs/architecture.md §Conventions 4:
// materials are values with named parameters; a switch over a small enum rather than virtual
// dispatch in the kernel). Formulas and sources: docs/method.md §Materials, §Damping.
//
// Plane strain: the deformation gradient is 2x2 in the plane and F_zz = 1.
// All stresses are per unit reference area (P, S) or current area (Cauchy), in the units of
// the Young modulus.
//
// No tangent(F) beside the stress, although a material interface usually has one: the explicit
// scheme never needs a tangent, the stable-step estimate differences the force kernel instead
// (solver/stable_time_step.h), and the tests check P = dW/dF by central differences.
#include <string>

#include "geometry/vec2.h"

namespace sg {

enum class MaterialLaw {
  neo_hookean,             // compressible neo-Hookean (default; papers 000-003)
  saint_venant_kirchhoff,  // linear elastic in Green-Lagrange strain ("Hooke" at small strain)
};

const char* to_string(MaterialLaw law);
// Every law, for readers that parse a name by to_string (scenario/toml_reader.h, named_value).
inline constexpr MaterialLaw kMaterialLaws[] = {MaterialLaw::neo_hookean,
                                                MaterialLaw::saint_venant_kirchhoff};

// The form of the stiffness-proportional (Kelvin-Voigt) damping, f_v = -C v with C ~ alpha K
// (docs/method.md "Damping models"). All three coincide at small strain and small rotation.
enum class DampingModel {
  // S_v = alpha C0 : E_dot, E_dot = sym(F^T F_dot), P_v = F S_v: objective, a rigid motion of
  // any size is never damped (default).
  objective,
  // P_v = R (alpha C0 : sym(R^T F_dot)), R the body's mean rotation (model/kinematics.h
  // BodyRotation): C = R (alpha K0) R^T, exact for rigid motions, first-order different from
  // the objective form at finite strain; its operator is constant in the rotated frame, which
  // the IMEX integrator exploits (one stored factorization per body).
  corotational,
  // P_v = alpha C0 : sym(F_dot): f_v = -alpha K0 v with K0 the small-strain stiffness of the
  // reference configuration, never rotated, as the reference code MELODY 2D and the papers'
  // results (paper 001 §2.1). A grain turned by theta and spinning at omega sees a strain rate
  // of order omega sin(theta) and is braked through its bulk modulus. For reproduction.
  reference_stiffness,
};

const char* to_string(DampingModel model);
// Every model, for readers that parse a name by to_string (scenario/toml_reader.h, named_value).
inline constexpr DampingModel kDampingModels[] = {
    DampingModel::objective, DampingModel::corotational, DampingModel::reference_stiffness};

// How the volumetric part of the deformation enters the elastic energy (docs/method.md
// "Nearly incompressible grains: F-bar").
enum class VolumetricFormulation {
  // W(F) at every Gauss point (default).
  standard,
  // W(F_bar) with F_bar = (J_bar / J)^(1/2) F, J_bar the weighted mean of det F over a patch of
  // Gauss points (the points nearest to one node: model/gauss_patches.h): one volumetric
  // constraint per node instead of one per Gauss point, against the locking of nearly
  // incompressible grains (de Souza Neto, Peric, Dutko & Owen 1996, Int. J. Solids Struct.
  // 33:3277, adapted to plane strain). The viscous stress keeps F (model/force_kernel_impl.h).
  fbar,
};

const char* to_string(VolumetricFormulation formulation);
// Every formulation, for readers that parse a name by to_string (scenario/toml_reader.h).
inline constexpr VolumetricFormulation kVolumetricFormulations[] = {VolumetricFormulation::standard,
                                                                    VolumetricFormulation::fbar};

struct MaterialDef {
  std::string name;
  MaterialLaw law = MaterialLaw::neo_hookean;
  double young = 0.0;    // E (stress units)
  double poisson = 0.3;  // nu, in (-1, 0.5)
  double density = 1.0;  // rho (mass per unit area in 2D)
  double damping = 0.0;  // alpha, stiffness-proportional Rayleigh coefficient (time units)
  DampingModel damping_model = DampingModel::objective;
  VolumetricFormulation volumetric = VolumetricFormulation::standard;
};

// Throws sg::Error naming the material and the bad value.
void validate(const MaterialDef& def);

// Coefficients the kernel uses, derived once from a MaterialDef.
struct MaterialParams {
  MaterialLaw law = MaterialLaw::neo_hookean;
  double lambda = 0.0;  // first Lame parameter (plane strain: the 3D one)
  double mu = 0.0;      // shear modulus
  double density = 1.0;
  double damping = 0.0;  // alpha
  DampingModel damping_model = DampingModel::objective;
  VolumetricFormulation volumetric = VolumetricFormulation::standard;
};

MaterialParams make_material_params(const MaterialDef& def);

// P-wave speed sqrt((lambda + 2 mu) / rho) of the reference state.
double p_wave_speed(const MaterialParams& m);

// The first Piola-Kirchhoff stress and the strain energy density W (per reference area).
// Requires det F > 0 (the caller checks).
struct ElasticResponse {
  Mat2 first_piola;
  double energy_density;
};
ElasticResponse elastic_response(const MaterialParams& m, const Mat2& f);

// Viscous second Piola-Kirchhoff stress of the stiffness-proportional (Kelvin-Voigt)
// damping: S_v = alpha * C0 : E_dot, with E_dot = sym(F^T F_dot) the Green-Lagrange strain
// rate and C0 = dS/dE at the reference state (isotropic: lambda tr(E_dot) I + 2 mu E_dot).
//
// Why the reference tangent C0 and not the current dS/dE: (1) for the neo-Hookean law the
// current tangent is lambda C^-1 (x) C^-1 + 2 (mu - lambda ln J) I_{C^-1}, which loses
// positive definiteness as soon as ln J > mu / lambda (J > 1.01 for nu = 0.495): damping would
// then create energy; (2) at small strain C0 is exactly what the papers' Rayleigh damping
// alpha K0 v uses (paper 001 §2.3 quotes E "ignoring finite-strain effects on the tangent").
// Unlike alpha K0 v it is objective: a rigid rotation has E_dot = 0 and is never damped.
// The dissipated power density is S_v : E_dot >= 0.
Mat2 viscous_second_piola(const MaterialParams& m, const Mat2& strain_rate);

// The viscous first Piola-Kirchhoff stress of the material's damping model at deformation F
// and rate F_dot, and the dissipated power density (>= 0): S_v : E_dot for the objective and
// corotational forms, P_v : sym(F_dot) for the reference-stiffness one. `rotation` is the
// body's mean rotation R (used by the corotational form only).
struct ViscousResponse {
  Mat2 first_piola;
  double power_density;
};
ViscousResponse viscous_response(const MaterialParams& m, const Mat2& f, const Mat2& f_rate,
                                 const Mat2& rotation);

// Full plane-strain Cauchy stress, in-plane components and the out-of-plane sigma_zz.
struct CauchyStress {
  double xx, yy, xy, zz;
  double von_mises() const;
  double pressure() const { return -(xx + yy + zz) / 3.0; }
};
CauchyStress cauchy_stress(const MaterialParams& m, const Mat2& f);

}  // namespace sg
