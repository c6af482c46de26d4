#pragma once
// The contact-level strain rate on grain outlines (io/contact_rate.h): a strain-rate picture
// shows how fast the velocity jump between grains is accommodated at their contacts beside
// the strain rate inside them, with one colour map, so that "deformation inside grains vs
// between grains" reads from one picture (papers 001 Figs 6-12, 003 Figs 4 and 10).
//
// Each contact of contacts/NNNNNN.vtu names its slave point in fields/NNNNNN.vtu
// (field_point); the outline around that point (half of each boundary edge at it) takes the
// colour of its contact_rate, the largest where a point has several contacts (one per
// master body it touches).
#include <filesystem>
#include <string>
#include <vector>

#include "render/vtu_reader.h"

namespace sg {

// The fields whose pictures carry the contact rates.
bool field_shows_contact_rates(const std::string& field);

// Per point of the field snapshot `field_file` (with `point_count` points): the largest
// contact_rate of the contacts at it, NaN where there is none. Empty when the run wrote no
// contacts/<same name>.vtu (no contact laws); also empty, with a `note`, for a contacts file
// without contact_rate (written by an older softgrain). Throws sg::Error naming the file for
// a field_point outside the snapshot.
std::vector<double> contact_rates_on_points(const std::filesystem::path& field_file,
                                            std::size_t point_count, std::string& note);

// The boundary edges of a snapshot (point pairs, lower index first): the triangle edges used
// by one triangle (the grains' outlines), sorted, then with_polygons the edges of the rigid
// bodies' polygons in cell order.
std::vector<std::pair<int, int>> boundary_edges(const VtuMesh& mesh, bool with_polygons);

}  // namespace sg
