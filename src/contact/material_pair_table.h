#pragma once
// Which contact law acts between two materials: a symmetric table material x material ->
// ContactLawParams, filled once from the scenario (cold data), looked up per contact pair.
//
// Materials are small integer ids (0 .. count-1, indices into the scenario's material list)
// with names for messages. Lookup is O(1) in a flat n x n slot array; names and strings are
// only touched on the error path, so `at` may be called inside the contact loop.
// A class rather than a plain struct: it keeps the symmetric slot array, the law list and the
// names consistent (a pair is set once, both orders map to one law).
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "contact/contact_law.h"

namespace sg {

class MaterialPairTable {
 public:
  // Material names, unique and non-empty; their positions are the material ids.
  explicit MaterialPairTable(std::vector<std::string> material_names);

  int material_count() const { return static_cast<int>(names_.size()); }
  const std::string& material_name(int material) const;
  // Id of a material by name; throws sg::Error "unknown material 'x' (known: a, b)".
  int find_material(std::string_view name) const;

  // Sets the law of the unordered pair {a, b} (a == b: contacts within one material).
  // Validates `params` with the context "contact law for materials 'a' and 'b'"; throws if
  // the pair already has a law (a scenario naming a pair twice is a mistake).
  void set(int a, int b, const ContactLawParams& params);
  void set(std::string_view a, std::string_view b, const ContactLawParams& params);

  bool has(int a, int b) const;
  // The law of {a, b}; throws sg::Error "no contact law for materials 'a' and 'b'".
  const ContactLawParams& at(int a, int b) const;

  // Throws, naming the first missing pair (in id order), unless every pair of materials in
  // `materials` (with repetitions allowed, e.g. the material of each body) has a law: the
  // check to run once before a simulation starts, so that `at` never fails in a step.
  void verify_covers(std::span<const int> materials) const;

  // The same table with every law replaced by per_pass_params(law): what the two-pass
  // node-to-segment loop evaluates (contact_law.h).
  MaterialPairTable per_pass() const;

 private:
  std::vector<std::string> names_;
  std::vector<int> slot_;  // n x n, symmetric: index into laws_, or -1 when no law
  std::vector<ContactLawParams> laws_;
  void check_id(int material) const;
};

}  // namespace sg
