#pragma once
// ParaView output: one VTK XML UnstructuredGrid (.vtu) per snapshot, and a .pvd collection
// indexing them by time. The arrays are zlib-compressed binary appended data by default, text
// on request ([output] field_format; the encodings: io/vtu_document.h). Each deformable body is
// drawn as its triangulation in the current configuration, with nodal fields evaluated from the MLS
// rows at the nodes:
//   displacement, velocity (physical, not the MLS parameters), sigma_xx, sigma_yy, sigma_xy,
//   von_mises, pressure (Cauchy, plane strain), green_lagrange_norm |E|, strain_rate,
//   strain_rate_instant, body_id, material_id.
//
// strain_rate (papers 001 Figs 6-12, 003 Figs 4, 7b, 10: "calculated via increment in the
// norm of the Green-Lagrange strain tensor", normalized by the global strain rate V/D): at
// snapshot k, the increment of the nodal |E| since the previous snapshot over the interval,
//   strain_rate_k = | |E|_k - |E|_(k-1) | / (t_k - t_(k-1)) / (V/D),
// its absolute value (the papers' colour scales start at 0: where |E| falls, as in a grain
// unloading, the strain is changing as much as where it grows). The first snapshot of a run
// (no previous one) holds the instantaneous |d|E|/dt| / (V/D) instead. The previous snapshot's
// norms are the caller's (run/snapshot_output.h keeps them in the checkpoint).
// strain_rate_instant: the instantaneous rate d|E|/dt = E:E'/|E| with E' = sym(F^T F') and
// F' = sum_J v_J (x) grad0 N_J from the node's row (|E'| where E = 0), over V/D, signed.
// Both are zero on rigid bodies and under any rigid motion of a grain. Without a global rate
// (global_strain_rate <= 0 or NaN): in 1/time.
#include <filesystem>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "model/model.h"
#include "scenario/scenario.h"  // FieldFormat

namespace sg {

// The global strain rate V/D of a [shear_cell] under gap loading (D given); NaN otherwise
// (under pressure loading D is an output of the run).
double global_strain_rate(const ScenarioDef& scenario);

// |E| = |(F^T F - I) / 2| at every field node (the model's node order), from the node's row.
std::vector<double> nodal_strain_norms(const Model& model);

// The interval of strain_rate: the previous snapshot's nodal_strain_norms and the time since
// it. Empty norms (the first snapshot) or a non-positive interval: the instantaneous rate.
struct StrainInterval {
  std::span<const double> previous_norm;
  double length = 0.0;  // t_k - t_(k-1)
};

// Writes `path` (.vtu) atomically, its arrays compressed binary or text (io/vtu_document.h).
// global_strain_rate: the unit of strain_rate (V/D of the run's shear cell); NaN: strain_rate
// in 1/time.
void write_vtu_snapshot(const Model& model, const std::filesystem::path& path,
                        double global_strain_rate = std::numeric_limits<double>::quiet_NaN(),
                        const StrainInterval& interval = {},
                        FieldFormat format = FieldFormat::binary);

// The index in a snapshot's point list of every contour point (Model::contour_body order):
// a deformable body's contour point is its boundary node, a rigid body's contour points
// follow the field nodes, body after body. contacts/*.vtu refer to field points by it.
std::vector<int> contour_point_field_index(const Model& model);

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
