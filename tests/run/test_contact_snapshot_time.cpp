// The contact network of a run (contacts/NNNNNN.vtu, run/run.cpp) describes the instant its
// snapshot is labelled with: every contact's slave point is where the fields snapshot of the
// same index (the state at that time) has that body's contour point, and its gap against the
// floor is that point's height above it. The first snapshot (t = 0) shows the contacts of the
// initial configuration, the last one those of the final state; a snapshot whose step the
// step control rolled back is taken again, not kept from the rejected trajectory.
// (Written before the step, the network showed the previous step's force evaluation: empty
// at t = 0, one step of travel behind the fields elsewhere.)
// The scenes write their .vtu as text (field_format = "ascii"), which this module (below the
// render stage and its reader) parses itself.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <regex>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include "geometry/vec2.h"
#include "run/run.h"
#include "scenario/scenario.h"
#include "scenes/scenario_files.h"
#include "scenes/tiny_scenario.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

// The folder of this test process, removed when the process ends (ctest runs every test in a
// process of its own: the folders would pile up in the temp directory).
fs::path temp_root() {
  struct RemovedAtExit {
    fs::path root;
    ~RemovedAtExit() {
      std::error_code ignored;
      fs::remove_all(root, ignored);
    }
  };
  static const RemovedAtExit folder{scenes::process_temp_dir("contact_snapshots")};
  return folder.root;
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  EXPECT_TRUE(in) << path;
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The numbers of the DataArray whose tag holds `marker` (Name="...") or, for a marker that
// is an element ("<Points>"), of the first DataArray in it, in a VTK XML file.
std::vector<double> data_array(const std::string& xml, const std::string& marker) {
  const std::size_t at = xml.find(marker);
  EXPECT_NE(at, std::string::npos) << marker;
  if (at == std::string::npos) return {};
  const std::size_t open = marker.front() == '<' ? xml.find("<DataArray", at) : at;
  const std::size_t begin = xml.find('>', open) + 1;
  const std::size_t end = xml.find("</DataArray>", begin);
  std::istringstream in(xml.substr(begin, end - begin));
  std::vector<double> values;
  double v = 0.0;
  while (in >> v)
    values.push_back(v);
  return values;
}

std::vector<Vec2> points_of(const std::vector<double>& xyz) {
  std::vector<Vec2> p;
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
    p.emplace_back(xyz[i], xyz[i + 1]);
  return p;
}

struct PvdEntry {
  double time = 0.0;
  std::string file;
};

std::vector<PvdEntry> read_pvd(const fs::path& path) {
  const std::string text = read_text(path);
  const std::regex entry("timestep=\"([^\"]+)\" part=\"0\" file=\"([^\"]+)\"");
  std::vector<PvdEntry> entries;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), entry);
       it != std::sregex_iterator(); ++it)
    entries.push_back({std::stod((*it)[1]), (*it)[2]});
  return entries;
}

struct ContactNetwork {
  std::vector<Vec2> position;
  std::vector<double> gap, slave, master;
};

ContactNetwork read_contacts(const fs::path& path) {
  const std::string xml = read_text(path);
  ContactNetwork c;
  c.position = points_of(data_array(xml, "<Points>"));
  c.gap = data_array(xml, "Name=\"gap\"");
  c.slave = data_array(xml, "Name=\"slave_body\"");
  c.master = data_array(xml, "Name=\"master_body\"");
  EXPECT_EQ(c.gap.size(), c.position.size()) << path;
  EXPECT_EQ(c.slave.size(), c.position.size()) << path;
  EXPECT_EQ(c.master.size(), c.position.size()) << path;
  return c;
}

struct FieldPoints {
  std::vector<Vec2> position;
  std::vector<double> body;
};

FieldPoints read_fields(const fs::path& path) {
  const std::string xml = read_text(path);
  FieldPoints f{points_of(data_array(xml, "Name=\"position\"")),
                data_array(xml, "Name=\"body_id\"")};
  EXPECT_EQ(f.body.size(), f.position.size()) << path;
  return f;
}

// Both files print 9 significant digits of the same computation (model/kinematics.h
// node_position and compute_contour_positions); coordinates here are below 10, so two prints
// of one point differ by at most a unit of the 9th digit. One step of travel is 1e-3 or more.
constexpr double kSamePoint = 2e-8;

// Distance from `p` to the nearest point of body `body` in the fields snapshot.
double distance_to_body(const FieldPoints& f, double body, const Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < f.position.size(); ++i)
    if (f.body[i] == body) best = std::min(best, (f.position[i] - p).norm());
  return best;
}

// The body whose points in `f` all lie in the floor's rectangle [-2, 2] x [-1, -0.5].
double floor_body(const FieldPoints& f) {
  for (double b = 0; b < 16; ++b) {
    bool any = false, inside = true;
    for (std::size_t i = 0; i < f.position.size(); ++i)
      if (f.body[i] == b) {
        any = true;
        const Vec2& p = f.position[i];
        inside =
            inside && std::abs(p.x()) <= 2.0 + 1e-9 && p.y() >= -1.0 - 1e-9 && p.y() <= -0.5 + 1e-9;
      }
    if (any && inside) return b;
  }
  ADD_FAILURE() << "no floor in the fields snapshot";
  return -1;
}

struct RunFolder {
  fs::path dir;
  std::vector<PvdEntry> fields, contacts;
  long steps = 0;
};

RunFolder run(const std::string& file, const std::string& text) {
  const ScenarioDef s = load_scenario(scenes::write_text_file(temp_root() / file, text));
  RunOptions options;
  options.output_root_override = temp_root() / "out";
  const RunSummary summary = run_scenario(s, options);
  EXPECT_TRUE(summary.completed);
  RunFolder r;
  r.dir = summary.directory;
  r.steps = summary.steps;
  r.fields = read_pvd(r.dir / "fields.pvd");
  r.contacts = read_pvd(r.dir / "contacts.pvd");
  return r;
}

// Checks every snapshot of `r`: the two indexes list the same files at the same, increasing
// times, and each contact is at its slave body's point in the fields snapshot of the same
// index, with its gap against the floor that point's height above it. Returns the number of
// contacts checked against a moving body (not the floor).
int expect_contacts_at_their_time(const RunFolder& r) {
  EXPECT_EQ(r.fields.size(), r.contacts.size());
  int moving = 0;
  for (std::size_t k = 0; k < std::min(r.fields.size(), r.contacts.size()); ++k) {
    char name[32];
    std::snprintf(name, sizeof name, "%06zu.vtu", k);
    EXPECT_EQ(r.fields[k].file, std::string("fields/") + name);
    EXPECT_EQ(r.contacts[k].file, std::string("contacts/") + name);
    EXPECT_EQ(r.contacts[k].time, r.fields[k].time) << name;
    if (k > 0) {
      EXPECT_GT(r.fields[k].time, r.fields[k - 1].time) << name;
    }
    const FieldPoints f = read_fields(r.dir / "fields" / name);
    const ContactNetwork c = read_contacts(r.dir / "contacts" / name);
    const double floor = floor_body(f);
    for (std::size_t i = 0; i < c.position.size(); ++i) {
      const Vec2& p = c.position[i];
      EXPECT_LE(distance_to_body(f, c.slave[i], p), kSamePoint)
          << name << " (t = " << r.fields[k].time << "): contact " << i << " of body " << c.slave[i]
          << " at (" << p.x() << ", " << p.y() << ")";
      if (c.master[i] == floor && std::abs(p.x()) < 1.9) {
        EXPECT_NEAR(c.gap[i], p.y() + 0.5, kSamePoint) << name << ": contact " << i;
      }
      if (c.slave[i] != floor) ++moving;
    }
  }
  return moving;
}

// The tiny scene (floor with top at y = -0.5, a soft disc thrown down from touching it, a
// rigid disc) and a rigid disc sliding along the floor, sunk 0.02 into it at t = 0.
std::string touching_scene() {
  return std::string(R"(
name = "touching"
[time]
duration = 0.1
[output]
series_period = 0.01
field_period = 0.03
field_format = "ascii"
)") + scenes::kTinyScenarioBody +
         R"(
[[grains]]
name = "sunk"
center = [-1.4, -0.12]
radius = 0.4
material = "hard"
rigid = true
velocity = [0.5, 0.0]
)";
}

TEST(ContactSnapshotTime, FirstSnapshotShowsTheInitialContacts) {
  const RunFolder r = run("touching.toml", touching_scene());
  ASSERT_GE(r.contacts.size(), 2u);
  EXPECT_EQ(r.contacts.front().time, 0.0);
  const ContactNetwork c = read_contacts(r.dir / "contacts" / "000000.vtu");
  const FieldPoints f = read_fields(r.dir / "fields" / "000000.vtu");
  ASSERT_FALSE(c.position.empty()) << "no contact at t = 0";
  // The sunk disc's lowest contour point is 0.02 - r (1 - cos(pi / n)) below the floor's top
  // (n contour points, about 17 at spacing 0.15): its contact has gap in [-0.02, -0.012].
  const double floor = floor_body(f);
  double deepest = 0.0;
  for (std::size_t i = 0; i < c.position.size(); ++i)
    if (c.master[i] == floor) deepest = std::min(deepest, c.gap[i]);
  EXPECT_LE(deepest, -0.012);
  EXPECT_GE(deepest, -0.02 - 1e-9);
  EXPECT_GT(expect_contacts_at_their_time(r), 0);
}

TEST(ContactSnapshotTime, EverySnapshotShowsTheStateOfItsTimeLabel) {
  const RunFolder r = run("touching_all.toml", touching_scene());
  // t = 0, 0.03, 0.06, 0.09 and the end of the run (the first step time at or after 0.1).
  ASSERT_EQ(r.fields.size(), 5u);
  EXPECT_GE(r.fields.back().time, 0.1 - 1e-12);
  EXPECT_GT(expect_contacts_at_their_time(r), 0);
  // The last snapshot too has contacts of moving bodies (the sunk disc still slides on the
  // floor), evaluated at the final state.
  const ContactNetwork last = read_contacts(r.dir / "contacts" / "000004.vtu");
  const FieldPoints f = read_fields(r.dir / "fields" / "000004.vtu");
  const double floor = floor_body(f);
  int on_floor = 0;
  for (std::size_t i = 0; i < last.position.size(); ++i)
    on_floor += last.master[i] == floor && last.slave[i] != floor;
  EXPECT_GT(on_floor, 0);
}

TEST(ContactSnapshotTime, SnapshotOfARolledBackStepIsTakenAgain) {
  // The periodic seam scene of test_checkpoint_restart.cpp with its one rejected step (energy
  // check at tolerance 0.0006: the collision at t = 0.1057 is rolled back with the step
  // before it and retried at half), and a snapshot at every step (field_period < dt). The
  // snapshot of the state the rejection discarded is not kept: one snapshot per state of the
  // run's trajectory plus the final one, at increasing times, each at its own instant.
  const std::string text = std::string(R"(
name = "seam"
[time]
duration = 0.2
step_tolerance = 0.0006
[output]
series_period = 0.002
field_period = 0.001
field_format = "ascii"
checkpoint_period = 0
)") + scenes::kTinyScenarioBody +
                           scenes::kSeamGrains;
  const RunFolder r = run("seam.toml", text);
  const std::string log = read_text(r.dir / "run.log");
  ASSERT_NE(log.find(" 1 rejected"), std::string::npos) << log;
  EXPECT_EQ(static_cast<long>(r.fields.size()), r.steps + 1);
  EXPECT_GT(expect_contacts_at_their_time(r), 0);
}

}  // namespace
}  // namespace sg
