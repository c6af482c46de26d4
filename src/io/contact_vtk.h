#pragma once
// The contact network for ParaView: one VTK XML UnstructuredGrid of vertices per snapshot,
// a vertex at each evaluated contact (the slave contour point) with
//   normal (master outward normal), force (on the slave point: l (p_n n + p_t t)),
//   normal_force, tangential_force (per contact, force units), gap, length (tributary),
//   state (0 open/broken, 1 sticking, 2 slipping), slave_body, master_body.
#include <filesystem>

#include "contact/contact_system.h"

namespace sg {

void write_contact_snapshot(const ContactSystem& contacts, const std::filesystem::path& path);

}  // namespace sg
