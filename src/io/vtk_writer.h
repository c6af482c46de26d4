#pragma once
// ParaView output: one VTK XML UnstructuredGrid (.vtu) per snapshot, and a .pvd collection
// indexing them by time. Each deformable body is drawn as its triangulation in the current
// configuration, with nodal fields evaluated from the MLS rows at the nodes:
//   displacement, velocity (physical, not the MLS parameters), sigma_xx, sigma_yy, sigma_xy,
//   von_mises, pressure (Cauchy, plane strain), green_lagrange_norm |E|, body_id, material_id.
#include <filesystem>
#include <string>
#include <vector>

#include "model/model.h"

namespace sg {

// Writes `path` (.vtu) atomically.
void write_vtu_snapshot(const Model& model, const std::filesystem::path& path);

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
