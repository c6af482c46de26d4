#pragma once
// Pressure loading (paper 003 §2: "a constant normal pressure ... imposed onto the upper border
// of the upper first body"; scenario [shear_cell] normal_load = "pressure"): the normal stress
// is an input, p on the loaded first body, the top. The papers' coordinates
//   E~ = log10(E / sigma_n),  c~ = log10(c / sigma_n)          (paper 001 eqs 2-3)
// then take sigma_n = p, the stress the loaded body carries by construction, and not the mean
// of the measured top and bottom stresses: while a layer settles those differ (issue #29:
// 50-80%, which put a campaign's realized coordinates 0.11-0.15 off the requested ones), and
// E~, c~ are properties of the point of the parametric space the run was asked to sample.
// Each body's measured mean stress stays in summary.json (top_normal_stress,
// bottom_normal_stress), and one check compares the loaded body's with p: a servo too slow to
// load the layer within the run (issue #29: the top crept down at 0.07 per time unit) leaves
// it short of p over the window.
//
// Under gap loading sigma_n is an output and E~, c~ use the bodies' mean (paper 001 §2.3).
#include <optional>

#include "analysis/friction.h"
#include "analysis/steadiness.h"

namespace sg {

// The first body the pressure is imposed on (scenario/shear_cell.h: the top).
inline constexpr const char* kLoadedFirstBody = "top";

// sigma_n of E~ and c~: the imposed pressure if there is one (> 0), else the measured mean
// normal stress (NaN if unknown).
double coordinate_normal_stress(double imposed_pressure, double mean_normal_stress);

// The warning "pressure_not_reached" when the loaded body's mean normal stress over the window
// differs from p by more than `tolerance` of p; nothing when it does not, or without p or that
// body's stress.
std::optional<SteadinessWarning> check_imposed_pressure(const FrictionResult& friction,
                                                        double imposed_pressure, double tolerance);

}  // namespace sg
