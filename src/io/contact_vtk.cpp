#include "io/contact_vtk.h"

#include <iomanip>

#include "io/atomic_file.h"

namespace sg {

void write_contact_snapshot(const ContactSystem& contacts, const std::filesystem::path& path) {
  const std::vector<ContactRecord>& records = contacts.records();
  const std::size_t n = records.size();
  write_file_atomically(path, [&](std::ostream& out) {
    out << std::setprecision(9);
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
           "  <UnstructuredGrid>\n"
        << "    <Piece NumberOfPoints=\"" << n << "\" NumberOfCells=\"" << n << "\">\n"
        << "      <Points>\n        <DataArray type=\"Float64\" NumberOfComponents=\"3\" "
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
    out << "        </DataArray>\n      </Cells>\n      <PointData Vectors=\"force\">\n";
    auto vectors = [&](const char* name, auto&& get) {
      out << "        <DataArray type=\"Float64\" Name=\"" << name
          << "\" NumberOfComponents=\"3\" format=\"ascii\">\n";
      for (const ContactRecord& r : records) {
        const Vec2 v = get(r);
        out << v.x() << ' ' << v.y() << " 0\n";
      }
      out << "        </DataArray>\n";
    };
    auto scalars = [&](const char* name, const char* type, auto&& get) {
      out << "        <DataArray type=\"" << type << "\" Name=\"" << name
          << "\" format=\"ascii\">\n";
      for (const ContactRecord& r : records)
        out << get(r) << '\n';
      out << "        </DataArray>\n";
    };
    vectors("normal", [](const ContactRecord& r) { return r.normal; });
    vectors("force", [](const ContactRecord& r) -> Vec2 {
      return r.length * (r.traction.normal * r.normal + r.traction.tangential * perp(r.normal));
    });
    scalars("normal_force", "Float64",
            [](const ContactRecord& r) { return r.length * r.traction.normal; });
    scalars("tangential_force", "Float64",
            [](const ContactRecord& r) { return r.length * r.traction.tangential; });
    scalars("gap", "Float64", [](const ContactRecord& r) { return r.gap; });
    scalars("length", "Float64", [](const ContactRecord& r) { return r.length; });
    scalars("state", "Int32", [](const ContactRecord& r) {
      if (r.traction.normal == 0.0 && r.traction.tangential == 0.0) return 0;
      return r.traction.slipping ? 2 : 1;
    });
    scalars("slave_body", "Int32", [](const ContactRecord& r) { return r.slave_body; });
    scalars("master_body", "Int32", [](const ContactRecord& r) { return r.master_body; });
    out << "      </PointData>\n    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
  });
}

}  // namespace sg
