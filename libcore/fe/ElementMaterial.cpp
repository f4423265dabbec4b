// The material pipeline (material/MaterialPackage.hpp) instantiated for FE elements.
#include "fe/ElementRates.hpp"
#include "fe/FeMesh.hpp"
#include "material/MaterialPackage.tpp"

namespace hvi::material {

template void MaterialPackage::updatePressure(fe::ElementSet&) const;
template void MaterialPackage::updatePressure(fe::ElementSet&, std::span<const int32_t>) const;
template void MaterialPackage::addStressRates(const fe::ElementSet&, std::span<const int32_t>,
                                              fe::ElementRates&) const;
template void MaterialPackage::applyPlasticity(fe::ElementSet&, const fe::ElementRates&,
                                               std::span<const int32_t>, double) const;
template void MaterialPackage::applyPlasticity(fe::ElementSet&, const fe::ElementRates&,
                                               std::span<const int32_t>,
                                               const std::vector<double>&) const;

} // namespace hvi::material
