#pragma once
// What a run says about its own time integration, beside its results: a fixed step beyond the
// estimated stability limit (at the start) and an energy ledger that does not close (at the
// end). Both are warnings, in the run's first or last lines and in run.log, never refusals: a
// fixed step is an expert's choice (reproducing another code's step), and a ledger off by a
// few percent may still be what the user wants to see. Why they are needed: with fixed_step at
// 1.5 times the estimated step (safety 0.8) the 400-grain imex cell of
// bench/results/debian12-2core/step_margin.csv finished "done" with a ledger residual of 28% of
// its external work, its contacts having given back 71 energy units more than they took, and
// printed its mu without a word (docs/method.md "Stable step").
#include <string>

#include "model/model.h"
#include "solver/energy_ledger.h"
#include "solver/integrator_params.h"

namespace sg {

// The share of the energy a run received that its ledger may leave unexplained before the
// end-of-run check warns: the 1% the project's ledger tests ask (docs/verification.md).
inline constexpr double kLedgerTolerance = 0.01;

// "" unless `fixed_step` > 0 exceeds the estimated critical step of `model` (its stable step
// at safety 1, solver/stable_time_step.h; `contact_stiffness` the largest contact penalty);
// then why that step may gain energy or explode, with the ratio and the limiting body.
std::string check_fixed_step(double fixed_step, const Model& model, double contact_stiffness,
                             const IntegratorParams& integrator);

// "" while |residual| <= `tolerance` times the energy the run received (the external work's
// magnitude plus the initial kinetic and elastic energies); otherwise how far off the ledger
// is, whether the contacts gave back more energy than they took (a negative contact
// dissipation, which no contact law has), and what the run's energies and friction are then
// worth.
std::string check_energy_balance(const EnergyLedger& ledger, double tolerance = kLedgerTolerance);

}  // namespace sg
