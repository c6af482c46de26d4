#pragma once
// A scenario of the fuzzer's own that points to a contour file and a profile file (issue #26,
// item 2): no example does (only shear-cell-explicit.toml names a grains file), so without it
// their CSV readers would never see a mutated cell. Its CSV files are mutated like an
// example's (fuzz/mutations.h, csv_mutations_of); the scenario itself is not.
#include <string>
#include <vector>

namespace sg::fuzz {

struct SeedFile {
  std::string name, text;
};

// The scenario (first: csv-seed.toml, a contour grain over a strip with a points profile,
// two steps a few milliseconds each) and the CSV files it names.
std::vector<SeedFile> csv_seed_files();

}  // namespace sg::fuzz
