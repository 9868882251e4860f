#pragma once
// The split-sum DFG table of image-based lighting (Karis 2013; Lagarde and de Rousiers 2014): for a GGX
// lobe of perceptual roughness r (alpha = r^2, as glTF and Filament) seen at n.v, the directional albedo
// split into the parts that multiply F0 and that add to it, so that prefiltered radiance times
// (F0 scale + bias) is the specular term.
//   single scattering: (scale, bias) = integral of (1 - Fc) G2 / G1, integral of Fc G2 / G1
//   multiscatter:      (bias, scale + bias), Filament's layout: specular = mix(x, y, F0), and
//                      1 + F0 (1 / y - 1) compensates the energy multiple scattering keeps
// with Fc = (1 - v.h)^5 and G2 / G1 the weight of a visible normal (Heitz 2018), integrated by the
// quadrature of the renderer's own albedo tables (engine/bsdf/visible_normal_quadrature.hpp).
#include <memory>
#include <vector>

namespace lp {

struct DfgValue {
  double x = 0, y = 0;
};

// The integrals at one point. Where alpha is below the delta-lobe threshold the lobe is a mirror:
// scale = 1 - (1 - n.v)^5, bias = (1 - n.v)^5.
DfgValue dfg(double n_dot_v, double roughness, bool multiscatter);

// size x size texels: column x at n.v = (x + 0.5) / size, row y at roughness (y + 0.5) / size (row 0,
// at the top of an image, is the smoothest).
struct DfgLut {
  int size = 0;
  bool multiscatter = false;
  std::vector<DfgValue> texels;  // row-major
  const DfgValue& at(int x, int y) const { return texels[size_t(y) * size_t(size) + size_t(x)]; }
};

DfgLut make_dfg_lut(int size, bool multiscatter);
// The same, computed once per (size, multiscatter) in this process.
std::shared_ptr<const DfgLut> dfg_lut_cached(int size, bool multiscatter);

}  // namespace lp
