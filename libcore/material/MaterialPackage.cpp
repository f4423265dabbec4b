#include "material/MaterialPackage.hpp"

#include <limits>
#include <variant>

namespace hvi::material {

double densityCeiling(const material::MaterialSpec& spec) {
    if (const auto* mg = std::get_if<material::MieGruneisen>(&spec.eos)) {
        const double sm1 = mg->hugoniotSlope - 1.0;
        if (sm1 > 0.0) {
            return mg->referenceDensity * (1.0 + 0.5 / sm1);
        }
    }
    return std::numeric_limits<double>::infinity();
}

} // namespace hvi::material
