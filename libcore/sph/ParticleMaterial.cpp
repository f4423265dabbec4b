// The material pipeline (material/MaterialPackage.hpp) instantiated for SPH particles.
#include "material/MaterialPackage.tpp"
#include "sph/ParticleSet.hpp"

namespace hvi::material {

template void MaterialPackage::updatePressure(sph::ParticleSet&) const;
template void MaterialPackage::updatePressure(sph::ParticleSet&, std::span<const int32_t>) const;
template void MaterialPackage::addStressRates(const sph::ParticleSet&, std::span<const int32_t>,
                                              sph::ParticleRates&) const;
template void MaterialPackage::applyPlasticity(sph::ParticleSet&, const sph::ParticleRates&,
                                               std::span<const int32_t>, double) const;
template void MaterialPackage::applyPlasticity(sph::ParticleSet&, const sph::ParticleRates&,
                                               std::span<const int32_t>,
                                               const std::vector<double>&) const;

} // namespace hvi::material
