#pragma once
// What a model's materials let a ray through (Embree filter functions on its triangle geometry): glTF
// alpha coverage (MASK keeps alpha >= alphaCutoff, BLEND keeps a hit with probability alpha) for every
// ray, and the culling of single-sided materials' back faces for camera rays. glTF says the back faces
// of a single-sided material are not visible; Blender's importer maps that to backface culling, which
// Cycles does not apply when rendering. Here the camera does not see them, as in a glTF viewer, while
// shadow and bounce rays still meet them, so a single-sided mesh lights and shadows as Cycles renders it.
#include <embree3/rtcore.h>

#include <cstdint>

#include "engine/model/model.hpp"

namespace lp::render {

// An intersection context that says what kind of ray Embree traces, for the filter functions.
struct RayContext {
  RTCIntersectContext embree;
  bool camera = false;

  explicit RayContext(bool camera_ray) : camera(camera_ray) { rtcInitIntersectContext(&embree); }
};

// Installs the filters on `geometry` if some material of `model` needs them (not opaque, or
// single-sided); `model` must outlive the geometry. Fully opaque, double-sided models pay nothing.
void install_hit_filter(RTCGeometry geometry, const Model& model);

// A material's alpha at a point of a triangle (barycentrics u, v): base colour factor x base colour
// texture (finest level) x COLOR_0.
float coverage_alpha(const Model& model, uint32_t triangle, float u, float v);

// Whether a hit on `triangle` with `alpha` is kept, given a uniform `xi` in [0, 1).
bool covers(const ModelMaterial& material, float alpha, float xi);

// A uniform number in [0, 1) that is a function of the ray and the primitive it hits: the same ray
// meeting the same triangle always gets the same answer, different rays independent ones.
float hit_uniform(Vec3 origin, Vec3 direction, uint32_t primitive);

}  // namespace lp::render
