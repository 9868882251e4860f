#pragma once
// Median-cut lights as other tools read them. Each light is directional: its direction points from the
// scene towards the light, in Lightprobe's world frame (z up, a lat-long map's theta measured from +z and
// phi from +x); its value is its power, the radiance of its region integrated over the region's solid
// angle, which is the irradiance it gives a surface facing it. The lights of a map sum to its power.
#include <string>

#include "engine/mediancut/median_cut.hpp"

namespace lp::cli {

// A header, then one row per light:
// dir_x,dir_y,dir_z,pixel_x,pixel_y,u,v,x0,y0,x1,y1,power_r,power_g,power_b,energy
std::string lights_csv(const MedianCutResult& result);

// pbrt-v4 scene text to Include after WorldBegin: one `LightSource "distant"` per light, light arriving
// from "point3 from" (the direction) towards "point3 to" [0 0 0], with "rgb L" its power and "float
// scale" 1 (pbrt-v4 normalises an RGB illuminant so that [1 1 1] has luminance 1: the values carry over).
std::string lights_pbrt(const MedianCutResult& result);

}  // namespace lp::cli
