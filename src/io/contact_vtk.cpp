#include "io/contact_vtk.h"

#include <iomanip>

#include "io/atomic_file.h"
#include "io/contact_rate.h"
#include "io/vtk_writer.h"

namespace sg {

namespace {

void write_points_and_cells(std::ostream& out, const std::vector<ContactRecord>& records) {
  const std::size_t n = records.size();
  out << "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" "
         "format=\"ascii\">\n";
  for (const ContactRecord& r : records)
    out << r.position.x() << ' ' << r.position.y() << " 0\n";
  out << "        </DataArray>\n      </Points>\n      <Cells>\n"
         "        <DataArray type=\"Int32\" Name=\"connectivity\" format=\"ascii\">\n";
  for (std::size_t i = 0; i < n; ++i)
    out << i << '\n';
  out << "        </DataArray>\n        <DataArray type=\"Int32\" Name=\"offsets\" "
         "format=\"ascii\">\n";
  for (std::size_t i = 0; i < n; ++i)
    out << i + 1 << '\n';
  out << "        </DataArray>\n        <DataArray type=\"UInt8\" Name=\"types\" "
         "format=\"ascii\">\n";
  for (std::size_t i = 0; i < n; ++i)
    out << "1\n";  // VTK_VERTEX
  out << "        </DataArray>\n      </Cells>\n";
}

}  // namespace

void write_contact_snapshot(const ContactSystem& contacts, const Model& model,
                            std::span<const Vec2> contour_velocity, double global_strain_rate,
                            const std::filesystem::path& path) {
  const std::vector<ContactRecord>& records = contacts.records();
  const std::size_t n = records.size();
  std::vector<ContactRate> rates(n);
  for (std::size_t i = 0; i < n; ++i)
    rates[i] = contact_rate(model, records[i], contour_velocity, global_strain_rate);
  const std::vector<int> field_point = contour_point_field_index(model);
  write_file_atomically(path, [&](std::ostream& out) {
    out << std::setprecision(9);
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n << "\">\n";
    write_points_and_cells(out, records);
    out << "      <PointData Vectors=\"force\">\n";
    // One array: `get(i)` of every contact i (a Vec2 for vectors, a number for scalars).
    auto vectors = [&](const char* name, auto&& get) {
      out << "        <DataArray type=\"Float64\" Name=\"" << name
          << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (std::size_t i = 0; i < n; ++i) {
        const Vec2 v = get(i);
        out << v.x() << ' ' << v.y() << " 0\n";
      }
      out << "        </DataArray>\n";
    };
    auto scalars = [&](const char* name, const char* type, auto&& get) {
      out << "        <DataArray type=\"" << type << "\" Name=\"" << name
          << "\" format=\"ascii\">\n";
      for (std::size_t i = 0; i < n; ++i)
        out << get(i) << '\n';
      out << "        </DataArray>\n";
    };
    auto record = [&](auto&& get) { return [&, get](std::size_t i) { return get(records[i]); }; };
    vectors("normal", record([](const ContactRecord& r) { return r.normal; }));
    vectors("force", record([](const ContactRecord& r) -> Vec2 {
              return r.length *
                     (r.traction.normal * r.normal + r.traction.tangential * perp(r.normal));
            }));
    scalars("normal_force", "Float64",
            record([](const ContactRecord& r) { return r.length * r.traction.normal; }));
    scalars("tangential_force", "Float64",
            record([](const ContactRecord& r) { return r.length * r.traction.tangential; }));
    scalars("gap", "Float64", record([](const ContactRecord& r) { return r.gap; }));
    scalars("length", "Float64", record([](const ContactRecord& r) { return r.length; }));
    scalars("state", "Int32", record([](const ContactRecord& r) {
              if (r.traction.normal == 0.0 && r.traction.tangential == 0.0) return 0;
              return r.traction.slipping ? 2 : 1;
            }));
    scalars("slave_body", "Int32", record([](const ContactRecord& r) { return r.slave_body; }));
    scalars("master_body", "Int32", record([](const ContactRecord& r) { return r.master_body; }));
    vectors("relative_velocity", [&](std::size_t i) { return rates[i].relative_velocity; });
    scalars("contact_rate", "Float64", [&](std::size_t i) { return rates[i].rate; });
    scalars("field_point", "Int32", [&](std::size_t i) {
      return field_point[static_cast<std::size_t>(records[i].slave_point)];
    });
    out << "      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  });
}

}  // namespace sg
