#include "sph/SphHydro.hpp"

#include "core/Parallel.hpp"
#include "core/Units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <omp.h>

namespace hvi::sph {

namespace {

struct StepVote {
    double dt = std::numeric_limits<double>::infinity();
    int32_t particle = -1;
};

/// `kArtificialStress`: the artificial-stress terms are compiled in (chosen once per scene, so
/// the default path carries no per-pair test).
template <class Kern, bool kArtificialStress>
void evaluatePairs(const ParticleSet& ps, const NeighbourList& list, const HydroOptions& opt,
                   const std::vector<PairData>& data, ParticleRates& rates, StepVote& vote) {
    using Shape = typename Kern::ShapeType;
    const bool axi = opt.axisymmetric;
    const bool strength = ps.hasStrength();
    const double alpha = opt.avAlpha, beta = opt.avBeta, eta2 = opt.avEta2;
    const double invShapeAtSpacing = 1.0 / Shape::shape(opt.spacingOverH);
    const double inv2Pi = 0.5 / units::kPi;
    const std::size_t activeCount = list.active.size();
    const auto* src = list.source.data();
    const auto* sgn = list.sign.data();
    const auto* nb = list.neighbours.data();
    const PairData* pd = data.data();

    // Thread-local vote, combined in a fixed order afterwards (min is order-independent,
    // ties broken by the lowest particle index, so the result is thread-count independent).
    std::vector<StepVote> threadVotes(static_cast<std::size_t>(omp_get_max_threads()));
    int64_t longestRow = 0;
    for (std::size_t a = 0; a < activeCount; ++a) {
        const int32_t row = list.row[a];
        longestRow = std::max(longestRow, list.offset[row + 1] - list.offset[row]);
    }
#pragma omp parallel if (activeCount > kParallelMinHeavyItems)
    {
        StepVote local;
        // This particle's neighbours within the support (sized once: no per-particle fill).
        std::vector<int32_t> inside(static_cast<std::size_t>(longestRow));
        // Dynamic chunks balance the threads (a particle's cost varies with its neighbours);
        // each particle's sums are its own, so who computes it does not change the result.
#pragma omp for schedule(dynamic, 256)
        for (std::size_t a = 0; a < activeCount; ++a) {
            const int32_t i = list.active[a];
            const PairData& di = pd[i];
            const double zi = di.z, ri = di.r, hi = di.h;
            const double vzi = di.vz, vri = di.vr;
            const double rhoi = di.rho, ci = di.cs;
            const double bzzi = di.bzz, brri = di.brr, brzi = di.brz;
            const double azzi = di.azz, arri = di.arr, arzi = di.arz;
            double az = 0.0, ar = 0.0, de = 0.0;
            double lzz = 0.0, lzr = 0.0, lrz = 0.0, lrr = 0.0;
            double mzz = 0.0, mzr = 0.0, mrz = 0.0, mrr = 0.0;
            double gr = 0.0; // radial part of g = (2/rho) sum (w_pair - A) grad W ~ e_r / r
            // The axial excess of the pair weights over the area weight A_j (header comment):
            double ownExcessZ = 0.0;  // sum (w_own - A) B_i,zz dW/dz, of the own stress
            double viscExcessZ = 0.0; // -sum (w_pair - A) Pi dW/dz, of the viscosity
            double workExcessZ = 0.0; // what the energy split adds to the axial work over it
            double viscHoop = 0.0;    // sum (w_pair - A) Pi grad_r W: the viscous hoop part
            double maxMu = 0.0;
            // Pass 1: keep the listed candidates inside the support (the list reaches a Verlet
            // skin further). Branch-free, order-preserving compaction.
            const int32_t row = list.row[a];
            const int64_t k0 = list.offset[row], k1 = list.offset[row + 1];
            std::size_t count = 0;
            for (int64_t k = k0; k < k1; ++k) {
                const int32_t j = nb[k];
                const PairData& dj = pd[src[j]];
                const double dz = zi - dj.z;
                const double dr = ri - sgn[j] * dj.r;
                const double support = kKernelSupport * 0.5 * (hi + dj.h);
                inside[count] = j;
                count += (dz * dz + dr * dr < support * support) ? 1 : 0;
            }
            // A mirror image is among the neighbours (ghosts come last in a row).
            const bool mirrored = count > 0 && sgn[inside[count - 1]] < 0.0;
            // Pass 2: the pair terms. Each particle's own stress acts over its own
            // circumference and the neighbour's over the neighbour's: the pair force
            // m_i m_j (B_i / 2 pi r_i + B_j / 2 pi r_j) . grad W is antisymmetric (z-momentum is
            // exact) and its axial part is the area-weighted, consistent one even at the axis.
            const double ownPerMass = axi ? inv2Pi / ri : 1.0; // w_own = m_j / (2 pi r_i)
            for (std::size_t k = 0; k < count; ++k) {
                const int32_t j = inside[k];
                const int32_t s = src[j];
                const PairData& dj = pd[s];
                const double sg = sgn[j];
                const double dz = zi - dj.z;
                const double dr = ri - sg * dj.r;
                const double hij = 0.5 * (hi + dj.h);
                const double dist2 = dz * dz + dr * dr;
                const double invH = 1.0 / hij;
                const double invH2 = invH * invH;
                const double q = std::sqrt(dist2) * invH;
                // grad W = kNorm f'(q)/q / h^4 * x_ij (Kernel.hpp), without the divisions.
                const double gor = Shape::kNorm * Shape::shapeDerivOverQ(q) * invH2 * invH2;
                const double wz = gor * dz, wr = gor * dr; // grad_i W_ij
                const double mj = dj.mass;
                const double areaMass = dj.areaMass;          // m_j / (2 pi r_j)
                const double wOwn = mj * ownPerMass;          // m_j / (2 pi r_i)
                const double wPair = 0.5 * (wOwn + areaMass); // the symmetric viscous weight
                const double vzj = dj.vz, vrj = sg * dj.vr;
                const double dvz = vzi - vzj, dvr = vri - vrj;
                // Artificial viscosity for approaching pairs.
                double visc = 0.0;
                const double dot = dvz * dz + dvr * dr;
                if (dot < 0.0) {
                    const double mu = hij * dot / (dist2 + eta2 * hij * hij);
                    const double cbar = 0.5 * (ci + dj.cs);
                    const double rhobar = 0.5 * (rhoi + dj.rho);
                    visc = (-alpha * cbar * mu + beta * mu * mu) / rhobar;
                    maxMu = std::max(maxMu, -mu);
                }
                double ozz = bzzi, orr = brri, orz = brzi;            // own
                double nzz = dj.bzz, nrr = dj.brr, nrz = sg * dj.brz; // neighbour's
                if constexpr (kArtificialStress) {
                    const double f = Shape::shape(q) * invShapeAtSpacing;
                    const double f2 = f * f;
                    const double fn = f2 * f2; // n = 4 (Gray, Monaghan & Swift 2001)
                    ozz += fn * azzi;
                    orr += fn * arri;
                    orz += fn * arzi;
                    nzz += fn * dj.azz;
                    nrr += fn * dj.arr;
                    nrz += fn * sg * dj.arz;
                }
                const double ownZ = ozz * wz + orz * wr, ownR = orz * wz + orr * wr;
                const double nbrZ = nzz * wz + nrz * wr, nbrR = nrz * wz + nrr * wr;
                az += wOwn * ownZ + areaMass * nbrZ - wPair * visc * wz;
                ar += wOwn * ownR + areaMass * nbrR - wPair * visc * wr;
                // Particle i's share of the pair's work (the compatible energy split). The
                // stress part of the pair's work is m_i m_j (B_i / 2 pi r_i + B_j / 2 pi r_j) :
                // v_ij grad W; i takes m_i A_j B_i of it and j takes m_j A_i B_j, and each half
                // the remainder m_i m_j (1 / 2 pi r_i - 1 / 2 pi r_j)(B_i - B_j), which is small
                // (a stress difference times a radius difference). Exact per pair. Taking
                // instead the whole own-stress part (weight w_own) heated the first column 1.49
                // times as fast as its row under a uniform compression: next to the axis
                // w_own sums the mirror images' |r|, not their signed r. The viscous work is
                // halved between the pair as before: split with the area weights too, the
                // cylindrical Noh shock ran 10 % ahead instead of 3 %.
                const double halfExcess = 0.5 * (wOwn - areaMass);
                de -= wPair * (dvz * ownZ + dvr * ownR) - halfExcess * (dvz * nbrZ + dvr * nbrR) -
                      wPair * 0.5 * visc * (dvz * wz + dvr * wr);
                // Velocity gradient and its linear correction matrix.
                const double vol = dj.volume;
                lzz -= vol * dvz * wz;
                lzr -= vol * dvz * wr;
                lrz -= vol * dvr * wz;
                lrr -= vol * dvr * wr;
                mzz -= vol * dz * wz;
                mzr -= vol * dz * wr;
                mrz -= vol * dr * wz;
                mrr -= vol * dr * wr;
                if (axi) {
                    const double excess = (wPair - areaMass) * wr;
                    gr += excess;
                    viscHoop += excess * visc;
                    if (mirrored) {
                        ownExcessZ += (wOwn - areaMass) * ozz * wz;
                        viscExcessZ -= (wPair - areaMass) * visc * wz;
                        workExcessZ +=
                            (halfExcess * (ozz - nzz) - 0.5 * (wPair - areaMass) * visc) * dvz * wz;
                    }
                }
            }
            // Corrected gradient L M^-1 where M is well conditioned (enough neighbours around);
            // otherwise the raw estimate (an isolated particle or a lone pair).
            const double det = mzz * mrr - mzr * mrz;
            if (std::fabs(det) > 0.01) {
                const double izz = mrr / det, izr = -mzr / det, irz = -mrz / det, irr = mzz / det;
                const double czz = lzz * izz + lzr * irz, czr = lzz * izr + lzr * irr;
                const double crz = lrz * izz + lrr * irz, crr = lrz * izr + lrr * irr;
                lzz = czz;
                lzr = czr;
                lrz = crz;
                lrr = crr;
            }
            double hoopRate = 0.0;
            if (axi) {
                const double grr = 2.0 * gr / rhoi;
                // D_thth = v_r / r, the exact rate of a ring's circumference, except where the
                // neighbourhood cannot hold a hoop stress (g_r < 1/r: a particle with few
                // neighbours, e.g. a lone debris particle near the axis): there it follows
                // the hoop force's g_r, so a ring cannot be compressed by converging motion
                // that no hoop stress resists.
                hoopRate = vri * std::min(std::max(grr, 0.0), 1.0 / ri);
                const double sThTh = strength ? -(ps.szz[i] + ps.srr[i]) : 0.0;
                const double sigmaThTh = sThTh - ps.p[i];
                // The radial hoop force. It has no axial part: an axial force on one particle
                // would break the pairwise cancellation that conserves z-momentum, and no
                // antisymmetric pair term can stand in for it (docs/formulation.md).
                const double hoopR = -(sigmaThTh / rhoi) * grr;
                // The viscous stress's hoop part. The pair-weighted viscous sum gives the
                // in-plane viscous stress its cylindrical divergence term sigma_rr^v / r, which
                // only a hoop stress sigma_thth^v can balance. The pair viscosity has a
                // sigma_rr^v even where nothing is compressed radially (the diagonal pairs of a
                // compression along z); r and theta are then both transverse and equivalent,
                // so sigma_thth^v = sigma_rr^v, which sum (w_pair - A) Pi grad_r W adds exactly.
                // Without it a plate's impact shock pulled particles towards the axis with a
                // force growing as 1/r and held the first particle column on the axis
                // (tests/unit/sph/AxisForces_test.cpp). Where the flow is compressed
                // radially (a converging shock, as in the Noh problem) sigma_rr^v is that
                // compression's own viscous stress and the hoop direction need not share it,
                // so the hoop part fades with the radial share of the in-plane compression.
                const double compressZ = std::max(-lzz, 0.0);
                const double compressR = std::max(-lrr, 0.0);
                const double compressMax = std::max(compressZ, compressR);
                const double hoopShare = compressMax > 0.0 ? 1.0 - compressR / compressMax : 1.0;
                const double hoopViscR = hoopShare * viscHoop;
                // The own-stress part of the pair sum, B_i . sum (w_own - A) grad W = B_i . (rho g)
                // with g ~ e_r / r, is the cylindrical divergence's sigma_rr / (rho r) and
                // sigma_rz / (rho r); the neighbours' part is area-weighted, so no second
                // moment of the stress differences enters the force (docs/formulation.md).
                ar += hoopR + hoopViscR;
                de -= vri * (hoopR + hoopViscR);
                // Next to the axis the axial sums are the area-weighted ones (header
                // comment): the own and viscous excess over them is taken off, and its work
                // with it (the work split's remainder and the viscous work beyond A_j, both
                // along z), so the particle heats as its row does. Only an awake
                // particle: one at rest and unstressed can only have a viscous excess, from a
                // neighbour closing in, and skipping dormant particles must not change it.
                if (mirrored && isAwake(ps, i)) {
                    az -= ownExcessZ + viscExcessZ;
                    de += workExcessZ;
                }
            }
            rates.az[i] += az;
            rates.ar[i] += ar;
            rates.de[i] += de;
            const double divergence = lzz + lrr;
            rates.drho[i] += -rhoi * (divergence + hoopRate);
            rates.dh[i] += 0.5 * hi * divergence;
            rates.dvzDz[i] = lzz;
            rates.dvzDr[i] = lzr;
            rates.dvrDz[i] = lrz;
            rates.dvrDr[i] = lrr;
            rates.hoopRate[i] = hoopRate;
            // Equivalent strain rate sqrt(2/3 e':e') of the deviatoric strain rate.
            const double mean = (lzz + lrr + hoopRate) / 3.0;
            const double ezz = lzz - mean, err = lrr - mean, ett = hoopRate - mean;
            const double ezr = 0.5 * (lzr + lrz);
            rates.strainRate[i] =
                std::sqrt((2.0 / 3.0) * (ezz * ezz + err * err + ett * ett + 2.0 * ezr * ezr));
            // Time-step vote. The Courant condition bounds how far a signal crosses between
            // neighbours in a step, so a particle with no neighbour inside its support (a lone
            // debris particle, whose sound speed may be that of a strongly shocked state)
            // sets none: it only must not cross its own support in a step, which could carry
            // it past a particle it has not met yet (dt <= h / |v|; FE surfaces have their
            // own vote in contact).
            double dtI = std::numeric_limits<double>::infinity();
            if (count > 0) {
                const double signal = ci + 1.2 * (alpha * ci + beta * maxMu);
                if (signal > 0.0) {
                    dtI = hi / signal;
                }
            } else {
                const double speed = std::sqrt(vzi * vzi + vri * vri);
                if (speed > 0.0) {
                    dtI = hi / speed;
                }
            }
            const double acc = std::sqrt(az * az + ar * ar);
            if (acc > 0.0) {
                dtI = std::min(dtI, std::sqrt(hi / acc));
            }
            if (dtI < local.dt || (dtI == local.dt && i < local.particle)) {
                local.dt = dtI;
                local.particle = i;
            }
        }
        threadVotes[static_cast<std::size_t>(omp_get_thread_num())] = local;
    }
    for (const auto& v : threadVotes) {
        if (v.particle >= 0 &&
            (v.dt < vote.dt || (v.dt == vote.dt && v.particle < vote.particle))) {
            vote = v;
        }
    }
}

} // namespace

void SphHydro::evaluate(const ParticleSet& ps, const NeighbourList& list, ParticleRates& rates,
                        const std::vector<int32_t>* changed) {
    const std::size_t n = ps.size();
    if (m_data.size() != n) {
        m_data.resize(n);
        changed = nullptr; // nothing packed yet
    }
    const bool axi = m_options.axisymmetric;
    const double inv2Pi = 1.0 / (2.0 * units::kPi);
    const bool strength = ps.hasStrength();
    // Everything a neighbour contributes, packed per particle: a neighbour costs two cache
    // lines instead of a line from each of thirteen arrays. Only what changed is repacked.
    const std::size_t count = changed ? changed->size() : n;
#pragma omp parallel for schedule(static) if (count > kParallelMinItems)
    for (std::size_t k = 0; k < count; ++k) {
        const std::size_t i = changed ? static_cast<std::size_t>((*changed)[k]) : k;
        PairData& d = m_data[i];
        const double inv = 1.0 / (ps.rho[i] * ps.rho[i]);
        const double szz = strength ? ps.szz[i] : 0.0;
        const double srr = strength ? ps.srr[i] : 0.0;
        const double srz = strength ? ps.srz[i] : 0.0;
        d.z = ps.z[i];
        d.r = ps.r[i];
        d.h = ps.h[i];
        d.mass = ps.mass[i];
        d.vz = ps.vz[i];
        d.vr = ps.vr[i];
        d.rho = ps.rho[i];
        d.cs = ps.cs[i];
        d.bzz = (szz - ps.p[i]) * inv;
        d.brr = (srr - ps.p[i]) * inv;
        d.brz = srz * inv;
        d.azz = d.arr = d.arz = 0.0;
        if (m_options.artificialStress > 0.0) {
            // Principal in-plane stresses and their direction; only tension is opposed.
            const double a = szz - ps.p[i], c = srr - ps.p[i], b = srz;
            const double mean = 0.5 * (a + c), half = 0.5 * (a - c);
            const double radius = std::sqrt(half * half + b * b);
            const double s1 = mean + radius, s2 = mean - radius;
            const double theta = 0.5 * std::atan2(b, half);
            const double co = std::cos(theta), si = std::sin(theta);
            const double eps = m_options.artificialStress * inv;
            const double r1 = s1 > 0.0 ? -eps * s1 : 0.0;
            const double r2 = s2 > 0.0 ? -eps * s2 : 0.0;
            d.azz = r1 * co * co + r2 * si * si;
            d.arr = r1 * si * si + r2 * co * co;
            d.arz = (r1 - r2) * si * co;
        }
        // Area mass A = m / (2 pi r) and area V = A / rho in the (z, r) plane.
        d.areaMass = axi ? ps.mass[i] * inv2Pi / ps.r[i] : ps.mass[i];
        d.volume = d.areaMass / ps.rho[i];
    }
    StepVote vote;
    withKernel(m_options.kernel, [&](auto kernel) {
        using Kern = decltype(kernel);
        if (m_options.artificialStress > 0.0) {
            evaluatePairs<Kern, true>(ps, list, m_options, m_data, rates, vote);
        } else {
            evaluatePairs<Kern, false>(ps, list, m_options, m_data, rates, vote);
        }
    });
    m_stableDt = vote.dt;
    m_limitingParticle = vote.particle;
}

} // namespace hvi::sph
