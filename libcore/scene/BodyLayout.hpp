// Where the bodies are, checked before a scene runs (issue #25, items 3-4): bodies that
// overlap, and bodies reaching outside the simulated region, are refused with the JSON
// pointer of the body, instead of running into a verdict that means nothing (a projectile
// centred inside its bumper came out P; one upstream of z_min was deleted at step 1 and came
// out NP; a wall beyond the domain radius was deleted and came out P).
//
// In the (z, r) half-plane a sphere is a half-disc on the axis and a plate or rectangle a
// box. Two bodies overlap when they share more than half the finer of their spacings (one
// body's points would sit inside the other's); bodies that touch, as a foam layer stack's
// layers or a honeycomb's rings and facesheets do, do not. A body reaches outside the domain
// when it extends beyond the domain radius or its z limits by more than half its spacing.
// Plates are not cut to the domain: the scene writers make them exactly as wide as it.
// Lengths in mm.
#pragma once

#include "core/Error.hpp"
#include "scene/Scene.hpp"

#include <string>
#include <vector>

namespace hvi::scene {

/// The overlaps and out-of-domain bodies of `scene` (domain radius resolved), as issues of
/// `file` at /bodies/N/shape; empty when the layout is sound.
std::vector<InputIssue> bodyLayoutIssues(const Scene& scene, const std::string& file);

/// What is legal but most likely a mistake, one line each: a body moving along the axis with
/// nothing ahead of it in its path (no other body downstream whose radial extent meets its
/// own), and a scene in which nothing moves at all.
std::vector<std::string> bodyLayoutWarnings(const Scene& scene);

/// How deep shapes a and b overlap [mm]: the least distance either must move to clear the
/// other (<= 0: apart or touching). Exposed for the tests.
double overlapDepth(const Shape& a, const Shape& b);

} // namespace hvi::scene
