#include "io/grain_snapshot_writer.h"

#include <iomanip>

#include "io/atomic_file.h"
#include "model/body_motion.h"
#include "model/kinematics.h"

namespace sg {

void write_grain_snapshot(const Model& model, const std::filesystem::path& path) {
  std::vector<Vec2> contour;
  compute_contour_positions(model, contour);
  write_file_atomically(path, [&](std::ostream& out) {
    out << std::setprecision(12) << "body,x,y,vx,vy,area\n";
    for (std::size_t b = 0; b < model.bodies.size(); ++b) {
      const Body& body = model.bodies[b];
      const BodyMotion motion = body_motion(model, body);
      const Vec2& x = motion.centre;
      const Vec2& v = motion.velocity;
      const Polygon current(contour.begin() + body.contour_begin,
                            contour.begin() + body.contour_end);
      const double area = body.open_contour ? body.reference_area : signed_area(current);
      out << b << ',' << x.x() << ',' << x.y() << ',' << v.x() << ',' << v.y() << ',' << area
          << '\n';
    }
  });
}

}  // namespace sg
