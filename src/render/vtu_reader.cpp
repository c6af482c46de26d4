#include "render/vtu_reader.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
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

VtuMesh read_vtu(const std::filesystem::path& path) {
  const std::string text = read_text(path);
  SG_VERIFY(text.find("type=\"UnstructuredGrid\"") != std::string::npos,
            path.string() << ": not a VTK UnstructuredGrid file");
  // Our writer always closes the document: a file without its end was cut short.
  SG_VERIFY(text.find("</VTKFile>") != std::string::npos,
            path.string() << ": truncated (no closing </VTKFile>)");
  const auto piece = text.find("<Piece ");
  SG_VERIFY(piece != std::string::npos, path.string() << ": no <Piece>");
  const std::string piece_tag = text.substr(piece, text.find('>', piece) - piece);
  const std::string n_points_text = attribute(piece_tag, "NumberOfPoints");
  const std::string n_cells_text = attribute(piece_tag, "NumberOfCells");
  SG_VERIFY(!n_points_text.empty() && !n_cells_text.empty(),
            path.string() << ": <Piece> without NumberOfPoints/NumberOfCells");
  const auto n_points = static_cast<std::size_t>(std::stoull(n_points_text));
  const auto n_cells = static_cast<std::size_t>(std::stoull(n_cells_text));
  const auto points_at = text.find("<Points>");
  const auto cells_at = text.find("<Cells>");
  const auto point_data_at = text.find("<PointData");
  SG_VERIFY(points_at != std::string::npos && cells_at != std::string::npos,
            path.string() << ": missing <Points> or <Cells>");

  VtuMesh mesh;
  mesh.path = path;
  std::size_t at = 0;
  while ((at = text.find("<DataArray", at)) != std::string::npos) {
    const auto tag_end = text.find('>', at);
    SG_VERIFY(tag_end != std::string::npos, path.string() << ": unterminated <DataArray>");
    const std::string_view tag(text.data() + at, tag_end - at);
    const std::string name = attribute(tag, "Name");
    const std::string format = attribute(tag, "format");
    SG_VERIFY(format == "ascii", path.string() << ": DataArray '" << name << "' has format '"
                                               << format << "'; only ascii is read");
    const std::string comp_text = attribute(tag, "NumberOfComponents");
    const int components = comp_text.empty() ? 1 : std::stoi(comp_text);
    const auto close = text.find("</DataArray>", tag_end);
    SG_VERIFY(close != std::string::npos, path.string()
                                              << ": DataArray '" << name << "' is not closed");
    std::vector<double> values = parse_numbers(path, name, text, tag_end + 1, close);
    // Our writer's order: <Points>, <Cells>, <PointData>.
    if (at > points_at && at < cells_at) {
      SG_VERIFY(components >= 2 && values.size() == n_points * static_cast<std::size_t>(components),
                path.string() << ": Points hold " << values.size() << " values for " << n_points
                              << " points of " << components << " components");
      mesh.points.resize(n_points);
      for (std::size_t p = 0; p < n_points; ++p)
        mesh.points[p] = Vec2(values[p * static_cast<std::size_t>(components)],
                              values[p * static_cast<std::size_t>(components) + 1]);
    } else if (at > cells_at && (point_data_at == std::string::npos || at < point_data_at)) {
      if (name == "connectivity")
        mesh.connectivity = to_ints(values);
      else if (name == "offsets")
        mesh.offsets = to_ints(values);
      else if (name == "types")
        mesh.types = to_ints(values);
    } else if (point_data_at != std::string::npos && at > point_data_at) {
      SG_VERIFY(values.size() == n_points * static_cast<std::size_t>(components),
                path.string() << ": point array '" << name << "' holds " << values.size()
                              << " values, expected " << n_points << " x " << components);
      mesh.point_data.push_back({name, components, std::move(values)});
    }
    at = close;
  }
  SG_VERIFY(mesh.points.size() == n_points, path.string() << ": no point coordinates");
  SG_VERIFY(mesh.types.size() == n_cells && mesh.offsets.size() == n_cells,
            path.string() << ": " << mesh.types.size() << " cell types and " << mesh.offsets.size()
                          << " offsets for " << n_cells << " cells");
  int previous = 0;
  for (std::size_t c = 0; c < n_cells; ++c) {
    SG_VERIFY(mesh.offsets[c] >= previous &&
                  static_cast<std::size_t>(mesh.offsets[c]) <= mesh.connectivity.size(),
              path.string() << ": cell " << c << ": offset " << mesh.offsets[c] << " out of order");
    previous = mesh.offsets[c];
  }
  for (int v : mesh.connectivity)
    SG_VERIFY(v >= 0 && static_cast<std::size_t>(v) < n_points,
              path.string() << ": connectivity refers to point " << v << " of " << n_points);
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
