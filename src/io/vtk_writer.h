#pragma once
// ParaView output: one VTK XML UnstructuredGrid (.vtu) per snapshot, and a .pvd collection
// indexing them by time. Each deformable body is drawn as its triangulation in the current
// configuration, with nodal fields evaluated from the MLS rows at the nodes:
//   displacement, velocity (physical, not the MLS parameters), sigma_xx, sigma_yy, sigma_xy,
//   von_mises, pressure (Cauchy, plane strain), green_lagrange_norm |E|, strain_rate, body_id,
//   material_id.
//
// strain_rate: the rate of the Green-Lagrange strain norm, d|E|/dt = E:E'/|E| with
// E' = sym(F^T F') and F' = sum_J v_J (x) grad0 N_J from the node's row (|E'| where E = 0),
// divided by the global strain rate V/D of a shear cell (papers 001 Figs 6-12, 003 Figs 4, 7b,
// 10: "calculated via increment in the norm of the Green-Lagrange strain tensor", normalized
// by V/D). It is the increment of |E| over a time step divided by the step, in the limit of a
// small step: the state of one instant, so no earlier snapshot is needed (a restart, a
// rollback and the first snapshot need nothing special). Zero on rigid bodies and under any
// rigid motion of a grain. Without a global rate (global_strain_rate <= 0 or NaN): in 1/time.
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

#include "model/model.h"

namespace sg {
struct ScenarioDef;
}

namespace sg {

// The global strain rate V/D of a [shear_cell] under gap loading (D given); NaN otherwise
// (under pressure loading D is an output of the run).
double global_strain_rate(const ScenarioDef& scenario);

// Writes `path` (.vtu) atomically. global_strain_rate: the unit of strain_rate (V/D of the
// run's shear cell); NaN: strain_rate in 1/time.
void write_vtu_snapshot(const Model& model, const std::filesystem::path& path,
                        double global_strain_rate = std::numeric_limits<double>::quiet_NaN());

// The .pvd index of a series of snapshots: rewritten atomically after each snapshot so the
// collection on disk is always complete and readable.
class PvdCollection {
 public:
  explicit PvdCollection(std::filesystem::path pvd_path) : path_(std::move(pvd_path)) {}
  // Records a snapshot file (path relative to the .pvd's folder) at `time` and rewrites the index.
  void add(double time, const std::string& relative_file);
  // The entries so far, and a collection continued from saved entries (a resumed run):
  // rewrites the index with exactly those.
  const std::vector<std::pair<double, std::string>>& entries() const { return entries_; }
  void restore(std::vector<std::pair<double, std::string>> entries);

 private:
  std::filesystem::path path_;
  std::vector<std::pair<double, std::string>> entries_;
  void write() const;
};

}  // namespace sg
