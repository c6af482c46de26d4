// [[contact_laws]] (scenario/contact_law_def.h): the keys of every law are read into its
// coefficients; a key of another law, a missing one or a value out of range is one error
// naming the file, the line and the key.
#include <gtest/gtest.h>

#include <string>

#include "contact/law_coefficients.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "scenes/tiny_scenario.h"

namespace sg {
namespace {

const std::string kTiny = std::string(R"(
name = "tiny"
[time]
duration = 0.05
)") + scenes::kTinyScenarioBody;

// The tiny scene with its first law (soft / hard, coulomb) replaced by `law`.
std::string with_law(const std::string& law) {
  return scenes::replace_once(kTiny, "law = \"coulomb\"\nnormal_stiffness = 1000.0\nfriction = 0.3",
                              law);
}

std::string error_of(const std::string& text) {
  return scenes::scenario_error(scenes::process_temp_dir("contact_law_def"), text);
}

ContactLawParams first_law(const std::string& text) {
  const auto file =
      scenes::write_text_file(scenes::process_temp_dir("contact_law_def") / "good.toml", text);
  return load_scenario(file).contact_laws.at(0).params;
}

TEST(ContactLawDef, ReadsTheKeysOfEachLaw) {
  const ContactLawParams bonded = first_law(with_law(R"(law = "bonded"
normal_stiffness = 1000.0
bond_normal_stiffness = 500.0
bond_tensile_strength = 0.4
bond_shear_strength = 0.3
bond_friction = 0.2
friction = 0.1
adhesion = 0.05
bond_gap = 0.02
damping_ratio = 0.1
length = "initial")"));
  EXPECT_EQ(bonded.kind, ContactLawKind::bonded);
  EXPECT_EQ(bonded.tangential_stiffness, 1000.0);  // default k_n
  EXPECT_EQ(bonded.bond_normal_stiffness, 500.0);
  EXPECT_EQ(bonded.bond_tensile_strength, 0.4);
  EXPECT_EQ(bonded.bond_shear_strength, 0.3);
  EXPECT_EQ(bonded.bond_friction, 0.2);
  EXPECT_EQ(bonded.friction, 0.1);
  EXPECT_EQ(bonded.adhesion, 0.05);
  EXPECT_EQ(bonded.bond_gap, 0.02);
  EXPECT_EQ(bonded.damping_ratio, 0.1);
  EXPECT_EQ(bonded.length, ContactLength::initial);

  const ContactLawParams zone = first_law(with_law(R"(law = "cohesive_zone"
normal_stiffness = 1000.0
peak_traction = 1.0
critical_opening = 0.02
residual_traction = 0.1
mixed_mode_ratio = 0.5)"));
  EXPECT_EQ(zone.kind, ContactLawKind::cohesive_zone);
  EXPECT_EQ(zone.tangential_stiffness, 1000.0);
  EXPECT_EQ(zone.peak_traction, 1.0);
  EXPECT_EQ(zone.critical_opening, 0.02);
  EXPECT_EQ(zone.residual_traction, 0.1);
  EXPECT_EQ(zone.mixed_mode_ratio, 0.5);
  EXPECT_EQ(zone.length, ContactLength::current);

  const ContactLawParams slope =
      first_law(with_law("law = \"two_slope\"\nnormal_stiffness = 1000.0\nunloading_ratio = 0.5"));
  EXPECT_EQ(slope.unloading_ratio, 0.5);
}

TEST(ContactLawDef, ErrorsNameFileLineAndKey) {
  struct Case {
    std::string law, expected;
  };
  const Case cases[] = {
      {"law = \"coulomb\"\nnormal_stiffness = 1000.0\nunloading_ratio = 0.5",
       "key 'contact_laws[0].unloading_ratio': applies only to law = \"two_slope\""},
      {"law = \"cohesive_zone\"\nnormal_stiffness = 1000.0\ncritical_opening = 0.02",
       "key 'contact_laws[0].peak_traction': required number is missing"},
      {"law = \"cohesive_zone\"\nnormal_stiffness = 1000.0\ntangential_stiffness = 9.0\n"
       "peak_traction = 1.0\ncritical_opening = 0.02",
       "key 'contact_laws[0].tangential_stiffness': applies only to law"},
      {"law = \"cohesive_zone\"\nnormal_stiffness = 1000.0\npeak_traction = 100.0\n"
       "critical_opening = 0.02",
       "critical_opening 0.02 must exceed the elastic limit"},
      {"law = \"two_slope\"\nnormal_stiffness = 1000.0\nunloading_ratio = 2.0",
       "unloading_ratio must be in (0, 1]"},
      {"law = \"coulomb\"\nnormal_stiffness = 1000.0\ndamping_ratio = 1.5",
       "damping_ratio must be < 1"},
      {"law = \"coulomb\"\nnormal_stiffness = 1000.0\nlength = \"fixed\"",
       "key 'contact_laws[0].length': expected one of"},
  };
  for (const Case& c : cases) {
    const std::string what = error_of(with_law(c.law));
    EXPECT_NE(what.find(c.expected), std::string::npos) << "got: " << what;
    EXPECT_NE(what.find("bad.toml:"), std::string::npos) << "got: " << what;
  }
}

}  // namespace
}  // namespace sg

namespace sg {
namespace {

// A minimal valid law of each kind, as a scenario writes it (cohesive_zone needs its two
// required coefficients).
std::string minimal_law(ContactLawKind kind) {
  std::string text =
      std::string("law = \"") + contact_law_kind_name(kind) + "\"\nnormal_stiffness = 1000.0";
  if (kind == ContactLawKind::cohesive_zone)
    text += "\npeak_traction = 1.0\ncritical_opening = 0.1";
  return text;
}

// The value a law takes for `c` when the key is absent: valid for every law that uses it.
double value_when_absent(const LawCoefficient& c, const ContactLawParams& read) {
  return c.fallback_member ? read.*c.fallback_member : c.fallback;
}

// The shared table (contact/law_coefficients.h) is what the reader accepts: every row's key
// is read into its member for each law that uses it, and refused for every other law with the
// names of the laws that use it. A row added to the table is covered here without a new test.
TEST(ContactLawDef, TheSharedCoefficientTableIsWhatTheReaderAccepts) {
  const ContactLawKind kinds[] = {ContactLawKind::frictionless, ContactLawKind::coulomb,
                                  ContactLawKind::cohesive,     ContactLawKind::two_slope,
                                  ContactLawKind::bonded,       ContactLawKind::cohesive_zone};
  ASSERT_FALSE(law_coefficients().empty());
  for (const ContactLawKind kind : kinds) {
    const std::string base = minimal_law(kind);
    const ContactLawParams defaults = first_law(with_law(base));
    for (const LawCoefficient& c : law_coefficients()) {
      SCOPED_TRACE(std::string(c.key) + " on a " + contact_law_kind_name(kind) + " law");
      if (base.find(std::string(c.key) + " =") != std::string::npos) continue;  // required
      if (is_used_by(c, kind)) {
        // A value other than the default, within the bounds of every row: it must arrive.
        const double value = value_when_absent(c, defaults) == 0.5 ? 0.25 : 0.5;
        const ContactLawParams read =
            first_law(with_law(base + "\n" + c.key + " = " + std::to_string(value)));
        EXPECT_EQ(read.*c.member, value);
        EXPECT_EQ(defaults.*c.member, value_when_absent(c, defaults));
      } else {
        const std::string what =
            error_of(with_law(base + "\n" + c.key + " = " + std::to_string(c.unused_value)));
        EXPECT_NE(what.find(std::string("contact_laws[0].") + c.key + "'"), std::string::npos)
            << what;
        EXPECT_NE(what.find("applies only to law = " + names_of_laws_using(c)), std::string::npos)
            << what;
        EXPECT_EQ(defaults.*c.member, c.unused_value);
      }
    }
  }
  // A key in no row and read by no law is unknown.
  const std::string unknown =
      error_of(with_law(minimal_law(ContactLawKind::bonded) + "\nbond_fatigue_limit = 0.5"));
  EXPECT_NE(unknown.find("contact_laws[0].bond_fatigue_limit'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("unknown key"), std::string::npos) << unknown;
}

}  // namespace
}  // namespace sg
