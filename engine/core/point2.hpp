#pragma once
// A point of the unit square [0, 1)^2: the two uniform numbers a sampler turns into a direction.
namespace lp {

struct Point2 {
  float x = 0, y = 0;
};

}  // namespace lp
