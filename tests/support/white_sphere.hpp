#pragma once
// The render request of a white diffuse sphere of radius 1 at the origin, seen from 4 units on -y at
// size x size pixels (odd: the centre pixel looks at the sphere's nearest point), under the map `envmap`.
#include <nlohmann/json.hpp>
#include <string>

namespace lp::test {

inline nlohmann::json white_sphere_body(const std::string& envmap, int size, int spp) {
  return {{"envmap", envmap},
          {"width", size},
          {"height", size},
          {"spp", spp},
          {"scene",
           {{"objects",
             {{{"type", "sphere"},
               {"center", {0, 0, 0}},
               {"radius", 1},
               {"material", {{"type", "diffuse"}, {"albedo", 1}}}}}},
            {"camera", {{"position", {0, -4, 0}}, {"look_at", {0, 0, 0}}, {"fov_deg", 40}}}}}};
}

}  // namespace lp::test
