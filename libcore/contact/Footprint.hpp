// Where a particle's contact impulse lands on an FE surface: its footprint, not its centre.
//
// A particle stands for a piece of material of in-plane width h / f (f: the smoothing-length
// factor; h grows as the particle expands, docs/formulation.md), and in axisymmetry for a
// ring of that cross-section. Pressing on a surface, that piece loads the stretch of surface
// under it, [s - w/2, s + w/2] along the surface around the foot s of its centre, with the
// uniform traction of a body much wider than it is deep. Each piece of a segment under the
// footprint takes the share of its area (its length, times its mean radius in axisymmetry:
// the 3D area of a ring is 2 pi r ds), split between the segment's two nodes as the planar
// linear shape functions average over the piece:
//     w_A += W_piece (1 - t_mid), w_B += W_piece t_mid,  W_piece = integral of rho ds,
//     rho = r (axisymmetric) or 1 (planar), normalised to sum 1.
// In planar mode these are the shape-function integrals of mortar segment-to-segment contact
// with a constant traction (Puso M.A., Laursen T.A. (2004), Comput. Methods Appl. Mech. Eng.
// 193:601-629). In axisymmetry they are what the elements' own force form gives a uniform
// stress (fe/FeSolid.hpp: f_a = -V B_a^T sigma with V = 2 pi r_mid A, so a face's load is
// its ring area split equally between its nodes), which matches the nodes' lumped masses (a
// quarter of each element's): a uniform traction then accelerates a uniformly moving
// surface uniformly, the axis node included. The radius-weighted shape-function integrals
// (mortar in RZ) would give the axis node a third of its first segment's load, though it
// carries half of that element's mass on the face, and leave it behind its neighbour (at 0.69 of
// their speed after an SPH plate's first blow, FeContact_test.cpp). The stretch follows the chain
// of surface segments from the centre segment both ways. It ends where the chain does (the axis:
// the footprint of a ring near the axis is the disc it lands on; a corner where the chain turns by
// more than 45 degrees; the chain's end), so the footprint never wraps round a corner onto a face
// that does not meet the particle. The shares sum to 1. Why: a point contact hands a particle's
// whole impulse to the two nodes of the segment under its centre; an expanded particle on the axis
// then loads the disc of one element with the areal mass of a solid slug
// (docs/notebook/fe-erosion.md, "What fails the axis column").
//
// Units: mm (lengths); the shares are dimensionless.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace hvi::contact {

/// A set of surface segments A -> B (element on the left) linked into chains: next[s] is
/// the segment starting where s ends, prev[s] the one ending where s starts (-1: none, or
/// more than one). Node coordinates by node index.
struct SurfaceChain {
    std::span<const int32_t> segA, segB, next, prev;
    std::span<const double> z, r;
};

/// A node's or a segment's share of a footprint.
struct Share {
    int32_t index = 0;
    double weight = 0.0;
};

/// The nodal shares (nodes, summing to 1) and the segments' shares (segments, summing to 1:
/// what each segment's element takes) of a footprint of half-width halfWidth [mm] centred at
/// parameter xi in [0, 1] of segment centre. halfWidth 0 gives the point shares 1 - xi and xi.
/// The vectors are cleared first.
void footprintShares(const SurfaceChain& chain, int32_t centre, double xi, double halfWidth,
                     bool axisymmetric, std::vector<Share>& nodes, std::vector<Share>& segments);

} // namespace hvi::contact
