#include "io/vtu_document.h"

#include <zlib.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/parallel.h"

namespace sg {

namespace {

// VTK's own block size (vtkXMLWriter): a reader inflates one block at a time.
constexpr std::size_t kBlockBytes = 32768;

const char* type_name(VtkType type) {
  switch (type) {
    case VtkType::float64:
      return "Float64";
    case VtkType::int32:
      return "Int32";
    case VtkType::uint8:
      return "UInt8";
  }
  return "";
}

// The array's values as the little-endian bytes of its type (x86-64 and AArch64 are
// little-endian, as the file's byte_order says).
std::vector<unsigned char> raw_bytes(const VtuDataArray& a) {
  std::vector<unsigned char> bytes;
  auto append = [&](auto value) {
    const auto at = bytes.size();
    bytes.resize(at + sizeof value);
    std::memcpy(bytes.data() + at, &value, sizeof value);
  };
  for (const double v : a.values) {
    switch (a.type) {
      case VtkType::float64:
        append(v);
        break;
      case VtkType::int32:
        append(static_cast<std::int32_t>(v));
        break;
      case VtkType::uint8:
        append(static_cast<std::uint8_t>(v));
        break;
    }
  }
  return bytes;
}

// The arrays in VTK's compressed layout, each the UInt64 header and then its zlib blocks. The
// blocks are independent: those of all the arrays are compressed in one parallel loop (each
// into its own buffer, joined in order: the bytes do not depend on the thread count). Array
// by array, a field snapshot of the 60-grain cell (4,300 nodes: two or four blocks per array)
// barely used the second thread, and zlib was 60% of its time. Z_BEST_SPEED: on a
// paper-scale snapshot zlib's default level 6 made the file only 0.9% smaller, at about twice
// the time (bench/vtu_formats.cpp, docs/scenario.md "Field files").
std::vector<std::string> compressed_arrays(const std::vector<const VtuDataArray*>& arrays) {
  std::vector<std::vector<unsigned char>> raw(arrays.size());
  parallel_for(static_cast<int>(arrays.size()), [&](int k) {
    raw[static_cast<std::size_t>(k)] = raw_bytes(*arrays[static_cast<std::size_t>(k)]);
  });
  struct Block {
    std::size_t array, begin, size;
  };
  std::vector<Block> blocks;
  for (std::size_t k = 0; k < raw.size(); ++k)
    for (std::size_t begin = 0; begin < raw[k].size(); begin += kBlockBytes)
      blocks.push_back({k, begin, std::min(kBlockBytes, raw[k].size() - begin)});
  std::vector<std::string> packed(blocks.size());
  parallel_for(static_cast<int>(blocks.size()), [&](int b) {
    const Block& block = blocks[static_cast<std::size_t>(b)];
    uLongf packed_size = compressBound(static_cast<uLong>(block.size));
    std::string& out = packed[static_cast<std::size_t>(b)];
    out.resize(packed_size);
    const int status = compress2(reinterpret_cast<Bytef*>(out.data()), &packed_size,
                                 raw[block.array].data() + block.begin,
                                 static_cast<uLong>(block.size), Z_BEST_SPEED);
    SG_VERIFY(status == Z_OK, "zlib failed compressing DataArray '"
                                  << arrays[block.array]->name << "' (status " << status << ")");
    out.resize(packed_size);
  });
  std::vector<std::string> result(arrays.size());
  std::size_t next = 0;  // the first block of array k
  for (std::size_t k = 0; k < arrays.size(); ++k) {
    const std::size_t count = (raw[k].size() + kBlockBytes - 1) / kBlockBytes;
    std::vector<std::uint64_t> header = {count, kBlockBytes, raw[k].size() % kBlockBytes};
    for (std::size_t b = next; b < next + count; ++b)
      header.push_back(packed[b].size());
    std::string& out = result[k];
    out.assign(header.size() * sizeof(std::uint64_t), '\0');
    std::memcpy(out.data(), header.data(), out.size());
    for (std::size_t b = next; b < next + count; ++b)
      out += packed[b];
    next += count;
  }
  return result;
}

// The shortest text that reads back to the same double (integers print as integers).
void write_number(std::ostream& out, double v) {
  char text[32];
  const auto [end, error] = std::to_chars(text, text + sizeof text, v);
  SG_ASSERT(error == std::errc(), "to_chars: 32 characters are enough for a double");
  out.write(text, end - text);
}

void write_ascii_values(std::ostream& out, const VtuDataArray& a) {
  // One tuple per line for vectors, eight numbers per line for scalars.
  const std::size_t per_line = a.components > 1 ? static_cast<std::size_t>(a.components) : 8;
  for (std::size_t i = 0; i < a.values.size(); ++i) {
    write_number(out, a.values[i]);
    out << ((i + 1) % per_line == 0 || i + 1 == a.values.size() ? '\n' : ' ');
  }
}

// Writes the XML of the document; binary: the arrays' compressed bytes (`compressed`, in the
// order of the calls to array()) go to `appended`.
class DocumentXml {
 public:
  DocumentXml(std::ostream& out, FieldFormat format, std::vector<std::string> compressed)
      : out_(out), format_(format), compressed_(std::move(compressed)) {}

  void array(const VtuDataArray& a) {
    out_ << "        <DataArray type=\"" << type_name(a.type) << "\"";
    if (!a.name.empty()) out_ << " Name=\"" << a.name << "\"";
    if (a.components > 1) out_ << " NumberOfComponents=\"" << a.components << "\"";
    if (format_ == FieldFormat::binary) {
      out_ << " format=\"appended\" offset=\"" << appended_.size() << "\"/>\n";
      appended_ += compressed_[next_++];
    } else {
      out_ << " format=\"ascii\">\n";
      write_ascii_values(out_, a);
      out_ << "        </DataArray>\n";
    }
  }

  const std::string& appended() const { return appended_; }

 private:
  std::ostream& out_;
  FieldFormat format_;
  std::vector<std::string> compressed_;
  std::size_t next_ = 0;
  std::string appended_;
};

}  // namespace

void write_vtu_document(const VtuDocument& document, FieldFormat format, std::ostream& out) {
  out << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\"";
  if (format == FieldFormat::binary) out << " compressor=\"vtkZLibDataCompressor\"";
  out << ">\n  <UnstructuredGrid>\n"
      << "    <Piece NumberOfPoints=\"" << document.point_count << "\" NumberOfCells=\""
      << document.cell_count << "\">\n      <Points>\n";
  // The arrays in the order of the file.
  std::vector<const VtuDataArray*> arrays = {&document.points};
  for (const VtuDataArray& a : document.cells)
    arrays.push_back(&a);
  for (const VtuDataArray& a : document.point_data)
    arrays.push_back(&a);
  DocumentXml xml(
      out, format,
      format == FieldFormat::binary ? compressed_arrays(arrays) : std::vector<std::string>{});
  xml.array(document.points);
  out << "      </Points>\n      <Cells>\n";
  for (const VtuDataArray& a : document.cells)
    xml.array(a);
  out << "      </Cells>\n      <PointData " << document.point_data_attributes << ">\n";
  for (const VtuDataArray& a : document.point_data)
    xml.array(a);
  out << "      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n";
  if (format == FieldFormat::binary) {
    out << "  <AppendedData encoding=\"raw\">\n   _";
    out.write(xml.appended().data(), static_cast<std::streamsize>(xml.appended().size()));
    out << "\n  </AppendedData>\n";
  }
  out << "</VTKFile>\n";
}

}  // namespace sg
