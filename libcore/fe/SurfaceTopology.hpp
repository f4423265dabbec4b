// The surface of an FE mesh under erosion: the boundary edges of its alive elements, linked
// into chains, and the alive elements around each node. Contact takes its master segments
// from here (contact/KinematicContact.hpp); a node's heat goes to the elements listed here.
//
// A boundary edge is an edge of exactly one alive element; in axisymmetry an edge with both
// nodes on the axis is no surface. Segments run A -> B with the element on the left. The
// mesh's edges are tabled once (grouped by node pair, then by element); a rebuild after
// erosion is one pass over that table in a fixed order, so the segment order, and with it
// every result that sums over segments, does not depend on when the rebuild happens.
//
// Units: none (indices), except nodeElementMass [mg].
#pragma once

#include "fe/FeMesh.hpp"

#include <cstdint>
#include <limits>
#include <vector>

namespace hvi::fe {

class SurfaceTopology {
public:
    /// Rebuilds the segments and the node-element lists when the number of alive elements
    /// changed since the last build (or on the first call); true if it rebuilt.
    bool update(const ElementSet& elements, const NodeSet& nodes, bool axisymmetric);

    /// Master segments: nodes A -> B, the body and the element they bound.
    std::vector<int32_t> segA, segB, segBody, segElement;
    /// The chains: the segment starting where each ends, ending where each starts (-1: none,
    /// or a pinch where several meet).
    std::vector<int32_t> segNext, segPrev;
    /// The corners of the alive elements at each node, in element order (none: a free node).
    NodeCorners nodeCorners;
    /// 1 where a node lies on a segment of its own body.
    std::vector<uint8_t> surfaceNode;

    std::size_t segmentCount() const { return segA.size(); }
    /// The mass of a node's alive elements [mg].
    double nodeElementMass(const ElementSet& elements, std::size_t node) const;

private:
    void rebuild(const ElementSet& elements, const NodeSet& nodes, bool axisymmetric);
    void buildEdgeTable(const ElementSet& elements);
    void linkChains(std::size_t nodeCount);

    // The mesh's edges (CSR by node pair, ascending): the elements using each, and at which
    // corner the edge starts (corner -> corner + 1).
    std::vector<int32_t> m_edgeOffset, m_edgeElement;
    std::vector<uint8_t> m_edgeCorner;
    std::size_t m_edgeTableElements = std::numeric_limits<std::size_t>::max();
    std::size_t m_aliveElementsAtBuild = std::numeric_limits<std::size_t>::max();
};

} // namespace hvi::fe
