#pragma once
// Friction of the first bodies over the steady-state window (paper 001 §2.3, paper 002
// §2.1.1 and eq. 4) and the dimensionless parameters of the third body (paper 001
// eqs 2-4 = paper 002 eqs 1-3).
//
//   mu = Ft_bar / Fn_bar           ratio of the time averages (paper 002 eq. 4; paper 001
//                                  eq. 1 prints the ratio upside down, a typo)
//   mu_std = std over the window of mu(t) = Ft(t)/Fn(t)
//   mu_error = mu_std sqrt(2 tau_int / n): error of the mean, n rows of which n / (2 tau_int)
//              are independent (tau_int the integrated autocorrelation time of mu(t) in rows,
//              Sokal 1997; analysis/autocorrelation.h)
//   sigma_n = Fn_bar / L,  sigma_t = Ft_bar / L
//   E~ = log10(E / sigma_n),  c~ = log10(c / sigma_n),  alpha~ = log10(alpha V / D)
//
// Time averages are plain means over the window's rows: series.csv has one row per
// output period, a constant interval of simulated time.
#include <string>
#include <vector>

#include "analysis/driven_body.h"
#include "analysis/run_parameters.h"
#include "analysis/series.h"
#include "analysis/steady_state.h"

namespace sg {

// Fn(t), Ft(t) of one body, every row (DrivenBody's sign convention).
struct BodyForces {
  std::vector<double> normal;
  std::vector<double> tangential;
};
BodyForces body_forces(const Series& series, const DrivenBody& body);

struct FrictionStats {
  std::string body;               // body name, or "mean" for the average of the bodies
  double normal_force = 0.0;      // Fn_bar (force)
  double tangential_force = 0.0;  // Ft_bar (force)
  double mu = 0.0;                // Ft_bar / Fn_bar
  double mu_std = 0.0;            // std of Ft(t)/Fn(t) over the window
  // Error of the mean of mu(t) over the window, mu_std sqrt(2 tau_int / n), and the
  // decorrelation time 2 tau_int x (row interval) (time) of mu(t): autocorrelation.h.
  double mu_error = RunParameters::kUnknown;
  double mu_decorrelation_time = RunParameters::kUnknown;
  double normal_stress = RunParameters::kUnknown;  // Fn_bar / L (stress); NaN if L unknown
  double shear_stress = RunParameters::kUnknown;   // Ft_bar / L (stress)
};

struct FrictionResult {
  std::vector<FrictionStats> bodies;  // one per driven body, in the given order
  // The bodies' forces averaged row by row, then treated as one body: the headline mu.
  // In steady state both bodies carry the same mean load (the layer's momentum is
  // bounded), so this only halves the noise.
  FrictionStats mean;
};

// Throws sg::Error if a mean normal force is not positive, or if Fn(t) <= 0 on a row of
// the window (mu(t) undefined: the window starts before the layer carries load).
FrictionResult compute_friction(const Series& series, std::span<const DrivenBody> bodies,
                                const TimeWindow& window, double length);

struct DimensionlessParameters {
  double stiffness = RunParameters::kUnknown;  // E~ = log10(E / sigma_n), paper 001 eq. 2
  double cohesion = RunParameters::kUnknown;   // c~ = log10(c / sigma_n), paper 001 eq. 3
  double viscosity = RunParameters::kUnknown;  // alpha~ = log10(alpha V / D), paper 001 eq. 4
};

// NaN for each parameter whose inputs are unknown or not positive.
DimensionlessParameters compute_dimensionless(const RunParameters& run, double normal_stress);

}  // namespace sg
