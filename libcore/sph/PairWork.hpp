// The pair work of one evaluation, kept so the leapfrog's half kicks can pay it with the
// velocities they actually move the particles through: the compatible energy update (J.M. Owen,
// "A compatibly differenced total energy conserving form of SPH", Int. J. Numer. Meth. Fluids
// 75 (2014) 749; Spheral's `compatibleEnergyEvolution` keeps pair accelerations to the same end).
//
// Particle i's heating in the energy equation (sph/SphHydro.hpp) is linear in the velocities:
//
//   de_i/dt = sum_k [gz_ik (v_z,i - v_z,j) + gr_ik (v_r,i - s_k v_r,j)] + c_i v_r,i
//
// with (gz, gr)_ik i's share of the work of its k-th pair (neighbour j) per unit relative
// velocity (s_k = -1 for j's mirror image across the axis) and c_i its hoop coefficient. A half kick applies the forces of
// one evaluation over dt/2; the kinetic energy it gives the particles is the forces' work with
// the mean of the velocities before and after it. Paying the heating with that same mean
// makes the internal energy gained equal to the kinetic energy lost, pair by pair, to round-off,
// whatever the step; the trapezoid rule the other fields take leaves a second-order error in
// the step where pressures change fast within it (docs/notebook/stray-states.md). The rate at
// the evaluation's own velocities remains the rate of the end-of-step prediction.
//
// Units: km/s for velocities; g in MJ/kg/us per km/s.
#pragma once

#include "io/Checkpoint.hpp"
#include "sph/NeighbourSearch.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace hvi::sph {

class PairWork {
public:
    /// One slot per active particle of `list`, each with room for its listed row padded to a
    /// multiple of `lanes` (what the pair loop can keep of it). Discards what was kept.
    void layOut(const NeighbourList& list, std::size_t lanes);

    /// Slot a's pair entries, for the evaluation to fill (up to its capacity).
    int32_t* source(std::size_t a) { return m_source.data() + m_start[a]; }
    double* sign(std::size_t a) { return m_sign.data() + m_start[a]; }
    double* gz(std::size_t a) { return m_gz.data() + m_start[a]; }
    double* gr(std::size_t a) { return m_gr.data() + m_start[a]; }
    std::size_t capacity(std::size_t a) const {
        return static_cast<std::size_t>(m_start[a + 1] - m_start[a]);
    }
    /// Closes slot a: its particle, how many entries the evaluation wrote, its hoop coefficient.
    void close(std::size_t a, int32_t particle, std::size_t count, double hoop) {
        m_particle[a] = particle;
        m_count[a] = static_cast<int32_t>(count);
        m_hoop[a] = hoop;
    }

    std::size_t slots() const { return m_particle.size(); }
    int32_t particle(std::size_t a) const { return m_particle[a]; }

    /// Slot a's heating rate de/dt with the velocities (vz, vr) of every particle [MJ/kg/us].
    double heating(std::size_t a, const std::vector<double>& vz,
                   const std::vector<double>& vr) const;

    /// Its arrays into a checkpoint under `prefix`, and back: the next step's first half kick
    /// pays the work of the evaluation before the checkpoint, which was taken at the step's
    /// predicted state and cannot be recomputed from its final one.
    void save(io::CheckpointState& state, const std::string& prefix) const;
    void restore(const io::CheckpointState& state, const std::string& prefix);

private:
    std::vector<int64_t> m_start{0}; ///< slot a's entries from m_start[a], capacity to a + 1
    std::vector<int32_t> m_particle, m_count;
    std::vector<double> m_hoop;
    std::vector<int32_t> m_source;
    std::vector<double> m_sign, m_gz, m_gr;
};

} // namespace hvi::sph
