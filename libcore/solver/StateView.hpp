// The solver's point sets as the run file's fields (io/OutputFields.hpp), viewed without a
// copy: what a snapshot writes, and what the stop rule hands hvi-assess's rules
// (solver/RearWallConfirmation.hpp).
#pragma once

#include "fe/FeSolid.hpp"
#include "io/OutputFields.hpp"
#include "sph/ParticleSet.hpp"

#include <vector>

namespace hvi::solver {

/// The particle fields. The deviator is interleaved (zz, rr, rz) per particle in the file, so
/// it is copied into `deviator`, which must outlive the view.
io::ParticleFieldsView particleFieldsOf(const sph::ParticleSet& ps, std::vector<double>& deviator);

/// The FE node and element fields (the element state arrays that a strengthless scene lacks
/// stay empty and are left out), with `erosionStrain` as the elements' geometric strain.
io::FeFieldsView feFieldsOf(const fe::FeSolid& fe, const std::vector<double>& erosionStrain);

} // namespace hvi::solver
