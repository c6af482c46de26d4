// The one table of the coefficients only some laws use (contact/law_coefficients.h), as
// validate() (contact/contact_law.h) reads it, and the one table of law names.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "contact/contact_law.h"
#include "contact/law_coefficients.h"
#include "core/error.h"

namespace sg {
namespace {

// A valid law of `kind` with every coefficient at its value when not given.
ContactLawParams valid_law(ContactLawKind kind) {
  ContactLawParams p;
  p.kind = kind;
  p.normal_stiffness = 1000.0;
  if (kind != ContactLawKind::frictionless) p.tangential_stiffness = 1000.0;
  if (kind == ContactLawKind::bonded) p.bond_normal_stiffness = 1000.0;
  if (kind == ContactLawKind::cohesive_zone) {
    p.peak_traction = 1.0;
    p.critical_opening = 0.1;
  }
  return p;
}

std::string error_of(const ContactLawParams& p) {
  try {
    validate(p, "contact law for materials 'a' and 'b'");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// A row's bound is what validate() applies to the laws that use it: a positive coefficient at
// 0 is refused naming its key, a negative one always; a row added to the table is covered
// here without a new test.
TEST(LawCoefficients, ValidateAppliesEachRowsBound) {
  for (const ContactLawKind kind : kContactLawKinds) {
    ASSERT_EQ(error_of(valid_law(kind)), "") << contact_law_kind_name(kind);
    for (const LawCoefficient& c : law_coefficients()) {
      if (!is_used_by(c, kind)) continue;
      SCOPED_TRACE(std::string(c.key) + " on a " + contact_law_kind_name(kind) + " law");
      ContactLawParams p = valid_law(kind);
      p.*c.member = -1.0;
      const std::string negative = error_of(p);
      EXPECT_NE(negative.find(c.key), std::string::npos) << negative;
      p.*c.member = 0.0;
      const std::string zero = error_of(p);
      if (c.bound == LawCoefficient::Bound::positive) {
        EXPECT_NE(zero.find(std::string(c.key) + " must be > 0"), std::string::npos) << zero;
      } else {
        EXPECT_EQ(zero, "");
      }
    }
  }
}

// Every law has its own name, which is what to_string (the readers' table) gives.
TEST(LawCoefficients, EveryLawHasItsOwnName) {
  std::set<std::string> names;
  for (const ContactLawKind kind : kContactLawKinds) {
    const std::string name = to_string(kind);
    EXPECT_EQ(name, contact_law_kind_name(kind));
    EXPECT_NE(name, "unknown");
    EXPECT_TRUE(names.insert(name).second) << name << " twice";
  }
  EXPECT_EQ(std::string(to_string(ContactLength::current)), "current");
  EXPECT_EQ(std::string(to_string(ContactLength::initial)), "initial");
}

}  // namespace
}  // namespace sg
