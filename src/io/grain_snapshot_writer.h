#pragma once
// Per-grain snapshot for analysis (coherence, profiles): grains/NNNNNN.csv with columns
// body,x,y,vx,vy,area: centre of mass, its velocity, and the current area of each grain
// (rigid or deformable; walls included, with their names in the run log).
#include <filesystem>

#include "model/model.h"

namespace sg {

void write_grain_snapshot(const Model& model, const std::filesystem::path& path);

}  // namespace sg
