#include "geometry/bounding_box.h"

namespace sg {

BoundingBox bounding_box(const Polygon& p) {
  BoundingBox box;
  for (const Vec2& v : p)
    box.add(v);
  return box;
}

BoundingBox bounding_box(const Polygon& p, const Vec2& shift) {
  BoundingBox box;
  for (const Vec2& v : p)
    box.add(v + shift);
  return box;
}

}  // namespace sg
