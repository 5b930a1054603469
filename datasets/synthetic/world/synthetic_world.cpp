#include "datasets/synthetic/world/synthetic_world.hpp"

#include <array>
#include <cmath>

namespace radarpr::synthetic {

void add_wall(World& world, Vec2 a, Vec2 b, const WallMaterial& material) {
  world.walls.push_back({a, b, material.strength, material.transmission, material.texture_period_m,
                         material.scatter_units});
}

void add_box(World& world, Vec2 centre, double length_m, double width_m, double yaw_rad,
             const WallMaterial& material) {
  const double c = std::cos(yaw_rad);
  const double s = std::sin(yaw_rad);
  const double hl = 0.5 * length_m;
  const double hw = 0.5 * width_m;
  const std::array<Vec2, 4> corners = {{
      {centre.x + c * hl - s * hw, centre.y + s * hl + c * hw},
      {centre.x - c * hl - s * hw, centre.y - s * hl + c * hw},
      {centre.x - c * hl + s * hw, centre.y - s * hl - c * hw},
      {centre.x + c * hl + s * hw, centre.y + s * hl - c * hw},
  }};
  for (std::size_t i = 0; i < corners.size(); ++i) {
    add_wall(world, corners[i], corners[(i + 1) % corners.size()], material);
  }
}

void add_axis_box(World& world, double x0, double y0, double x1, double y1,
                  const WallMaterial& material) {
  add_box(world, {0.5 * (x0 + x1), 0.5 * (y0 + y1)}, x1 - x0, y1 - y0, 0.0, material);
}

}  // namespace radarpr::synthetic
