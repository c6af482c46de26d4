#include "io/vtu_document.h"

#include <zlib.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>

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

// One array as VTK's compressed layout: the UInt64 header, then the zlib blocks. The blocks
// are independent, so they are compressed in parallel (each into its own buffer, joined in
// order: the bytes do not depend on the thread count). Z_BEST_SPEED: on a paper-scale
// snapshot zlib's default level 6 made the file only 0.9% smaller, at about twice the time
// (bench/vtu_formats.cpp, docs/scenario.md "Field files").
std::string compressed_array(const VtuDataArray& a) {
  const std::vector<unsigned char> raw = raw_bytes(a);
  const std::size_t blocks = (raw.size() + kBlockBytes - 1) / kBlockBytes;
  std::vector<std::string> packed(blocks);
  parallel_for(static_cast<int>(blocks), [&](int b) {
    const std::size_t begin = static_cast<std::size_t>(b) * kBlockBytes;
    const std::size_t size = std::min(kBlockBytes, raw.size() - begin);
    uLongf packed_size = compressBound(static_cast<uLong>(size));
    std::string& block = packed[static_cast<std::size_t>(b)];
    block.resize(packed_size);
    const int status = compress2(reinterpret_cast<Bytef*>(block.data()), &packed_size,
                                 raw.data() + begin, static_cast<uLong>(size), Z_BEST_SPEED);
    SG_VERIFY(status == Z_OK,
              "zlib failed compressing DataArray '" << a.name << "' (status " << status << ")");
    block.resize(packed_size);
  });
  std::vector<std::uint64_t> header = {blocks, kBlockBytes, raw.size() % kBlockBytes};
  for (const std::string& block : packed)
    header.push_back(block.size());
  std::string out(header.size() * sizeof(std::uint64_t), '\0');
  std::memcpy(out.data(), header.data(), out.size());
  for (const std::string& block : packed)
    out += block;
  return out;
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

// Writes the XML of the document; binary: each array's compressed bytes go to `appended`.
class DocumentXml {
 public:
  DocumentXml(std::ostream& out, FieldFormat format) : out_(out), format_(format) {}

  void array(const VtuDataArray& a) {
    out_ << "        <DataArray type=\"" << type_name(a.type) << "\"";
    if (!a.name.empty()) out_ << " Name=\"" << a.name << "\"";
    if (a.components > 1) out_ << " NumberOfComponents=\"" << a.components << "\"";
    if (format_ == FieldFormat::binary) {
      out_ << " format=\"appended\" offset=\"" << appended_.size() << "\"/>\n";
      appended_ += compressed_array(a);
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
  DocumentXml xml(out, format);
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
