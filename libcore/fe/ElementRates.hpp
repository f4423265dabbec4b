// Per-element rates of one finite-element update, in the field names the material pipeline
// (material::MaterialPackage) shares with sph::ParticleRates. Units: 1/us, GPa/us.
#pragma once

#include <cstddef>
#include <vector>

namespace hvi::fe {

struct ElementRates {
    std::vector<double> dvzDz, dvzDr, dvrDz, dvrDr; ///< velocity gradient at the centroid
    std::vector<double> hoopRate;                   ///< D_thth = v_r / r [1/us]
    std::vector<double> strainRate;                 ///< equivalent deviatoric strain rate
    std::vector<double> dszz, dsrr, dsrz;           ///< Jaumann deviator rate [GPa/us]

    void resize(std::size_t n) {
        for (auto* v : {&dvzDz, &dvzDr, &dvrDz, &dvrDr, &hoopRate, &strainRate, &dszz, &dsrr,
                        &dsrz}) {
            v->assign(n, 0.0);
        }
    }
};

} // namespace hvi::fe
