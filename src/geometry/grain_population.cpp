#include "geometry/grain_population.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.h"
#include "geometry/shapes.h"

namespace sg {

Polygon sample_grain_contour(const GrainShapeDef& shape, RandomEngine& engine, double& size) {
  SG_VERIFY(shape.contour_spacing > 0.0,
            "grain shape: contour_spacing must be positive, got " << shape.contour_spacing);
  const Vec2 origin(0.0, 0.0);
  switch (shape.kind) {
    case GrainShapeKind::disc: {
      verify_size_range(shape.diameter, "disc diameter");
      size = sample_size(shape.diameter, engine);
      return make_disc(origin, 0.5 * size, shape.contour_spacing);
    }
    case GrainShapeKind::ellipse: {
      verify_size_range(shape.major_axis, "ellipse major axis");
      verify_size_range(shape.minor_axis, "ellipse minor axis");
      SG_VERIFY(shape.orientation_max >= shape.orientation_min,
                "ellipse orientation range must satisfy min <= max, got ["
                    << shape.orientation_min << ", " << shape.orientation_max << "]");
      double major = sample_size(shape.major_axis, engine);
      double minor = sample_size(shape.minor_axis, engine);
      if (minor > major) std::swap(major, minor);
      const double angle = uniform_in(engine, shape.orientation_min, shape.orientation_max);
      size = major;
      return make_ellipse(origin, 0.5 * major, 0.5 * minor, angle, shape.contour_spacing);
    }
    case GrainShapeKind::fourier: {
      verify_size_range(shape.diameter, "Fourier shape diameter");
      size = sample_size(shape.diameter, engine);
      return sample_fourier_shape(origin, 0.5 * size, shape.spectrum, shape.contour_spacing,
                                  engine);
    }
  }
  SG_THROW("grain shape: unknown kind");
}

std::vector<GrainDef> generate_grains(const MixtureDef& mixture, int count, std::uint64_t seed) {
  SG_VERIFY(!mixture.components.empty(), "grain mixture: no components");
  SG_VERIFY(count >= 0, "grain mixture: count must be >= 0, got " << count);
  double total_fraction = 0.0;
  for (const GrainComponentDef& c : mixture.components) {
    SG_VERIFY(c.number_fraction >= 0.0 && std::isfinite(c.number_fraction),
              "grain mixture: component '" << c.name << "' has number_fraction "
                                           << c.number_fraction << " (must be >= 0)");
    total_fraction += c.number_fraction;
  }
  SG_VERIFY(total_fraction > 0.0, "grain mixture: number fractions sum to zero");

  // Largest-remainder rounding: floor of each exact share, then one more grain to the
  // components with the largest remainders (ties to the first listed).
  const std::size_t m = mixture.components.size();
  std::vector<int> counts(m);
  std::vector<double> remainder(m);
  int assigned = 0;
  for (std::size_t c = 0; c < m; ++c) {
    const double exact = count * mixture.components[c].number_fraction / total_fraction;
    counts[c] = static_cast<int>(std::floor(exact));
    remainder[c] = exact - counts[c];
    assigned += counts[c];
  }
  std::vector<std::size_t> by_remainder(m);
  std::iota(by_remainder.begin(), by_remainder.end(), std::size_t{0});
  std::stable_sort(by_remainder.begin(), by_remainder.end(),
                   [&](std::size_t a, std::size_t b) { return remainder[a] > remainder[b]; });
  for (std::size_t k = 0; assigned < count; ++k, ++assigned)
    ++counts[by_remainder[k % m]];

  std::vector<int> component_of;
  component_of.reserve(static_cast<std::size_t>(count));
  for (std::size_t c = 0; c < m; ++c)
    component_of.insert(component_of.end(), counts[c], int(c));
  RandomEngine engine(seed);
  // Fisher-Yates with the portable uniform_index (std::shuffle is implementation-defined).
  for (int i = count - 1; i > 0; --i)
    std::swap(component_of[static_cast<std::size_t>(i)],
              component_of[static_cast<std::size_t>(uniform_index(engine, i + 1))]);

  std::vector<GrainDef> grains(static_cast<std::size_t>(count));
  for (std::size_t i = 0; i < grains.size(); ++i) {
    const GrainComponentDef& c = mixture.components[static_cast<std::size_t>(component_of[i])];
    GrainDef& g = grains[i];
    g.contour = sample_grain_contour(c.shape, engine, g.size);
    g.bounding_radius = center_on_centroid(g.contour);
    g.component = component_of[i];
    g.rigid = c.rigid;
    g.material = c.material;
  }
  return grains;
}

double mixture_grain_size(const std::vector<GrainComponentDef>& components,
                          const std::string& what) {
  double weighted = 0.0, total = 0.0;
  for (const GrainComponentDef& c : components) {
    const SizeRangeDef& range =
        c.shape.kind == GrainShapeKind::ellipse ? c.shape.minor_axis : c.shape.diameter;
    weighted += c.number_fraction * 0.5 * (range.min + range.max);
    total += c.number_fraction;
  }
  SG_VERIFY(total > 0.0, what << ": no grain components, or their fractions sum to zero");
  return weighted / total;
}

}  // namespace sg
