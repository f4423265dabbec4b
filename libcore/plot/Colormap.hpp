// Colours for field pictures: a perceptually uniform sequential map for scalar fields
// (damage), and a fixed palette of distinguishable colours for categories (bodies).
#pragma once

#include "plot/XyPlot.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

namespace hvi::plot {

/// Viridis (van der Walt & Smith 2015, matplotlib's default map), sampled at 9 stops and
/// interpolated linearly: dark blue at 0, green at 0.5, yellow at 1. `t` is clamped to [0, 1].
inline Rgb viridis(double t) {
    static constexpr std::array<Rgb, 9> stops{{{0.267, 0.005, 0.329},
                                               {0.282, 0.141, 0.458},
                                               {0.254, 0.265, 0.530},
                                               {0.207, 0.372, 0.553},
                                               {0.164, 0.471, 0.558},
                                               {0.128, 0.567, 0.551},
                                               {0.135, 0.659, 0.518},
                                               {0.478, 0.821, 0.318},
                                               {0.993, 0.906, 0.144}}};
    t = std::clamp(t, 0.0, 1.0) * static_cast<double>(stops.size() - 1);
    const auto k = std::min(static_cast<std::size_t>(t), stops.size() - 2);
    const double f = t - static_cast<double>(k);
    const Rgb& a = stops[k];
    const Rgb& b = stops[k + 1];
    return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b)};
}

/// The k-th colour of a 10-colour categorical palette (Tableau 10), repeating.
inline Rgb categorical(std::size_t k) {
    static constexpr std::array<Rgb, 10> palette{{{0.122, 0.467, 0.706},
                                                  {1.000, 0.498, 0.055},
                                                  {0.173, 0.627, 0.173},
                                                  {0.839, 0.153, 0.157},
                                                  {0.580, 0.404, 0.741},
                                                  {0.549, 0.337, 0.294},
                                                  {0.890, 0.467, 0.761},
                                                  {0.498, 0.498, 0.498},
                                                  {0.737, 0.741, 0.133},
                                                  {0.090, 0.745, 0.812}}};
    return palette[k % palette.size()];
}

} // namespace hvi::plot
