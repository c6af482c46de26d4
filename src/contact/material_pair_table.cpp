#include "contact/material_pair_table.h"

#include <algorithm>
#include <sstream>

#include "core/error.h"

namespace sg {

MaterialPairTable::MaterialPairTable(std::vector<std::string> material_names)
    : names_(std::move(material_names)) {
  for (std::size_t i = 0; i < names_.size(); ++i) {
    SG_VERIFY(!names_[i].empty(), "material " << i << " has an empty name");
    for (std::size_t j = 0; j < i; ++j) {
      SG_VERIFY(names_[i] != names_[j], "material name '" << names_[i] << "' is used twice");
    }
  }
  slot_.assign(names_.size() * names_.size(), -1);
}

void MaterialPairTable::check_id(int material) const {
  SG_VERIFY(material >= 0 && material < material_count(),
            "material id " << material << " out of range (" << material_count() << " materials)");
}

const std::string& MaterialPairTable::material_name(int material) const {
  check_id(material);
  return names_[static_cast<std::size_t>(material)];
}

int MaterialPairTable::find_material(std::string_view name) const {
  for (std::size_t i = 0; i < names_.size(); ++i) {
    if (names_[i] == name) return static_cast<int>(i);
  }
  std::ostringstream known;
  for (std::size_t i = 0; i < names_.size(); ++i)
    known << (i ? ", " : "") << names_[i];
  SG_THROW("unknown material '" << name << "' (known: " << known.str() << ")");
}

void MaterialPairTable::set(int a, int b, const ContactLawParams& params) {
  check_id(a);
  check_id(b);
  const std::string context =
      "contact law for materials '" + material_name(a) + "' and '" + material_name(b) + "'";
  validate(params, context);
  const std::size_t n = names_.size();
  const std::size_t ab = static_cast<std::size_t>(a) * n + static_cast<std::size_t>(b);
  const std::size_t ba = static_cast<std::size_t>(b) * n + static_cast<std::size_t>(a);
  SG_VERIFY(slot_[ab] < 0, context << " is given twice");
  slot_[ab] = slot_[ba] = static_cast<int>(laws_.size());
  laws_.push_back(params);
}

void MaterialPairTable::set(std::string_view a, std::string_view b,
                            const ContactLawParams& params) {
  set(find_material(a), find_material(b), params);
}

bool MaterialPairTable::has(int a, int b) const {
  check_id(a);
  check_id(b);
  return slot_[static_cast<std::size_t>(a) * names_.size() + static_cast<std::size_t>(b)] >= 0;
}

const ContactLawParams& MaterialPairTable::at(int a, int b) const {
  const int slot =
      (a >= 0 && a < material_count() && b >= 0 && b < material_count())
          ? slot_[static_cast<std::size_t>(a) * names_.size() + static_cast<std::size_t>(b)]
          : -1;
  if (slot < 0) {  // error path only: names and strings are built here
    check_id(a);
    check_id(b);
    SG_THROW("no contact law for materials '" << material_name(a) << "' and '" << material_name(b)
                                              << "'");
  }
  return laws_[static_cast<std::size_t>(slot)];
}

void MaterialPairTable::verify_covers(std::span<const int> materials) const {
  std::vector<int> used(materials.begin(), materials.end());
  std::sort(used.begin(), used.end());
  used.erase(std::unique(used.begin(), used.end()), used.end());
  for (std::size_t i = 0; i < used.size(); ++i) {
    for (std::size_t j = i; j < used.size(); ++j)
      (void)at(used[i], used[j]);
  }
}

MaterialPairTable MaterialPairTable::per_pass() const {
  MaterialPairTable half = *this;
  for (ContactLawParams& law : half.laws_)
    law = per_pass_params(law);
  return half;
}

}  // namespace sg
