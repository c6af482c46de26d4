#pragma once
// The text of a small cohesive shear-cell scenario (soft neo-Hookean grains, rough rigid
// first bodies, cohesive grain-grain and grain-wall laws), for tests that run one end to end.
#include <sstream>
#include <string>

namespace sg::scenes {

struct CohesiveShearCell {
  std::string name = "cell";
  double duration = 1.0;
  std::string extra_time;  // more lines of the [time] table
  double series_period = 0.01, field_period = 0.1;
  double checkpoint_period = -1.0;  // < 0: key omitted (the default)
  double node_spacing = 0.25;
  double poisson = 0.45, damping = 0.01;
  std::string damping_model;  // of the grains; empty: key omitted (objective)
  double normal_stiffness = 2000.0, cohesion = 0.1;
  double length = 6.0;
  int grains = 8;
  double roughness_rms = 0.2;
  double gap = 0.0;  // 0: key omitted (90% of the packed height)
  double compaction_time = 1.0, velocity = 1.0;
  int seed = 3;
};

inline std::string shear_cell_scenario(const CohesiveShearCell& c) {
  std::ostringstream s;
  s.precision(17);
  auto law = [&](const char* a, const char* b, const char* kind) {
    s << "[[contact_laws]]\nmaterials = [\"" << a << "\", \"" << b << "\"]\nlaw = \"" << kind
      << "\"\nnormal_stiffness = " << c.normal_stiffness << "\n";
    if (std::string(kind) == "cohesive") s << "cohesion = " << c.cohesion << "\n";
  };
  s << "name = \"" << c.name << "\"\n[time]\nduration = " << c.duration << "\n"
    << c.extra_time << "\n[output]\nseries_period = " << c.series_period
    << "\nfield_period = " << c.field_period << "\n";
  if (c.checkpoint_period >= 0.0) s << "checkpoint_period = " << c.checkpoint_period << "\n";
  s << "[discretization]\nnode_spacing = " << c.node_spacing
    << "\n[[materials]]\nname = \"soft\"\nyoung = 10.0\npoisson = " << c.poisson
    << "\ndamping = " << c.damping << "\n";
  if (!c.damping_model.empty()) s << "damping_model = \"" << c.damping_model << "\"\n";
  s << "[[materials]]\nname = \"first_body\"\nyoung = 1000.0\n";
  law("soft", "soft", "cohesive");
  law("soft", "first_body", "cohesive");
  law("first_body", "first_body", "frictionless");
  s << "[shear_cell]\nlength = " << c.length << "\ngrains = " << c.grains
    << "\ndiameter = [0.85, 1.15]\ngrain_material = \"soft\"\nfirst_body_material = "
       "\"first_body\"\nroughness_rms = "
    << c.roughness_rms << "\nhurst = 0.8\n";
  if (c.gap > 0.0) s << "gap = " << c.gap << "\n";
  s << "compaction_time = " << c.compaction_time << "\nvelocity = " << c.velocity
    << "\nseed = " << c.seed << "\n";
  return s.str();
}

// A 16-grain imex cell under pressure loading with a light top (density 0.1) and a stiff servo,
// which loads the layer within its 4 time units (the campaign tests under pressure).
inline std::string tiny_pressure_cell(double field_period, const std::string& pressure) {
  CohesiveShearCell c;
  c.name = "cell";
  c.duration = 4.0;
  c.compaction_time = 0.4;
  c.grains = 16;
  c.series_period = 0.01;
  c.field_period = field_period;
  c.extra_time = "integrator = \"imex\"";
  std::string text = shear_cell_scenario(c);
  const std::string rigid = "name = \"first_body\"\nyoung = 1000.0\n";
  text.replace(text.find(rigid), rigid.size(), rigid + "density = 0.1\n");
  return text + "normal_load = \"pressure\"\npressure = " + pressure + "\nservo_damping = 0.5\n";
}

}  // namespace sg::scenes
