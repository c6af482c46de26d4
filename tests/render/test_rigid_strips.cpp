// Rigid bodies in a periodic picture (render/frame_drawing.cpp): a first body spanning the
// period is written as its open surface (model/model.h Body::open_contour); the picture fills
// it from the surface out to its back on the body's side, across the seam, and a closed rigid
// body crossing the seam is drawn whole. Drawn here from made-up snapshots, read pixel by
// pixel. (Before: the surface was closed by a chord from its last point to its first, so only
// the slivers between the chord and the surface were filled, with a notch at the seam.)
#include <gtest/gtest.h>

#include <cairo.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "picture_checks.h"
#include "render/frame_drawing.h"
#include "render/picture_layout.h"
#include "render/vtu_reader.h"

namespace sg {
namespace {

constexpr double kPeriod = 4.0;
const Rgb kRigidGrey{0.78, 0.78, 0.78};

// A snapshot of rigid polygons only, their points in the order given.
struct Snapshot {
  VtuMesh mesh;
  void add_polygon(const std::vector<Vec2>& points) {
    for (const Vec2& p : points) {
      mesh.connectivity.push_back(static_cast<int>(mesh.points.size()));
      mesh.points.push_back(p);
    }
    mesh.offsets.push_back(static_cast<int>(mesh.connectivity.size()));
    mesh.types.push_back(kVtkPolygon);
    const std::vector<double> zeros(mesh.points.size(), 0.0);
    mesh.point_data = {VtuArray{"von_mises", 1, zeros}, VtuArray{"body_id", 1, zeros}};
  }
};

// A rough surface over one period from x_start, `n` points `step` apart in x (step < 0: the
// surface is written towards -x), the last one a step short of the period (an open contour).
std::vector<Vec2> surface(double x_start, double step, double y_mean, int n) {
  std::vector<Vec2> points;
  for (int k = 0; k < n; ++k) {
    const double x = x_start + k * step;
    points.emplace_back(x, y_mean + 0.1 * std::sin(2.0 * std::numbers::pi * x / kPeriod));
  }
  return points;
}

// The picture of `snapshot` over the world [0, kPeriod] x [-2, 2], periodic.
class Picture {
 public:
  explicit Picture(const Snapshot& snapshot)
      : layout_(make_layout(400, 400, BoundingBox{Vec2(0, -2), Vec2(kPeriod, 2)}, false, true)),
        surface_(cairo_image_surface_create(CAIRO_FORMAT_RGB24, 400, 400)) {
    cairo_t* cr = cairo_create(surface_);
    cairo_set_source_rgb(cr, 1, 1, 1);
    cairo_paint(cr);
    Style style;
    style.field = "von_mises";
    style.periodic = std::make_pair(0.0, kPeriod);
    Frame frame;
    frame.mesh = &snapshot.mesh;
    draw_frame(cr, layout_, style, frame);
    cairo_destroy(cr);
    cairo_surface_flush(surface_);
  }
  ~Picture() { cairo_surface_destroy(surface_); }
  Picture(const Picture&) = delete;
  Picture& operator=(const Picture&) = delete;

  // The pixel at world point (x, y).
  std::uint32_t at(double x, double y) const {
    const auto px = static_cast<int>(std::lround(layout_.px(x)));
    const auto py = static_cast<int>(std::lround(layout_.py(y)));
    const unsigned char* data = cairo_image_surface_get_data(surface_);
    const int stride = cairo_image_surface_get_stride(surface_);
    return *reinterpret_cast<const std::uint32_t*>(data + py * stride + 4 * px) & 0xffffff;
  }
  bool rigid(double x, double y) const { return test::pixel_is(at(x, y), kRigidGrey, 3); }

 private:
  Layout layout_;
  cairo_surface_t* surface_;
};

TEST(RigidStrips, AnOpenBottomSurfaceIsFilledDownToItsBackAcrossTheSeam) {
  // Written towards -x from x = 3.9 (as the shear cell's bottom body): the body is below.
  Snapshot s;
  s.add_polygon(surface(3.9, -0.2, -1.0, 20));  // x from 3.9 down to 0.1
  const Picture picture(s);
  for (double x : {0.5, 1.7, 2.9})
    EXPECT_TRUE(picture.rigid(x, -1.6)) << "below the surface at x = " << x;
  EXPECT_TRUE(picture.rigid(0.05, -1.5)) << "the seam, between the last point and the first";
  EXPECT_TRUE(picture.rigid(3.95, -1.5)) << "the seam, on the other side of the period";
  for (double x : {0.05, 1.7, 3.95})
    EXPECT_FALSE(test::is_matter(picture.at(x, 0.0))) << "above the surface at x = " << x;
}

TEST(RigidStrips, AnOpenTopSurfaceIsFilledUpToItsBackAcrossTheSeam) {
  // Written towards +x (as the shear cell's top body), starting away from the seam and
  // crossing it: the points are wrapped into the period, the body is above.
  Snapshot s;
  std::vector<Vec2> points = surface(2.1, 0.2, 1.0, 20);  // x from 2.1 to 5.9
  for (Vec2& p : points)
    if (p.x() >= kPeriod) p.x() -= kPeriod;
  s.add_polygon(points);
  const Picture picture(s);
  for (double x : {0.5, 1.95, 2.05, 3.9})
    EXPECT_TRUE(picture.rigid(x, 1.6)) << "above the surface at x = " << x;
  for (double x : {0.5, 2.0, 3.9})
    EXPECT_FALSE(test::is_matter(picture.at(x, 0.0))) << "below the surface at x = " << x;
}

TEST(RigidStrips, AClosedRigidBodyAcrossTheSeamIsDrawnWholeOnBothSides) {
  // A square of side 0.6 centred on the seam, its points wrapped into the period one by one.
  Snapshot s;
  s.add_polygon({Vec2(3.7, -0.3), Vec2(0.3, -0.3), Vec2(0.3, 0.3), Vec2(3.7, 0.3)});
  const Picture picture(s);
  EXPECT_TRUE(picture.rigid(0.15, 0.0));
  EXPECT_TRUE(picture.rigid(3.85, 0.0));
  EXPECT_FALSE(test::is_matter(picture.at(2.0, 0.0))) << "no chord across the period";
  EXPECT_FALSE(test::is_matter(picture.at(0.15, 0.6)));
}

}  // namespace
}  // namespace sg
