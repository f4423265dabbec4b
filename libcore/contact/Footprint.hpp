// Where a particle's contact impulse lands on an FE surface: its footprint, not its centre.
//
// A particle stands for a piece of material of in-plane width h / f (f: the smoothing-length
// factor; h grows as the particle expands, docs/formulation.md), and in axisymmetry for a
// ring of that cross-section. Pressing on a surface, that piece loads the stretch of surface
// under it, [s - w/2, s + w/2] along the surface around the foot s of its centre, with the
// uniform traction of a body much wider than it is deep. The consistent nodal shares of a
// uniform traction over that stretch are the integrals of the segments' linear shape
// functions over it (the mortar segment-to-segment projection, Puso M.A., Laursen T.A.
// (2004), Comput. Methods Appl. Mech. Eng. 193:601-629, with a constant slave traction), weighted
// by the radius in axisymmetry (the 3D area of a ring of the stretch is 2 pi r ds):
//     w_k = integral over the footprint of N_k(s) rho(s) ds / integral of rho(s) ds,
//     rho = r (axisymmetric) or 1 (planar).
// The stretch follows the chain of surface segments from the centre segment both ways. It
// ends where the chain does (the axis: the footprint of a ring near the axis is the disc it
// lands on; a corner where the chain turns by more than 45 degrees; the chain's end), so the
// footprint never wraps round a corner onto a face that does not meet the particle. The
// shares sum to 1. Why: a point contact hands a particle's whole impulse to the two nodes
// of the segment under its centre; an expanded particle on the axis then loads the disc of
// one element with the areal mass of a solid slug (docs/fe-erosion.md, "What fails the
// axis column").
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
