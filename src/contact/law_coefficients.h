#pragma once
// The coefficients that only some contact laws use, in one table: which laws use each, its
// value in the laws that do not, and how the scenario reads it. The scenario reader
// (scenario/contact_law_def.cpp) accepts, reads and refuses the keys of [[contact_laws]] from
// it, and validate() (contact_law.h) refuses a coefficient set on a law that does not use it
// or out of its row's bound: adding a coefficient to a law is one row here (and its use in the
// law's evaluation). The coefficients every law reads (normal_stiffness, tangential_stiffness,
// friction, adhesion, shear_strength, damping_ratio, length) are ContactLawParams' first
// members, read and checked by the reader and validate() themselves.
#include <initializer_list>
#include <span>
#include <string>

#include "contact/contact_law.h"

namespace sg {

struct LawCoefficient {
  enum class Bound { non_negative, positive };
  const char* key;                              // scenario key, and its name in messages
  double ContactLawParams::*member;             // where the law keeps it
  std::initializer_list<ContactLawKind> kinds;  // the laws that use it
  double unused_value;                          // its value in every other law
  Bound bound;
  // Read when absent: `fallback`, or the coefficient `fallback_member` when set (bond_normal_
  // stiffness defaults to normal_stiffness); `required` coefficients have no fallback.
  bool required = false;
  double fallback = 0.0;
  double ContactLawParams::*fallback_member = nullptr;
};

// Every row, in the order the reader reads them.
std::span<const LawCoefficient> law_coefficients();

bool is_used_by(const LawCoefficient& c, ContactLawKind kind);

// The laws that use `c`, quoted, as a message lists them: "\"bonded\" or \"cohesive_zone\"".
std::string names_of_laws_using(const LawCoefficient& c);

}  // namespace sg
