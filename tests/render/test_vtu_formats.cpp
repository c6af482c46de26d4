// The two encodings of the .vtu files (io/vtu_document.h): one run written with [output]
// field_format = "binary" (the default) and one with "ascii" hold the same snapshots, and
// softgrain's reader (render/vtu_reader.h) gives back identical arrays, bit for bit, for every
// field and contact snapshot. Identical, not close: the text is the shortest decimal that
// reads back to the same double, so a lossy text (9 significant digits, as before binary)
// fails here. The run is fine enough (about 2,000 nodes) that the larger arrays span several
// 32 KiB compression blocks. VTK's own reader is checked on both by python/tests
// (test_vtu_formats.py).
#include <gtest/gtest.h>

#include <omp.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.h"
#include "render/vtu_reader.h"
#include "run/run.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "scenes/tiny_scenario.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The tiny scene (a soft disc thrown on a floor beside a rigid disc: triangles, polygons and
// contacts), at spacing 0.02, in the given encoding; returns its run folder.
fs::path run_in(const std::string& format) {
  const fs::path root = scenes::process_temp_dir("vtu_" + format);
  std::string body = scenes::kTinyScenarioBody;
  body.replace(body.find("node_spacing = 0.15"), 19, "node_spacing = 0.02");
  const std::string text =
      "name = \"tiny\"\n[time]\nduration = 0.02\n[output]\n"
      "series_period = 0.002\nfield_period = 0.01\nfield_format = \"" +
      format + "\"\n" + body;
  const fs::path scenario = scenes::write_text_file(root / "tiny.toml", text);
  RunOptions options;
  options.output_root_override = root / "out";
  omp_set_num_threads(1);
  return run_scenario(load_scenario(scenario), options).directory;
}

class VtuFormats : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    binary_ = new fs::path(run_in("binary"));
    ascii_ = new fs::path(run_in("ascii"));
  }
  static void TearDownTestSuite() {
    delete binary_;
    delete ascii_;
  }
  static fs::path* binary_;
  static fs::path* ascii_;
};
fs::path* VtuFormats::binary_ = nullptr;
fs::path* VtuFormats::ascii_ = nullptr;

void expect_identical(const VtuMesh& a, const VtuMesh& b) {
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t p = 0; p < a.points.size(); ++p)
    ASSERT_EQ(a.points[p], b.points[p]) << a.path << " point " << p;
  EXPECT_EQ(a.connectivity, b.connectivity);
  EXPECT_EQ(a.offsets, b.offsets);
  EXPECT_EQ(a.types, b.types);
  ASSERT_EQ(a.point_data.size(), b.point_data.size());
  for (std::size_t k = 0; k < a.point_data.size(); ++k) {
    EXPECT_EQ(a.point_data[k].name, b.point_data[k].name);
    EXPECT_EQ(a.point_data[k].components, b.point_data[k].components);
    // Exact equality of every double (no NaN is written).
    EXPECT_EQ(a.point_data[k].values, b.point_data[k].values) << a.point_data[k].name;
  }
}

TEST_F(VtuFormats, BinaryAndAsciiRunsReadBackToIdenticalArrays) {
  for (const char* collection : {"fields.pvd", "contacts.pvd"}) {
    const std::vector<PvdEntry> binary = read_pvd(*binary_ / collection);
    const std::vector<PvdEntry> ascii = read_pvd(*ascii_ / collection);
    ASSERT_EQ(binary.size(), 3u) << collection;  // t = 0, 0.01 and the end
    ASSERT_EQ(binary.size(), ascii.size());
    std::size_t nonempty = 0;  // contacts: none at t = 0, some once the disc lands
    for (std::size_t i = 0; i < binary.size(); ++i) {
      EXPECT_EQ(binary[i].time, ascii[i].time);
      const std::string bytes = read_bytes(binary[i].file);
      EXPECT_NE(bytes.find("format=\"appended\""), std::string::npos) << binary[i].file;
      EXPECT_EQ(read_bytes(ascii[i].file).find("<AppendedData"), std::string::npos);
      const VtuMesh b = read_vtu(binary[i].file);
      const VtuMesh a = read_vtu(ascii[i].file);
      nonempty += !b.points.empty();
      expect_identical(b, a);
    }
    EXPECT_GT(nonempty, 0u) << collection;
  }
  const VtuMesh last = read_vtu(read_pvd(*binary_ / "fields.pvd").back().file);
  EXPECT_GT(last.points.size() * 3 * sizeof(double), 2u * 32768u);  // several blocks
  // The encoding changes no result.
  EXPECT_EQ(read_bytes(*binary_ / "series.csv"), read_bytes(*ascii_ / "series.csv"));
}

TEST_F(VtuFormats, BinaryFieldsAreSeveralTimesSmaller) {
  const fs::path b = read_pvd(*binary_ / "fields.pvd").back().file;
  const fs::path a = read_pvd(*ascii_ / "fields.pvd").back().file;
  EXPECT_LT(3 * fs::file_size(b), fs::file_size(a))
      << fs::file_size(b) << " vs " << fs::file_size(a);
}

// A binary file cut short, or with a corrupted block, is refused naming the file.
TEST_F(VtuFormats, ADamagedBinaryFileIsRefusedNamingIt) {
  const std::string bytes = read_bytes(read_pvd(*binary_ / "fields.pvd").back().file);
  const fs::path dir = scenes::process_temp_dir("vtu_damaged");
  const fs::path cut = dir / "cut.vtu";
  std::ofstream(cut, std::ios::binary) << bytes.substr(0, bytes.size() / 2) << "</VTKFile>\n";
  const fs::path corrupt = dir / "corrupt.vtu";
  std::string flipped = bytes;
  const auto data = flipped.find('_', flipped.find("<AppendedData")) + 1;
  for (std::size_t k = 0; k < 16; ++k)  // inside the first array's first zlib block
    flipped[data + 40 + k] = static_cast<char>(~flipped[data + 40 + k]);
  std::ofstream(corrupt, std::ios::binary) << flipped;
  for (const fs::path& file : {cut, corrupt}) {
    try {
      read_vtu(file);
      ADD_FAILURE() << file << " was read";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(file.filename().string()), std::string::npos)
          << e.what();
    }
  }
}

TEST(VtuFormatKey, AnUnknownFormatIsRefusedNamingTheKey) {
  const fs::path dir = scenes::process_temp_dir("vtu_key");
  const std::string text =
      "name = \"tiny\"\n[time]\nduration = 0.02\n[output]\n"
      "field_format = \"hdf5\"\n" +
      std::string(scenes::kTinyScenarioBody);
  try {
    load_scenario(scenes::write_text_file(dir / "bad.toml", text));
    ADD_FAILURE() << "field_format = \"hdf5\" was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("field_format"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("bad.toml"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace sg
