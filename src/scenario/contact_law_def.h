#pragma once
// One [[contact_laws]] entry of a scenario: the material pair and its law's coefficients
// (contact/contact_law.h), read and checked from TOML. docs/scenario.md lists the keys.
#include <string>

#include "contact/contact_law.h"

namespace sg {

class TomlReader;

struct ContactLawDef {
  std::string material_a, material_b;
  ContactLawParams params;
};

// Reads one [[contact_laws]] table. Errors name the file, the line and the key: an unknown
// key, a key of another law ("applies only to law = ..."), a value out of range.
ContactLawDef read_contact_law(const TomlReader& t);

}  // namespace sg
