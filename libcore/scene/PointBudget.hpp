// How many points (SPH particles, FE elements) a scene will make and what they would take in
// memory, checked before anything is allocated: a tiny spacing or a huge body would otherwise
// allocate until the machine gives out, or spin in the particle generator (issue #25, item 5).
//
// The estimate is each body's (z, r) bounding box over its spacing squared: exact for plates
// and rectangles on the lattice, 27 % high for a sphere (its half-disc is pi/4 of the
// box), which is what a guard wants. An FE body counts twice: its elements, and the particle
// slots kept for them should they erode. kBytesPerPoint is measured, with margin: an
// FE-walled Whipple run at 0.08 mm (27,350 particle slots and 21,900 elements) peaks at 98 MB
// resident, about 1.4 kB a point with the libraries' own footprint included.
#pragma once

#include "scene/Scene.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace hvi::scene {

inline constexpr double kBytesPerPoint = 2048.0;

/// Points each body makes (by the estimate above), in the order of scene.bodies.
std::vector<double> estimatedPoints(const Scene& scene);

/// Memory the machine can give a run now [bytes]: MemAvailable of /proc/meminfo, or +inf
/// where that cannot be read.
double availableMemoryBytes();

/// Throws InputError naming `file`, the body with the most points (/bodies/i), the count and
/// the memory, when the scene's points would take more than `limitBytes`.
void requirePointBudget(const Scene& scene, const std::string& file, double limitBytes);

} // namespace hvi::scene
