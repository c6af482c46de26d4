#pragma once
// The VTK XML UnstructuredGrid document both .vtu writers fill (io/vtk_writer.h for the
// fields, io/contact_vtk.h for the contact network), written in one of two encodings:
//
//   binary (the default): every DataArray in one <AppendedData encoding="raw"> block after the
//     XML, each array zlib-compressed in blocks of 32 KiB (header_type="UInt64",
//     compressor="vtkZLibDataCompressor": the layout VTK's own XML writer uses, so ParaView
//     and VTK's readers read it as is). Each array is a header of UInt64
//       [number of blocks, block size, size of the partial last block (0: none),
//        compressed size of each block...]
//     followed by the compressed blocks; an array's `offset` counts from the byte after '_'.
//   ascii: every value as text, the shortest decimal that reads back to the same double
//     (std::to_chars), so both encodings hold exactly the same numbers.
//
// Binary is the default because a paper-scale snapshot (317k nodes) is 3 times smaller than
// its text and reads back 2.5-3 times faster, for about 40% more CPU time to write
// (docs/scenario.md "Field files"; bench/vtu_formats.cpp). Raw appended data rather than
// base64 inline: base64 adds a third, and VTK's readers take both.
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

#include "scenario/scenario.h"  // FieldFormat

namespace sg {

// The VTK element types our files use.
enum class VtkType { float64, int32, uint8 };

// One DataArray: `values` holds the numbers whatever the type (Int32 and UInt8 values are
// exact in a double); point-major, `components` per tuple.
struct VtuDataArray {
  std::string name;
  VtkType type = VtkType::float64;
  int components = 1;
  std::vector<double> values;
};

struct VtuDocument {
  std::size_t point_count = 0, cell_count = 0;
  VtuDataArray points;                // Float64, 3 components (z = 0)
  std::vector<VtuDataArray> cells;    // connectivity, offsets, types
  std::string point_data_attributes;  // e.g. Scalars="von_mises" Vectors="velocity"
  std::vector<VtuDataArray> point_data;
};

// A 2D vector array as VTK's 3-component one (z = 0).
VtuDataArray vector_data_array(std::string name, std::size_t count, auto&& get_vec2) {
  VtuDataArray a{std::move(name), VtkType::float64, 3, {}};
  a.values.reserve(3 * count);
  for (std::size_t i = 0; i < count; ++i) {
    const auto v = get_vec2(i);
    a.values.insert(a.values.end(), {v.x(), v.y(), 0.0});
  }
  return a;
}

// A one-component array of `count` values get(i).
VtuDataArray scalar_data_array(std::string name, VtkType type, std::size_t count, auto&& get) {
  VtuDataArray a{std::move(name), type, 1, {}};
  a.values.reserve(count);
  for (std::size_t i = 0; i < count; ++i)
    a.values.push_back(static_cast<double>(get(i)));
  return a;
}

// Writes the whole file (XML and, for binary, the appended data) to `out`.
void write_vtu_document(const VtuDocument& document, FieldFormat format, std::ostream& out);

}  // namespace sg
