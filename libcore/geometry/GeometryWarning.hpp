// Warnings a geometry reduction attaches to its result. The reduction still produced a
// geometry, but a designer should look before running it, so a tool should print them.
#pragma once

#include <string>

namespace hvi::geometry {

enum class WarningKind {
    /// A body is thinner than 3 SPH particle spacings at the stated resolution: the
    /// hydrocode cannot represent it (the message names the spacing that would).
    UnderResolved,
    /// Bodies touch or overlap (a layer or ring thicker than the space between neighbours).
    Overlap,
};

struct GeometryWarning {
    WarningKind kind;
    std::string message; ///< one line, with the numbers and the remedy
};

} // namespace hvi::geometry
