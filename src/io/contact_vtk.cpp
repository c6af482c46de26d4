#include "io/contact_vtk.h"

#include "io/atomic_file.h"
#include "io/contact_rate.h"
#include "io/vtk_writer.h"
#include "io/vtu_document.h"

namespace sg {

namespace {

// One vertex cell per contact.
std::vector<VtuDataArray> vertex_cells(std::size_t n) {
  return {
      scalar_data_array("connectivity", VtkType::int32, n, [](std::size_t i) { return i; }),
      scalar_data_array("offsets", VtkType::int32, n, [](std::size_t i) { return i + 1; }),
      scalar_data_array("types", VtkType::uint8, n, [](std::size_t) { return 1; })};  // VTK_VERTEX
}

int contact_state(const ContactRecord& r) {
  if (r.traction.normal == 0.0 && r.traction.tangential == 0.0) return 0;
  return r.traction.slipping ? 2 : 1;
}

}  // namespace

void write_contact_snapshot(const ContactSystem& contacts, const Model& model,
                            std::span<const Vec2> contour_velocity, double global_strain_rate,
                            const std::filesystem::path& path, FieldFormat format) {
  const std::vector<ContactRecord>& records = contacts.records();
  const std::size_t n = records.size();
  std::vector<ContactRate> rates(n);
  for (std::size_t i = 0; i < n; ++i)
    rates[i] = contact_rate(model, records[i], contour_velocity, global_strain_rate);
  const std::vector<int> field_point = contour_point_field_index(model);
  VtuDocument doc;
  doc.point_count = doc.cell_count = n;
  doc.points = vector_data_array("", n, [&](std::size_t i) { return records[i].position; });
  doc.cells = vertex_cells(n);
  doc.point_data_attributes = "Vectors=\"force\"";
  auto vectors = [&](const char* name, auto&& get) {
    doc.point_data.push_back(vector_data_array(name, n, get));
  };
  auto scalars = [&](const char* name, VtkType type, auto&& get) {
    doc.point_data.push_back(scalar_data_array(name, type, n, get));
  };
  auto record = [&](auto&& get) { return [&, get](std::size_t i) { return get(records[i]); }; };
  vectors("normal", record([](const ContactRecord& r) { return r.normal; }));
  vectors("force", record([](const ContactRecord& r) -> Vec2 {
            return r.length *
                   (r.traction.normal * r.normal + r.traction.tangential * perp(r.normal));
          }));
  scalars("normal_force", VtkType::float64,
          record([](const ContactRecord& r) { return r.length * r.traction.normal; }));
  scalars("tangential_force", VtkType::float64,
          record([](const ContactRecord& r) { return r.length * r.traction.tangential; }));
  scalars("gap", VtkType::float64, record([](const ContactRecord& r) { return r.gap; }));
  scalars("length", VtkType::float64, record([](const ContactRecord& r) { return r.length; }));
  scalars("state", VtkType::int32, record([](const ContactRecord& r) { return contact_state(r); }));
  scalars("slave_body", VtkType::int32,
          record([](const ContactRecord& r) { return r.slave_body; }));
  scalars("master_body", VtkType::int32,
          record([](const ContactRecord& r) { return r.master_body; }));
  vectors("relative_velocity", [&](std::size_t i) { return rates[i].relative_velocity; });
  scalars("contact_rate", VtkType::float64, [&](std::size_t i) { return rates[i].rate; });
  scalars("field_point", VtkType::int32, [&](std::size_t i) {
    return field_point[static_cast<std::size_t>(records[i].slave_point)];
  });
  write_file_atomically(path, [&](std::ostream& out) { write_vtu_document(doc, format, out); });
}

}  // namespace sg
