#pragma once
// A reader for the VTK XML files softgrain itself writes (io/vtk_writer.h, io/contact_vtk.h):
// UnstructuredGrid (.vtu) snapshots and their .pvd time index. Not a general VTK reader: it
// understands the two encodings of io/vtu_document.h, format="ascii" DataArrays and
// format="appended" ones in raw <AppendedData> compressed by zlib with UInt64 headers, in
// <Points>, <Cells> and <PointData>, and refuses anything else (base64, another compressor
// or header type, a count that does not match, a truncated block) with an error naming the
// file, so that a format change is caught, not misread. Both encodings read back to the same
// doubles (the text is the shortest exact decimal).
#include <filesystem>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "geometry/vec2.h"

namespace sg {

// VTK cell type codes used by our writer.
inline constexpr int kVtkTriangle = 5;
inline constexpr int kVtkPolygon = 7;

struct VtuArray {
  std::string name;
  int components = 1;
  std::vector<double> values;  // point-major: values[p * components + c]
};

struct VtuMesh {
  std::filesystem::path path;  // for error messages
  std::vector<Vec2> points;    // z dropped (2D)
  std::vector<int> connectivity;
  std::vector<int> offsets;  // end of each cell in `connectivity`
  std::vector<int> types;    // VTK cell type per cell
  std::vector<VtuArray> point_data;

  std::size_t cell_count() const { return types.size(); }
  std::span<const int> cell(std::size_t c) const;
  const VtuArray* find(std::string_view name) const;  // nullptr if absent
};

// Throws sg::Error naming the file if it cannot be read or is not in the expected form.
VtuMesh read_vtu(const std::filesystem::path& path);

// One scalar per point for a field name: a one-component array as is; a vector array
// ("velocity", "displacement") as its magnitude, "<vector>_x" / "<vector>_y" as one
// component (velocity_x); "body" is an alias of body_id. Throws
// sg::Error naming the file and the fields present if there is no such array.
std::vector<double> point_scalar(const VtuMesh& mesh, std::string_view field);

struct PvdEntry {
  double time = 0.0;
  std::filesystem::path file;  // resolved against the .pvd's folder
};

// The <DataSet timestep=... file=...> entries, in file order.
std::vector<PvdEntry> read_pvd(const std::filesystem::path& path);

}  // namespace sg
