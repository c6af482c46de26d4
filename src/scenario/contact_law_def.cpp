#include "scenario/contact_law_def.h"

#include <initializer_list>

#include "core/error.h"
#include "scenario/toml_reader.h"

namespace sg {

namespace {

ContactLawKind read_kind(const TomlReader& t) {
  const std::string law = t.one_of(
      "law", {"frictionless", "coulomb", "cohesive", "two_slope", "bonded", "cohesive_zone"},
      "frictionless");
  for (const ContactLawKind kind :
       {ContactLawKind::frictionless, ContactLawKind::coulomb, ContactLawKind::cohesive,
        ContactLawKind::two_slope, ContactLawKind::bonded, ContactLawKind::cohesive_zone})
    if (law == contact_law_kind_name(kind)) return kind;
  t.fail("law", "unknown law '" + law + "'");
}

// Keys that belong to some kinds only: given to another kind, they are a mistake.
void reject_keys_of_other_kinds(const TomlReader& t, ContactLawKind kind) {
  using K = ContactLawKind;
  struct KeyKinds {
    const char* key;
    std::initializer_list<K> kinds;
    const char* names;
  };
  const KeyKinds keys[] = {
      {"unloading_ratio", {K::two_slope}, "\"two_slope\""},
      {"bond_normal_stiffness", {K::bonded}, "\"bonded\""},
      {"bond_tensile_strength", {K::bonded}, "\"bonded\""},
      {"bond_shear_strength", {K::bonded}, "\"bonded\""},
      {"bond_friction", {K::bonded}, "\"bonded\""},
      {"bond_gap", {K::bonded, K::cohesive_zone}, "\"bonded\" or \"cohesive_zone\""},
      {"peak_traction", {K::cohesive_zone}, "\"cohesive_zone\""},
      {"critical_opening", {K::cohesive_zone}, "\"cohesive_zone\""},
      {"residual_traction", {K::cohesive_zone}, "\"cohesive_zone\""},
      {"mixed_mode_ratio", {K::cohesive_zone}, "\"cohesive_zone\""},
      {"tangential_stiffness",
       {K::coulomb, K::cohesive, K::two_slope, K::bonded},
       "\"coulomb\", \"cohesive\", \"two_slope\" or \"bonded\" (cohesive_zone: normal_stiffness "
       "both ways)"},
  };
  for (const KeyKinds& k : keys) {
    if (!t.has(k.key)) continue;
    bool used = false;
    for (const K kind_using : k.kinds)
      used = used || kind_using == kind;
    if (!used && !(kind == K::frictionless && std::string(k.key) == "tangential_stiffness"))
      t.fail(k.key, std::string("applies only to law = ") + k.names);
  }
}

}  // namespace

ContactLawDef read_contact_law(const TomlReader& t) {
  t.reject_unknown_keys({"materials",
                         "law",
                         "normal_stiffness",
                         "tangential_stiffness",
                         "friction",
                         "adhesion",
                         "shear_strength",
                         "cohesion",
                         "damping_ratio",
                         "length",
                         "unloading_ratio",
                         "bond_normal_stiffness",
                         "bond_tensile_strength",
                         "bond_shear_strength",
                         "bond_friction",
                         "bond_gap",
                         "peak_traction",
                         "critical_opening",
                         "residual_traction",
                         "mixed_mode_ratio"});
  ContactLawDef d;
  const auto pair = t.string_pair("materials");
  d.material_a = pair.first;
  d.material_b = pair.second;
  ContactLawParams& p = d.params;
  p.kind = read_kind(t);
  reject_keys_of_other_kinds(t, p.kind);
  p.normal_stiffness = t.positive("normal_stiffness");
  if (p.kind == ContactLawKind::cohesive_zone)
    p.tangential_stiffness = p.normal_stiffness;  // one stiffness, as the envelope's
  else if (p.kind != ContactLawKind::frictionless)
    p.tangential_stiffness = t.positive("tangential_stiffness", p.normal_stiffness);
  p.friction = t.non_negative("friction", 0.0);
  // cohesion = c sets sigma_c = tau_c = c (the papers' single parameter).
  const double cohesion = t.non_negative("cohesion", 0.0);
  p.adhesion = t.non_negative("adhesion", cohesion);
  p.shear_strength = t.non_negative("shear_strength", cohesion);
  p.damping_ratio = t.non_negative("damping_ratio", 0.0);
  p.length = t.one_of("length", {"current", "initial"}, "current") == "current"
                 ? ContactLength::current
                 : ContactLength::initial;
  p.unloading_ratio = t.positive("unloading_ratio", 1.0);
  if (p.kind == ContactLawKind::bonded) {
    p.bond_normal_stiffness = t.positive("bond_normal_stiffness", p.normal_stiffness);
    p.bond_tensile_strength = t.non_negative("bond_tensile_strength", 0.0);
    p.bond_shear_strength = t.non_negative("bond_shear_strength", 0.0);
    p.bond_friction = t.non_negative("bond_friction", 0.0);
  }
  p.bond_gap = t.non_negative("bond_gap", 0.0);
  if (p.kind == ContactLawKind::cohesive_zone) {
    p.peak_traction = t.positive("peak_traction");
    p.critical_opening = t.positive("critical_opening");
    p.residual_traction = t.non_negative("residual_traction", 0.0);
    p.mixed_mode_ratio = t.positive("mixed_mode_ratio", 1.0);
  }
  try {
    validate(p, "contact law for materials '" + d.material_a + "' and '" + d.material_b + "'");
  } catch (const Error& e) {
    t.fail("law", e.what());
  }
  return d;
}

}  // namespace sg
