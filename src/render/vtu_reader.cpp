#include "render/vtu_reader.h"

#include <zlib.h>

#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.h"

namespace sg {
namespace {

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  SG_VERIFY(in, "cannot open '" << path.string() << "'");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// Value of attribute `name` inside the tag text `tag` ("" if absent).
std::string attribute(std::string_view tag, std::string_view name) {
  const std::string key = " " + std::string(name) + "=\"";
  const auto at = tag.find(key);
  if (at == std::string_view::npos) return "";
  const auto begin = at + key.size();
  const auto end = tag.find('"', begin);
  if (end == std::string_view::npos) return "";
  return std::string(tag.substr(begin, end - begin));
}

std::vector<double> parse_numbers(const std::filesystem::path& path, std::string_view name,
                                  const std::string& text, std::size_t begin, std::size_t end) {
  std::vector<double> values;
  const char* p = text.c_str() + begin;
  const char* stop = text.c_str() + end;
  while (p < stop) {
    while (p < stop && (*p == ' ' || *p == '\n' || *p == '\r' || *p == '\t'))
      ++p;
    if (p >= stop) break;
    char* next = nullptr;
    errno = 0;
    const double v = std::strtod(p, &next);
    SG_VERIFY(next != p && next <= stop && errno != ERANGE,
              path.string() << ": DataArray '" << name << "': cannot parse a number near '"
                            << std::string(p, static_cast<std::size_t>(
                                                  std::min<std::ptrdiff_t>(stop - p, 20)))
                            << "'");
    values.push_back(v);
    p = next;
  }
  return values;
}

std::vector<int> to_ints(const std::vector<double>& v) {
  std::vector<int> out(v.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    out[i] = static_cast<int>(std::lround(v[i]));
  return out;
}

// Files a DataArray where our writer's order puts it: <Points>, <Cells>, <PointData>.
void store_array(VtuMesh& mesh, VtuArray array, bool in_points, bool in_cells,
                 std::size_t n_points) {
  const auto components = static_cast<std::size_t>(array.components);
  const std::vector<double>& values = array.values;
  if (in_points) {
    SG_VERIFY(components >= 2 && values.size() == n_points * components,
              mesh.path.string() << ": Points hold " << values.size() << " values for " << n_points
                                 << " points of " << components << " components");
    mesh.points.resize(n_points);
    for (std::size_t p = 0; p < n_points; ++p)
      mesh.points[p] = Vec2(values[p * components], values[p * components + 1]);
  } else if (in_cells) {
    if (array.name == "connectivity")
      mesh.connectivity = to_ints(values);
    else if (array.name == "offsets")
      mesh.offsets = to_ints(values);
    else if (array.name == "types")
      mesh.types = to_ints(values);
  } else {
    SG_VERIFY(values.size() == n_points * components,
              mesh.path.string() << ": point array '" << array.name << "' holds " << values.size()
                                 << " values, expected " << n_points << " x " << components);
    mesh.point_data.push_back(std::move(array));
  }
}

void check_mesh(const VtuMesh& mesh, std::size_t n_points, std::size_t n_cells) {
  const std::string file = mesh.path.string();
  SG_VERIFY(mesh.points.size() == n_points, file << ": no point coordinates");
  SG_VERIFY(mesh.types.size() == n_cells && mesh.offsets.size() == n_cells,
            file << ": " << mesh.types.size() << " cell types and " << mesh.offsets.size()
                 << " offsets for " << n_cells << " cells");
  int previous = 0;
  for (std::size_t c = 0; c < n_cells; ++c) {
    SG_VERIFY(mesh.offsets[c] >= previous &&
                  static_cast<std::size_t>(mesh.offsets[c]) <= mesh.connectivity.size(),
              file << ": cell " << c << ": offset " << mesh.offsets[c] << " out of order");
    previous = mesh.offsets[c];
  }
  for (int v : mesh.connectivity)
    SG_VERIFY(v >= 0 && static_cast<std::size_t>(v) < n_points,
              file << ": connectivity refers to point " << v << " of " << n_points);
}

}  // namespace

std::span<const int> VtuMesh::cell(std::size_t c) const {
  const auto begin = static_cast<std::size_t>(c == 0 ? 0 : offsets[c - 1]);
  const auto end = static_cast<std::size_t>(offsets[c]);
  return std::span<const int>(connectivity).subspan(begin, end - begin);
}

const VtuArray* VtuMesh::find(std::string_view name) const {
  for (const auto& a : point_data)
    if (a.name == name) return &a;
  return nullptr;
}

namespace {

// The binary side of a file: its <AppendedData encoding="raw"> block, where each appended
// DataArray is VTK's compressed layout (io/vtu_document.h) at its offset from the byte
// after '_'. Only what our writer writes is read: header_type UInt64 and zlib.
class AppendedData {
 public:
  AppendedData(const std::filesystem::path& path, const std::string& text, std::size_t at,
               std::string_view file_tag)
      : path_(path), text_(text) {
    if (at == std::string::npos) return;
    SG_VERIFY(attribute(text.substr(at, text.find('>', at) - at), "encoding") == "raw",
              path.string() << ": <AppendedData> is not encoding=\"raw\"; only raw is read");
    SG_VERIFY(attribute(file_tag, "header_type") == "UInt64" &&
                  attribute(file_tag, "compressor") == "vtkZLibDataCompressor",
              path.string() << ": appended data with header_type '"
                            << attribute(file_tag, "header_type") << "' and compressor '"
                            << attribute(file_tag, "compressor")
                            << "'; only UInt64 headers and vtkZLibDataCompressor are read");
    const auto underscore = text.find('_', at);
    SG_VERIFY(underscore != std::string::npos, path.string() << ": <AppendedData> without '_'");
    begin_ = underscore + 1;
  }

  // The uncompressed bytes of the array at `offset`.
  std::string bytes(std::string_view name, std::size_t offset) const {
    SG_VERIFY(begin_ != 0, path_.string() << ": DataArray '" << name
                                          << "' is appended but the file has no <AppendedData>");
    std::size_t at = begin_ + offset;
    const std::uint64_t blocks = word(name, at), block_size = word(name, at + 8),
                        last_size = word(name, at + 16);
    SG_VERIFY(blocks < text_.size() && block_size > 0 && last_size < block_size,
              path_.string() << ": DataArray '" << name << "': bad compression header");
    std::size_t data = at + 24 + 8 * blocks;
    std::string out;
    for (std::uint64_t b = 0; b < blocks; ++b) {
      const std::uint64_t packed = word(name, at + 24 + 8 * b);
      const bool partial_last = b + 1 == blocks && last_size != 0;
      uLongf size = partial_last ? last_size : block_size;
      SG_VERIFY(data + packed <= text_.size(),
                path_.string() << ": DataArray '" << name << "' is cut short (truncated file)");
      const std::size_t start = out.size();
      out.resize(start + size);
      const int status = uncompress(reinterpret_cast<Bytef*>(out.data() + start), &size,
                                    reinterpret_cast<const Bytef*>(text_.data() + data),
                                    static_cast<uLong>(packed));
      SG_VERIFY(status == Z_OK && size == (partial_last ? last_size : block_size),
                path_.string() << ": DataArray '" << name << "': block " << b
                               << " does not inflate (zlib status " << status << ")");
      data += packed;
    }
    return out;
  }

 private:
  const std::filesystem::path& path_;
  const std::string& text_;
  std::size_t begin_ = 0;  // first byte after '_'; 0: no appended data

  std::uint64_t word(std::string_view name, std::size_t at) const {
    SG_VERIFY(at + 8 <= text_.size(),
              path_.string() << ": DataArray '" << name << "' is cut short (truncated file)");
    std::uint64_t v = 0;
    std::memcpy(&v, text_.data() + at, 8);
    return v;
  }
};

// Bytes of VTK type `type` (little-endian, as our files say) as doubles.
std::vector<double> decode(const std::filesystem::path& path, std::string_view name,
                           const std::string& type, const std::string& bytes) {
  auto values_of = [&]<typename T>(T) {
    SG_VERIFY(bytes.size() % sizeof(T) == 0, path.string() << ": DataArray '" << name << "': "
                                                           << bytes.size() << " bytes of " << type);
    std::vector<double> out(bytes.size() / sizeof(T));
    for (std::size_t i = 0; i < out.size(); ++i) {
      T v;
      std::memcpy(&v, bytes.data() + i * sizeof(T), sizeof(T));
      out[i] = static_cast<double>(v);
    }
    return out;
  };
  if (type == "Float64") return values_of(double{});
  if (type == "Int32") return values_of(std::int32_t{});
  if (type == "UInt8") return values_of(std::uint8_t{});
  SG_THROW(path.string() << ": DataArray '" << name << "' has type '" << type
                         << "'; only Float64, Int32 and UInt8 are read");
}

// The file's end after trailing white space: a file our writer finished ends with it.
bool ends_with_closing_tag(const std::string& text) {
  const auto last = text.find_last_not_of(" \n\r\t");
  const std::string_view tag = "</VTKFile>";
  return last != std::string::npos && last + 1 >= tag.size() &&
         std::string_view(text).substr(last + 1 - tag.size(), tag.size()) == tag;
}

}  // namespace

VtuMesh read_vtu(const std::filesystem::path& path) {
  const std::string text = read_text(path);
  // The XML part: everything before the binary block, if any.
  const auto appended_at = text.find("<AppendedData");
  const std::string_view xml = std::string_view(text).substr(0, appended_at);
  SG_VERIFY(xml.find("type=\"UnstructuredGrid\"") != std::string::npos,
            path.string() << ": not a VTK UnstructuredGrid file");
  // Our writer always closes the document: a file without its end was cut short.
  SG_VERIFY(ends_with_closing_tag(text), path.string() << ": truncated (no closing </VTKFile>)");
  const auto file_tag_at = xml.find("<VTKFile");
  SG_VERIFY(file_tag_at != std::string::npos, path.string() << ": no <VTKFile>");
  const AppendedData appended(path, text, appended_at,
                              xml.substr(file_tag_at, xml.find('>', file_tag_at) - file_tag_at));
  const auto piece = xml.find("<Piece ");
  SG_VERIFY(piece != std::string::npos, path.string() << ": no <Piece>");
  const std::string piece_tag(xml.substr(piece, xml.find('>', piece) - piece));
  const std::string n_points_text = attribute(piece_tag, "NumberOfPoints");
  const std::string n_cells_text = attribute(piece_tag, "NumberOfCells");
  SG_VERIFY(!n_points_text.empty() && !n_cells_text.empty(),
            path.string() << ": <Piece> without NumberOfPoints/NumberOfCells");
  const auto n_points = static_cast<std::size_t>(std::stoull(n_points_text));
  const auto n_cells = static_cast<std::size_t>(std::stoull(n_cells_text));
  const auto points_at = xml.find("<Points>");
  const auto cells_at = xml.find("<Cells>");
  const auto point_data_at = xml.find("<PointData");
  SG_VERIFY(points_at != std::string::npos && cells_at != std::string::npos,
            path.string() << ": missing <Points> or <Cells>");

  VtuMesh mesh;
  mesh.path = path;
  std::size_t at = 0;
  while ((at = xml.find("<DataArray", at)) != std::string::npos) {
    const auto tag_end = xml.find('>', at);
    SG_VERIFY(tag_end != std::string::npos, path.string() << ": unterminated <DataArray>");
    const std::string_view tag = xml.substr(at, tag_end - at);
    const std::string name = attribute(tag, "Name");
    const std::string format = attribute(tag, "format");
    const std::string comp_text = attribute(tag, "NumberOfComponents");
    const int components = comp_text.empty() ? 1 : std::stoi(comp_text);
    std::vector<double> values;
    if (format == "appended") {
      const std::string offset = attribute(tag, "offset");
      SG_VERIFY(!offset.empty(), path.string() << ": DataArray '" << name << "' without offset");
      values = decode(path, name, attribute(tag, "type"),
                      appended.bytes(name, static_cast<std::size_t>(std::stoull(offset))));
      at = tag_end;
    } else {
      SG_VERIFY(format == "ascii", path.string()
                                       << ": DataArray '" << name << "' has format '" << format
                                       << "'; only ascii and appended are read");
      const auto close = xml.find("</DataArray>", tag_end);
      SG_VERIFY(close != std::string::npos, path.string()
                                                << ": DataArray '" << name << "' is not closed");
      values = parse_numbers(path, name, text, tag_end + 1, close);
      at = close;
    }
    store_array(mesh, {name, components, std::move(values)},
                at > points_at && at<cells_at, at> cells_at &&
                    (point_data_at == std::string::npos || at < point_data_at),
                n_points);
  }
  check_mesh(mesh, n_points, n_cells);
  return mesh;
}

std::vector<double> point_scalar(const VtuMesh& mesh, std::string_view field) {
  std::string_view name = field == "body" ? std::string_view("body_id") : field;
  const VtuArray* a = mesh.find(name);
  int component = -1;  // -1: magnitude of a vector array
  if (!a && name.size() > 2 && (name.ends_with("_x") || name.ends_with("_y"))) {
    a = mesh.find(name.substr(0, name.size() - 2));
    if (a && a->components >= 2)
      component = name.back() == 'x' ? 0 : 1;
    else
      a = nullptr;
  }
  if (!a) {
    std::string present;
    for (const auto& p : mesh.point_data)
      present += (present.empty() ? "" : ", ") + p.name;
    SG_THROW(mesh.path.string() << ": no point field '" << field << "' (present: " << present
                                << ")");
  }
  const auto n = mesh.points.size();
  const auto k = static_cast<std::size_t>(a->components);
  std::vector<double> out(n);
  for (std::size_t p = 0; p < n; ++p) {
    if (k == 1) {
      out[p] = a->values[p];
    } else if (component >= 0) {
      out[p] = a->values[p * k + static_cast<std::size_t>(component)];
    } else {
      double s = 0.0;
      for (std::size_t c = 0; c < k; ++c)
        s += a->values[p * k + c] * a->values[p * k + c];
      out[p] = std::sqrt(s);
    }
  }
  return out;
}

std::vector<PvdEntry> read_pvd(const std::filesystem::path& path) {
  const std::string text = read_text(path);
  SG_VERIFY(text.find("type=\"Collection\"") != std::string::npos,
            path.string() << ": not a VTK Collection (.pvd) file");
  std::vector<PvdEntry> entries;
  std::size_t at = 0;
  while ((at = text.find("<DataSet", at)) != std::string::npos) {
    const auto end = text.find('>', at);
    SG_VERIFY(end != std::string::npos, path.string() << ": unterminated <DataSet>");
    const std::string_view tag(text.data() + at, end - at);
    const std::string time = attribute(tag, "timestep");
    const std::string file = attribute(tag, "file");
    SG_VERIFY(!time.empty() && !file.empty(), path.string()
                                                  << ": <DataSet> without timestep or file");
    entries.push_back({std::stod(time), path.parent_path() / file});
    at = end;
  }
  return entries;
}

}  // namespace sg
