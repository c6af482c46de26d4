#include "render/sample_picture.h"

#include "core/error.h"
#include "io/vtk_writer.h"
#include "render/snapshot_renderer.h"

namespace sg {

std::filesystem::path draw_sample_picture(const Model& model, const std::filesystem::path& dir,
                                          const std::string& title) {
  namespace fs = std::filesystem;
  // render_run draws a run folder's fields.pvd: a one-entry index for the duration of the call.
  const fs::path pvd = dir / "fields.pvd";
  const fs::path render_dir = dir / "render";
  SG_VERIFY(!fs::exists(render_dir),
            "'" << render_dir.string() << "' exists: remove it (generate draws its picture there)");
  struct Cleanup {
    fs::path pvd, render_dir;
    ~Cleanup() {
      std::error_code ignored;
      fs::remove(pvd, ignored);
      fs::remove_all(render_dir, ignored);
    }
  } cleanup{pvd, render_dir};
  PvdCollection(pvd).add(0.0, "sample.vtu");
  RenderOptions options;
  options.field = "body";  // one colour per body: rigid and deformable grains alike
  options.last_frame_only = true;
  options.movie = false;
  options.title = title;
  if (model.periodic_x) options.periodic = std::make_pair(model.x_min, model.x_max);
  const RenderResult result = render_run(dir, options);
  SG_VERIFY(result.images.size() == 1,
            "sample picture: render drew " << result.images.size() << " images, expected 1");
  const fs::path png = dir / "sample.png";
  fs::rename(result.images.front(), png);
  return png;
}

}  // namespace sg
