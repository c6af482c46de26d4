#include "io/grain_snapshot_writer.h"

#include <iomanip>

#include "io/atomic_file.h"
#include "model/kinematics.h"

namespace sg {

void write_grain_snapshot(const Model& model, const std::filesystem::path& path) {
  std::vector<Vec2> contour;
  compute_contour_positions(model, contour);
  write_file_atomically(path, [&](std::ostream& out) {
    out << std::setprecision(12) << "body,x,y,vx,vy,area\n";
    for (std::size_t b = 0; b < model.bodies.size(); ++b) {
      const Body& body = model.bodies[b];
      Vec2 x(0, 0), v(0, 0);
      if (body.kind == BodyKind::rigid) {
        const auto r = static_cast<std::size_t>(body.rigid_index);
        x = Vec2(model.rigid.x[r], model.rigid.y[r]);
        v = Vec2(model.rigid.vx[r], model.rigid.vy[r]);
      } else {
        // Centre of mass and momentum of the lumped parameters (exact for the discrete system).
        double m = 0.0;
        for (int i = body.node_begin; i < body.node_end; ++i) {
          const auto k = static_cast<std::size_t>(i);
          m += model.nodes.mass[k];
          x += model.nodes.mass[k] * Vec2(model.nodes.ref_x[k] + model.nodes.ux[k],
                                          model.nodes.ref_y[k] + model.nodes.uy[k]);
          v += model.nodes.mass[k] * Vec2(model.nodes.vx[k], model.nodes.vy[k]);
        }
        x /= m;
        v /= m;
      }
      const Polygon current(contour.begin() + body.contour_begin,
                            contour.begin() + body.contour_end);
      const double area = body.open_contour ? body.reference_area : signed_area(current);
      out << b << ',' << x.x() << ',' << x.y() << ',' << v.x() << ',' << v.y() << ',' << area
          << '\n';
    }
  });
}

}  // namespace sg
