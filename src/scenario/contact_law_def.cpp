#include "scenario/contact_law_def.h"

#include "contact/law_coefficients.h"
#include "core/error.h"
#include "scenario/toml_reader.h"

namespace sg {

namespace {

// Keys that belong to some kinds only (contact/law_coefficients.h): given to another kind,
// they are a mistake.
void reject_keys_of_other_kinds(const TomlReader& t, ContactLawKind kind) {
  for (const LawCoefficient& c : law_coefficients())
    if (t.has(c.key) && !is_used_by(c, kind))
      t.fail(c.key, "applies only to law = " + names_of_laws_using(c));
  // cohesive_zone has one stiffness both ways; a frictionless law ignores a tangential one.
  if (t.has("tangential_stiffness") && kind == ContactLawKind::cohesive_zone)
    t.fail("tangential_stiffness",
           "applies only to law = \"coulomb\", \"cohesive\", \"two_slope\" or \"bonded\" "
           "(cohesive_zone: normal_stiffness both ways)");
}

// The coefficients of law_coefficients.h that `kind` uses, with their bounds and fallbacks.
void read_kind_coefficients(const TomlReader& t, ContactLawParams& p) {
  for (const LawCoefficient& c : law_coefficients()) {
    if (!is_used_by(c, p.kind)) continue;
    const bool positive = c.bound == LawCoefficient::Bound::positive;
    if (c.required) {
      SG_ASSERT(positive, c.key << ": a required coefficient is read as a positive number");
      p.*c.member = t.positive(c.key);
      continue;
    }
    const double fallback = c.fallback_member ? p.*c.fallback_member : c.fallback;
    p.*c.member = positive ? t.positive(c.key, fallback) : t.non_negative(c.key, fallback);
  }
}

// The keys a [[contact_laws]] table may hold: those every law reads, and the table's.
std::vector<std::string> known_keys() {
  std::vector<std::string> keys = {
      "materials",     "law",      "normal_stiffness", "tangential_stiffness",
      "friction",      "adhesion", "shear_strength",   "cohesion",
      "damping_ratio", "length"};
  for (const LawCoefficient& c : law_coefficients())
    keys.emplace_back(c.key);
  return keys;
}

}  // namespace

ContactLawDef read_contact_law(const TomlReader& t) {
  t.reject_unknown_keys(known_keys());
  ContactLawDef d;
  const auto pair = t.string_pair("materials");
  d.material_a = pair.first;
  d.material_b = pair.second;
  ContactLawParams& p = d.params;
  p.kind = t.named_value("law", kContactLawKinds, ContactLawKind::frictionless);
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
  p.length = t.named_value("length", kContactLengths, ContactLength::current);
  read_kind_coefficients(t, p);
  try {
    validate(p, "contact law for materials '" + d.material_a + "' and '" + d.material_b + "'");
  } catch (const Error& e) {
    t.fail("law", e.what());
  }
  return d;
}

}  // namespace sg
