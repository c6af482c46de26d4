// The contact-level strain rate (io/contact_rate.h) in contacts/*.vtu and on the outlines of
// `render --field strain_rate` (render/contact_outlines.h): two grains sliding past each other
// rigidly, the velocity jump all at their contacts and none inside them.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <vector>

#include "contact/contact_system.h"
#include "io/contact_rate.h"
#include "io/contact_vtk.h"
#include "io/vtk_writer.h"
#include "model/kinematics.h"
#include "render/colormap.h"
#include "render/png_reader.h"
#include "render/snapshot_renderer.h"
#include "render/vtu_reader.h"
#include "scenes/contact_scenes.h"
#include "scenes/free_grains.h"
#include "scenes/scenario_files.h"

namespace sg {
namespace {

namespace fs = std::filesystem;

// Two soft blocks: the lower one [0, 1] x [-0.5, 0], the upper one [0.25, 0.75] x [-d, 0.5 - d]
// pressed d = 0.01 into it (contour spacing h = 0.1 on both; the upper block's sides are half a
// spacing off the lower block's nodes, so every penetrating point projects on the facing
// face, normal +-y). The pair turns rigidly at omega about (0.5, 0) while the upper block
// slides at +V/2 and the lower at -V/2 relative to that rotation.
struct SlidingBlocks {
  static constexpr double h = 0.1, d = 0.01, V = 0.8, omega = 0.3;
  static constexpr double global = 0.25;  // V/D of a cell (the unit of the rates)
  Model model;
  BodyId lower = 0, upper = 0;
  std::unique_ptr<ContactSystem> contacts;

  SlidingBlocks() {
    const MaterialId m = model.add_material(scenes::elastic_material());
    lower = model.add_deformable_body("lower", make_rectangle(Vec2(0, -0.5), Vec2(1, 0), h), m,
                                      scenes::discretization(h));
    upper =
        model.add_deformable_body("upper", make_rectangle(Vec2(0.25, -d), Vec2(0.75, 0.5 - d), h),
                                  m, scenes::discretization(h));
    const Vec2 pivot(0.5, 0.0);
    for (const auto& [body, slide] : {std::pair(lower, -0.5 * V), std::pair(upper, 0.5 * V)}) {
      // v(x) = (slide, 0) + omega perp(x - pivot) on the whole body (u = 0: positions = X).
      const Vec2 c = reference_mass_centroid(model, body);
      set_rigid_velocity(model, body, Vec2(slide, 0.0) + omega * perp(c - pivot), omega);
    }
    ContactLawParams law;
    law.kind = ContactLawKind::frictionless;
    law.normal_stiffness = 1000.0;
    ContactSettings settings;
    settings.cutoff = 0.5 * h;
    contacts = std::make_unique<ContactSystem>(model, scenes::single_law(model, law), settings);
    contacts->add_contact_forces(model);
  }

  // The contour points inside the other block: the lower block's top face under the upper
  // block, and the upper block's bottom face.
  std::set<int> penetrating_points() const {
    std::vector<Vec2> x;
    compute_contour_positions(model, x);
    std::set<int> out;
    for (int k = 0; k < static_cast<int>(x.size()); ++k) {
      const Vec2& p = x[static_cast<std::size_t>(k)];
      const bool on_lower = model.contour_body[static_cast<std::size_t>(k)] == lower;
      if (on_lower ? (p.y() == 0.0 && p.x() > 0.25 && p.x() < 0.75) : std::abs(p.y() + d) < 1e-15)
        out.insert(k);
    }
    return out;
  }

  // Tributary length of contour point k: half of its two segments along its block's contour.
  double tributary(int k) const {
    std::vector<Vec2> x;
    compute_contour_positions(model, x);
    const Body& b = model.body(model.contour_body[static_cast<std::size_t>(k)]);
    const int n = b.contour_count(), i = k - b.contour_begin;
    const Vec2& p = x[static_cast<std::size_t>(k)];
    const Vec2& prev = x[static_cast<std::size_t>(b.contour_begin + (i + n - 1) % n)];
    const Vec2& next = x[static_cast<std::size_t>(b.contour_begin + (i + 1) % n)];
    return 0.5 * ((p - prev).norm() + (next - p).norm());
  }

  // A run folder holding this instant as snapshot 000000: fields, contacts, fields.pvd.
  fs::path write_run_folder(const fs::path& dir) const {
    fs::remove_all(dir);
    fs::create_directories(dir / "fields");
    fs::create_directories(dir / "contacts");
    write_vtu_snapshot(model, dir / "fields" / "000000.vtu", global);
    std::vector<Vec2> v;
    compute_contour_velocities(model, v);
    write_contact_snapshot(*contacts, model, v, global, dir / "contacts" / "000000.vtu");
    PvdCollection(dir / "fields.pvd").add(0.0, "fields/000000.vtu");
    return dir;
  }
};

// The slip at every contact is V + omega d (the rotation adds omega times the distance d
// between the slave point and its projection), with no opening: |D| = slip / sqrt(2) / l, l
// the slave point's tributary length, over V/D. Inside the blocks: no strain rate at all.
TEST(ContactRate, GrainsSlidingRigidlyGiveTheAnalyticRateAtContactsAndNoneInside) {
  const SlidingBlocks s;
  const fs::path dir = s.write_run_folder(scenes::process_temp_dir("contact_rate") / "run");
  const VtuMesh contacts = read_vtu(dir / "contacts" / "000000.vtu");
  const std::vector<double> rate = point_scalar(contacts, "contact_rate");
  const std::vector<double> slave = point_scalar(contacts, "slave_body");
  const std::vector<double> point = point_scalar(contacts, "field_point");
  const VtuArray* dv = contacts.find("relative_velocity");
  ASSERT_NE(dv, nullptr);
  // Every contact is a penetrating point, each once (one master body each).
  std::set<int> slaves;
  for (const ContactRecord& r : s.contacts->records())
    slaves.insert(r.slave_point);
  EXPECT_EQ(slaves, s.penetrating_points());
  ASSERT_EQ(rate.size(), s.contacts->records().size());
  ASSERT_EQ(rate.size(), 11u);  // 5 points of the lower face, 6 of the upper
  const double slip = SlidingBlocks::V + SlidingBlocks::omega * SlidingBlocks::d;
  const VtuMesh fields = read_vtu(dir / "fields" / "000000.vtu");
  for (std::size_t i = 0; i < rate.size(); ++i) {
    const ContactRecord& r = s.contacts->records()[i];
    const double expected =
        slip / std::sqrt(2.0) / s.tributary(r.slave_point) / SlidingBlocks::global;
    EXPECT_NEAR(rate[i], expected, 1e-7 * expected) << "contact " << i;
    // Slave minus master: the lower block moves at -V relative to the upper one.
    const double sign = static_cast<int>(slave[i]) == s.lower ? -1.0 : 1.0;
    EXPECT_NEAR(dv->values[3 * i], sign * slip, 1e-7) << "contact " << i;
    EXPECT_NEAR(dv->values[3 * i + 1], 0.0, 1e-7) << "contact " << i;
    // field_point names the slave point in the field snapshot.
    const Vec2& at = fields.points[static_cast<std::size_t>(point[i])];
    EXPECT_NEAR((at - contacts.points[i]).norm(), 0.0, 1e-8) << "contact " << i;
  }
  for (const char* field : {"strain_rate", "strain_rate_instant"})
    for (const double v : point_scalar(fields, field))
      ASSERT_NEAR(v, 0.0, 1e-9) << field;
}

// Pixels of the picture's drawing area (left of the colour bar) within 3 of `c` per channel.
int pixels_of_colour(const PngPixels& png, const Rgb& c) {
  const auto channel = [](std::uint32_t v, int shift) {
    return static_cast<int>((v >> shift) & 0xff);
  };
  int n = 0;
  for (int y = 0; y < png.height; ++y)
    for (int x = 0; x < png.width * 3 / 4; ++x) {
      const std::uint32_t v = png.at(x, y);
      n += std::abs(channel(v, 16) - std::lround(255 * c.r)) <= 3 &&
           std::abs(channel(v, 8) - std::lround(255 * c.g)) <= 3 &&
           std::abs(channel(v, 0) - std::lround(255 * c.b)) <= 3;
    }
  return n;
}

// The strain-rate picture of the sliding blocks: the grains in the bottom colour (no strain
// rate), their outlines at the contacts in the colour of the contact rate; the contact rates
// set the top of the colour range. Without contacts/ no outline takes that colour.
TEST(ContactRate, StrainRatePicturesColourTheOutlinesAtContacts) {
  const SlidingBlocks s;
  const fs::path dir = s.write_run_folder(scenes::process_temp_dir("contact_rate") / "picture");
  double highest = 0.0;
  for (const double v : point_scalar(read_vtu(dir / "contacts" / "000000.vtu"), "contact_rate"))
    highest = std::max(highest, v);
  RenderOptions o;
  o.field = "strain_rate";
  o.width = 400;
  o.height = 300;
  o.movie = false;
  const RenderResult r = render_run(dir, o);
  ASSERT_EQ(r.images.size(), 1u);
  EXPECT_NEAR(r.range_min, 0.0, 1e-9);  // the grains: round-off of a rigid motion
  EXPECT_EQ(r.range_max, highest);      // the contacts' rates, not the grains' zero
  const Rgb top = viridis(1.0);
  const int coloured = pixels_of_colour(png_pixels(r.images[0]), top);
  // 11 contact points, two half-edges each, ~12 px long and 3 px wide at this size.
  EXPECT_GT(coloured, 200);
  fs::remove(dir / "contacts" / "000000.vtu");
  o.range = std::make_pair(0.0, highest);
  const RenderResult without = render_run(dir, o);
  EXPECT_EQ(pixels_of_colour(png_pixels(without.images[0]), top), 0);
}

}  // namespace
}  // namespace sg
