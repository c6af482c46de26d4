// [[strips]] of a scenario file, and the surface profiles of strips and of the shear cell's
// first bodies (scenario_readers.h).
#include <string>

#include "core/error.h"
#include "scenario/csv_table.h"
#include "scenario/motion_limits.h"
#include "scenario/scenario_readers.h"

namespace sg {

namespace {

// The (x, y) points of a profile: inline `points` or a CSV `file` (columns x, y).
std::vector<Vec2> read_profile_points(const TomlReader& t, std::string& source) {
  if (t.has("points") == t.has("file"))
    t.fail("points",
           "kind = \"points\" needs exactly one of points = [[x, y], ...] or "
           "file = \"profile.csv\"");
  if (t.has("points")) {
    source = t.file().string() + ", key points";
    return t.pairs("points", 2);
  }
  const std::filesystem::path path = t.file_path("file");
  source = path.string();
  const CsvTable csv(path, {"x", "y"}, {"x", "y"});
  std::vector<Vec2> points;
  for (const CsvTable::Row& row : csv.rows()) {
    const double x = csv.number(row, "x");  // x first: the message names the first bad cell
    points.emplace_back(x, csv.number(row, "y"));
  }
  return points;
}

}  // namespace

void check_profile(const TomlReader& t, const SurfaceProfileDef& profile, double x_begin,
                   double period) {
  try {
    sample_profile(profile, x_begin, period, period, "profile");  // validity only
  } catch (const Error& e) {
    t.fail("kind", e.what());
  }
}

SurfaceProfileDef read_profile(const TomlReader& t, const SurfaceProfileDef& defaults) {
  t.reject_unknown_keys({"kind", "rms", "hurst", "seed", "modes", "points", "file"});
  SurfaceProfileDef p = defaults;
  const std::string kind = t.one_of("kind", {"self_affine", "sines", "points"}, "self_affine");
  p.kind = kind == "self_affine" ? ProfileKind::self_affine
           : kind == "sines"     ? ProfileKind::sines
                                 : ProfileKind::points;
  auto only_for = [&](std::initializer_list<const char*> keys, const char* which) {
    for (const char* key : keys)
      if (t.has(key)) t.fail(key, std::string("applies only to kind = \"") + which + "\"");
  };
  if (p.kind != ProfileKind::self_affine) only_for({"rms", "hurst", "seed"}, "self_affine");
  if (p.kind != ProfileKind::sines) only_for({"modes"}, "sines");
  if (p.kind != ProfileKind::points) only_for({"points", "file"}, "points");
  if (p.kind == ProfileKind::self_affine) {
    p.rms = t.non_negative("rms", p.rms);
    p.hurst = t.number("hurst", p.hurst);
    if (!(p.hurst > 0 && p.hurst < 1)) t.fail("hurst", "expected a number in (0, 1)");
    const long seed = t.integer("seed", static_cast<long>(p.seed));
    if (seed < 0) t.fail("seed", "expected an integer >= 0");
    p.seed = static_cast<std::uint64_t>(seed);
  } else if (p.kind == ProfileKind::sines) {
    for (const TomlReader& m : t.array_of_tables("modes")) {
      m.reject_unknown_keys({"amplitude", "wavelength", "phase"});
      p.modes.push_back({m.number("amplitude"), m.positive("wavelength"), m.number("phase", 0.0)});
    }
    if (p.modes.empty()) t.fail("modes", "kind = \"sines\" needs at least one [[...modes]] table");
  } else {
    p.points = read_profile_points(t, p.source);
  }
  return p;
}

void read_strips(const TomlReader& root, ScenarioDef& s,
                 const std::set<std::string>& material_names, std::set<std::string>& body_names) {
  const std::vector<TomlReader> strips = root.array_of_tables("strips");
  for (std::size_t i = 0; i < strips.size(); ++i) {
    const TomlReader& t = strips[i];
    t.reject_unknown_keys({"name", "material", "rigid", "surface_y", "back_y", "profile", "drive"});
    if (!s.periodic_x)
      t.fail("name", "a strip spans the periodic cell: [periodic] (x_min, x_max) is required");
    StripDef d;
    d.name = t.string("name", "strip_" + std::to_string(i));
    d.material = t.string("material");
    if (!material_names.count(d.material))
      t.fail("material", "unknown material '" + d.material + "'");
    if (!body_names.insert(d.name).second)
      t.fail("name", "body name '" + d.name + "' is used twice");
    d.rigid = t.boolean("rigid", true);
    d.spacing = material_spacing(s, d.material);
    d.surface_y = t.number("surface_y");
    d.back_y = t.number("back_y");
    if (d.back_y == d.surface_y)
      t.fail("back_y", "expected a back face below (strip under the gap) or above surface_y");
    if (auto p = t.table("profile")) {
      d.profile = read_profile(*p, SurfaceProfileDef{});
      check_profile(*p, d.profile, s.x_min, s.x_max - s.x_min);
    } else {
      t.fail("profile", "required table [strips.profile] is missing");
    }
    if (auto dt = t.table("drive")) {
      d.drive = read_drive(*dt, false, true);
      TravelLimit(s).check_drive(*dt, d.drive, "strip '" + d.name + "'");
    }
    s.strips.push_back(d);
  }
}

}  // namespace sg
