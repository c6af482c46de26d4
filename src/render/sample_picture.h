#pragma once
// The picture of `softgrain generate`'s sample (report/sample_report.h): the bodies at t = 0,
// one colour per body, drawn by the snapshot renderer (render/snapshot_renderer.h).
#include <filesystem>
#include <string>

#include "model/model.h"

namespace sg {

// Draws <dir>/sample.vtu (written first) into <dir>/sample.png with the render stage (one
// colour per body); returns the picture's path.
std::filesystem::path draw_sample_picture(const Model& model, const std::filesystem::path& dir,
                                          const std::string& title);

}  // namespace sg
