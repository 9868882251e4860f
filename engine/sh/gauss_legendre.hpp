#pragma once
// The 8-point Gauss-Legendre rule on [-1, 1] (exact for polynomials of degree up to 15): the nodes
// +-kGaussLegendre8Nodes[i] each with weight kGaussLegendre8Weights[i].
#include <array>

namespace lp {

inline constexpr std::array<double, 4> kGaussLegendre8Nodes = {0.1834346424956498, 0.5255324099163290,
                                                               0.7966664774136267, 0.9602898564975363};
inline constexpr std::array<double, 4> kGaussLegendre8Weights = {0.3626837833783620, 0.3137066458778873,
                                                                 0.2223810344533745, 0.1012285362903763};

}  // namespace lp
