#include "fe/SurfaceTopology.hpp"

#include <algorithm>
#include <utility>

namespace hvi::fe {

bool SurfaceTopology::update(const ElementSet& el, const NodeSet& nd, bool axisymmetric) {
    std::size_t aliveElements = 0;
    for (const auto a : el.alive) {
        aliveElements += a;
    }
    if (aliveElements == m_aliveElementsAtBuild) {
        return false;
    }
    rebuild(el, nd, axisymmetric);
    m_aliveElementsAtBuild = aliveElements;
    return true;
}

double SurfaceTopology::nodeElementMass(const ElementSet& el, std::size_t node) const {
    double mass = 0.0;
    for (int64_t k = nodeCorners.offset[node]; k < nodeCorners.offset[node + 1]; ++k) {
        mass += el.mass[NodeCorners::elementOf(nodeCorners.corners[static_cast<std::size_t>(k)])];
    }
    return mass;
}

void SurfaceTopology::buildEdgeTable(const ElementSet& el) {
    // Every element edge once per element that has it, grouped by its node pair in ascending
    // (min, max) order and, within a pair, by element: the order the segments are listed in.
    struct Use {
        std::pair<int32_t, int32_t> key;
        int32_t element, corner;
    };
    std::vector<Use> uses;
    uses.reserve(4 * el.size());
    for (std::size_t i = 0; i < el.size(); ++i) {
        for (int a = 0; a < 4; ++a) {
            const int32_t na = el.node(i, a), nb = el.node(i, (a + 1) % 4);
            uses.push_back({{std::min(na, nb), std::max(na, nb)}, static_cast<int32_t>(i), a});
        }
    }
    std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) {
        return x.key != y.key ? x.key < y.key : x.element < y.element;
    });
    m_edgeOffset.clear();
    m_edgeElement.clear();
    m_edgeCorner.clear();
    for (std::size_t k = 0; k < uses.size(); ++k) {
        if (k == 0 || uses[k].key != uses[k - 1].key) {
            m_edgeOffset.push_back(static_cast<int32_t>(k));
        }
        m_edgeElement.push_back(uses[k].element);
        m_edgeCorner.push_back(static_cast<uint8_t>(uses[k].corner));
    }
    m_edgeOffset.push_back(static_cast<int32_t>(uses.size()));
    m_edgeTableElements = el.size();
}

void SurfaceTopology::rebuild(const ElementSet& el, const NodeSet& nd, bool axisymmetric) {
    if (m_edgeTableElements != el.size()) {
        buildEdgeTable(el);
    }
    nodeCorners = NodeCorners::of(el, nd.size(), true);
    segA.clear();
    segB.clear();
    segBody.clear();
    segElement.clear();
    surfaceNode.assign(nd.size(), 0);
    const std::size_t edgeCount = m_edgeOffset.size() - 1;
    for (std::size_t edge = 0; edge < edgeCount; ++edge) {
        int aliveUses = 0;
        std::size_t use = 0;
        for (auto k = static_cast<std::size_t>(m_edgeOffset[edge]);
             k < static_cast<std::size_t>(m_edgeOffset[edge + 1]); ++k) {
            if (el.alive[static_cast<std::size_t>(m_edgeElement[k])]) {
                ++aliveUses;
                use = k;
            }
        }
        if (aliveUses != 1) {
            continue;
        }
        const auto element = static_cast<std::size_t>(m_edgeElement[use]);
        const int corner = m_edgeCorner[use];
        const int32_t na = el.node(element, corner), nb = el.node(element, (corner + 1) % 4);
        const auto a = static_cast<std::size_t>(na), b = static_cast<std::size_t>(nb);
        if (axisymmetric && nd.onAxis[a] && nd.onAxis[b]) {
            continue;
        }
        segA.push_back(na);
        segB.push_back(nb);
        segBody.push_back(nd.body[a]);
        segElement.push_back(static_cast<int32_t>(element));
        surfaceNode[a] = surfaceNode[b] = 1;
    }
    linkChains(nd.size());
}

void SurfaceTopology::linkChains(std::size_t nodeCount) {
    // Through the nodes the segments share; a node where more than one segment starts or
    // ends (a pinch left by erosion) links none.
    const std::size_t ns = segA.size();
    std::vector<int32_t> startingAt(nodeCount, -1), endingAt(nodeCount, -1);
    constexpr int32_t kSeveral = -2;
    for (std::size_t s = 0; s < ns; ++s) {
        auto note = [&](int32_t& slot) { slot = slot == -1 ? static_cast<int32_t>(s) : kSeveral; };
        note(startingAt[static_cast<std::size_t>(segA[s])]);
        note(endingAt[static_cast<std::size_t>(segB[s])]);
    }
    segNext.assign(ns, -1);
    segPrev.assign(ns, -1);
    for (std::size_t s = 0; s < ns; ++s) {
        segNext[s] = std::max(startingAt[static_cast<std::size_t>(segB[s])], -1);
        segPrev[s] = std::max(endingAt[static_cast<std::size_t>(segA[s])], -1);
    }
}

} // namespace hvi::fe
