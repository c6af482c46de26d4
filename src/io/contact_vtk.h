#pragma once
// The contact network for ParaView: one VTK XML UnstructuredGrid of vertices per snapshot,
// a vertex at each evaluated contact (the slave contour point) with
//   normal (master outward normal), force (on the slave point: l (p_n n + p_t t)),
//   normal_force, tangential_force (per contact, force units), gap, length (tributary),
//   state (0 open/broken, 1 sticking, 2 slipping), slave_body, master_body,
//   relative_velocity (of the slave point against the master, io/contact_rate.h),
//   contact_rate (the contact-level strain rate, io/contact_rate.h, in V/D like the nodal
//   strain_rate), field_point (the slave point's index in the point list of the
//   fields/NNNNNN.vtu of the same number: io/vtk_writer.h contour_point_field_index).
#include <filesystem>
#include <span>

#include "contact/contact_system.h"
#include "scenario/scenario.h"  // FieldFormat

namespace sg {

// `contour_velocity`: compute_contour_velocities at the instant of the contacts' evaluation;
// `global_strain_rate`: V/D (NaN: contact_rate in 1/time). The model gives body and contour
// ranges only. `format`: the encoding of the arrays, as the fields' (io/vtu_document.h).
void write_contact_snapshot(const ContactSystem& contacts, const Model& model,
                            std::span<const Vec2> contour_velocity, double global_strain_rate,
                            const std::filesystem::path& path,
                            FieldFormat format = FieldFormat::binary);

}  // namespace sg
