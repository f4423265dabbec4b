#include "sph/SphHydro.hpp"

#include "core/Lanes.hpp"
#include "core/Parallel.hpp"
#include "core/Units.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <omp.h>
#include <type_traits>

namespace hvi::sph {

namespace {

/// Neighbours whose densities differ by more than this factor are a density contrast a
/// shock in a solid seldom makes between neighbours (Al on Al compresses 1.5 times at 7 km/s
/// and 1.9 times at 15 km/s, across a front some three smoothing lengths wide) but
/// fragmented debris does (expanded particles at 0.05-0.4 rho0 beside compressed ones);
/// there a solid takes the pairwise density rate
/// (HydroOptions::pairwiseContinuityAtContrast).
constexpr double kDensityContrast = 1.5;

struct StepVote {
    double dt = std::numeric_limits<double>::infinity();
    int32_t particle = -1;
};

/// The pair loop's lanes: four doubles of a 256-bit vector (core/Lanes.hpp).
constexpr std::size_t kPairLanes = 4;

// The pair loop is split into steps that the compiler inlines into one loop body (so the
// sums, their order and their floating-point contraction are those of a single function).
#define HVI_INLINE [[gnu::always_inline]] inline

/// The artificial viscosity's coefficients and the kernel's normalisations, per evaluation.
struct PairCoefficients {
    double alpha, beta, eta2; ///< Monaghan viscosity
    double invShapeAtSpacing; ///< 1 / f(spacing / h), the artificial stress's reference
};

/// What one particle's pair loop sums, and its own per-particle weights.
struct PairSums {
    double az = 0.0, ar = 0.0, de = 0.0;
    double lzz = 0.0, lzr = 0.0, lrz = 0.0, lrr = 0.0; // velocity gradient
    double mzz = 0.0, mzr = 0.0, mrz = 0.0, mrr = 0.0; // its linear correction matrix
    double gr = 0.0; // radial part of g = (2/rho) sum (w_pair - A) grad W ~ e_r / r
    // The axial excess of the pair weights over the area weight A_j (header comment):
    double ownExcessZ = 0.0;  // sum (w_own - A) B_i,zz dW/dz, of the own stress
    double viscExcessZ = 0.0; // -sum (w_pair - A) Pi dW/dz, of the viscosity
    double workExcessZ = 0.0; // what the energy split adds to the axial work over it
    double viscHoop = 0.0;    // sum (w_pair - A) Pi grad_r W: the viscous hoop part
    double hoopPower = 0.0;   // the hoop force's heating per unit v_r (sph/PairWork.hpp)
    double maxMu = 0.0;
    double pairDivergence = 0.0; // sum A_j v_ij . grad W: the density rate the energy pays for
    bool contrast = false;       // a neighbour's density differs by more than kDensityContrast
};

/// A particle's neighbours inside its support: the particle each stands for and its sign (-1:
/// the mirror image across the axis), contiguous for the pair loop.
struct InsideNeighbours {
    std::vector<int32_t> source;
    std::vector<double> sign;
    explicit InsideNeighbours(std::size_t capacity)
        : source(capacity + kPairLanes), sign(capacity + kPairLanes) {}
};

/// Pass 1: keeps the listed candidates of row `row` inside the support of particle `i` (the
/// list reaches a Verlet skin further) in `inside`; returns their count. Branch-free,
/// order-preserving compaction. The list is then padded to a multiple of kPairLanes with the
/// particle itself, a pair whose every term is zero (no separation and no relative velocity),
/// so the vectorised loop needs no scalar remainder.
HVI_INLINE std::size_t keepInside(const NeighbourList& list, int32_t row, int32_t i,
                                  const PairData* pd, InsideNeighbours& inside) {
    const auto* src = list.source.data();
    const auto* sgn = list.sign.data();
    const auto* nb = list.neighbours.data();
    const PairData& di = pd[i];
    const int64_t k0 = list.offset[row], k1 = list.offset[row + 1];
    std::size_t count = 0;
    for (int64_t k = k0; k < k1; ++k) {
        const int32_t j = nb[k];
        const int32_t sj = src[j];
        const PairData& dj = pd[sj];
        const double dz = di.z - dj.z;
        const double dr = di.r - sgn[j] * dj.r;
        const double support = kKernelSupport * 0.5 * (di.h + dj.h);
        inside.source[count] = sj;
        inside.sign[count] = sgn[j];
        count += (dz * dz + dr * dr < support * support) ? 1 : 0;
    }
    for (std::size_t k = count; k % kPairLanes != 0; ++k) {
        inside.source[k] = i;
        inside.sign[k] = 1.0;
    }
    return count;
}

/// A neighbour's record as the pair body reads it: one neighbour (V = double) or four lanes
/// of four neighbours (V = Lanes4), with its mirror sign.
template <class V>
struct Neighbour {
    V z, r, h, mass, vz, vr, rho, cs, bzz, brr, brz, areaMass, volume, azz, arr, arz, sign;
};

HVI_INLINE Neighbour<double> neighbourAt(const PairData* pd, const InsideNeighbours& inside,
                                         std::size_t k) {
    const PairData& d = pd[static_cast<std::size_t>(inside.source[k])];
    return {d.z,   d.r,   d.h,        d.mass,   d.vz,  d.vr,  d.rho, d.cs,          d.bzz,
            d.brr, d.brz, d.areaMass, d.volume, d.azz, d.arr, d.arz, inside.sign[k]};
}

#if HVI_HAVE_LANES4
static_assert(sizeof(PairData) == 16 * sizeof(double) && alignof(PairData) >= 32 &&
                  offsetof(PairData, vz) == 4 * sizeof(double) &&
                  offsetof(PairData, bzz) == 8 * sizeof(double) &&
                  offsetof(PairData, volume) == 12 * sizeof(double),
              "a neighbour record is four aligned groups of four doubles, in neighboursAt's order");

/// Neighbours k to k+3: each record loaded as four 256-bit groups and four records
/// transposed at once, a field to a vector (eight shuffles for four fields of four lanes,
/// where a lane-by-lane gather takes four loads and three inserts for each field).
HVI_INLINE Neighbour<Lanes4> neighboursAt(const PairData* pd, const InsideNeighbours& inside,
                                          std::size_t k) {
    const double* rec[kPairLanes];
    for (std::size_t l = 0; l < kPairLanes; ++l) {
        rec[l] = &pd[static_cast<std::size_t>(inside.source[k + l])].z;
    }
    // Group g of the four records (doubles 4g to 4g+3 of each), one field a vector.
    const auto group = [&rec](std::size_t g, Lanes4& a, Lanes4& b, Lanes4& c, Lanes4& d) {
        a = Lanes4(_mm256_load_pd(rec[0] + 4 * g));
        b = Lanes4(_mm256_load_pd(rec[1] + 4 * g));
        c = Lanes4(_mm256_load_pd(rec[2] + 4 * g));
        d = Lanes4(_mm256_load_pd(rec[3] + 4 * g));
        transpose4(a, b, c, d);
    };
    Neighbour<Lanes4> n;
    group(0, n.z, n.r, n.h, n.mass);
    group(1, n.vz, n.vr, n.rho, n.cs);
    group(2, n.bzz, n.brr, n.brz, n.areaMass);
    group(3, n.volume, n.azz, n.arr, n.arz);
    n.sign = Lanes4(_mm256_loadu_pd(inside.sign.data() + k));
    return n;
}
#endif

/// The pair loop's running sums, one per lane.
template <class V>
struct PairAccumulators {
    V az = 0.0, ar = 0.0, de = 0.0, lzz = 0.0, lzr = 0.0, lrz = 0.0, lrr = 0.0;
    V mzz = 0.0, mzr = 0.0, mrz = 0.0, mrr = 0.0, gr = 0.0, viscHoop = 0.0;
    V ownExcessZ = 0.0, viscExcessZ = 0.0, workExcessZ = 0.0, pairDivergence = 0.0;
    V maxMu = 0.0;
    V contrast = 0.0; // 1 where a neighbour's density stands out
};

/// One pair's share of particle i's heating per unit relative velocity, by component, or four
/// pairs' (sph/PairWork.hpp): what the pair adds to de_i/dt is gz dv_z + gr dv_r.
template <class V>
struct PairWorkLanes {
    V gz = 0.0, gr = 0.0;
};

/// One pair (i, j), or four, with j mirrored where its sign is -1. Each particle's own stress
/// acts over its own circumference and the neighbour's over the neighbour's: the pair force
/// m_i m_j (B_i / 2 pi r_i + B_j / 2 pi r_j) . grad W is antisymmetric (z-momentum is exact)
/// and its axial part is the area-weighted, consistent one even at the axis. The viscosity is
/// computed for every pair and kept only for approaching ones.
/// `ownPerMass`: w_own / m_j = 1 / (2 pi r_i) (planar: 1).
/// `kKeepWork`: also the pair's heating coefficients into `work` (`excessOn`: 1 where the
/// axial excess's work is taken off, addHoopTerms; else 0).
template <class Shape, bool kArtificialStress, bool kAxi, bool kMirrored, bool kKeepWork, class V>
HVI_INLINE void addPair(PairAccumulators<V>& s, PairWorkLanes<V>& work, const PairData& di,
                        const Neighbour<V>& dj, double ownPerMass, double excessOn,
                        const PairCoefficients& c) {
    const V sg = dj.sign;
    const V dz = di.z - dj.z;
    const V dr = di.r - sg * dj.r;
    const V hij = 0.5 * (di.h + dj.h);
    const V dist2 = dz * dz + dr * dr;
    const V invH = 1.0 / hij;
    const V invH2 = invH * invH;
    const V q = sqrtOf(dist2) * invH;
    // grad W = kNorm f'(q)/q / h^4 * x_ij (Kernel.hpp), without the divisions.
    const V gor = Shape::kNorm * Shape::shapeDerivOverQInSupport(q) * invH2 * invH2;
    const V wz = gor * dz, wr = gor * dr;    // grad_i W_ij
    const V areaMass = dj.areaMass;          // m_j / (2 pi r_j)
    const V wOwn = dj.mass * ownPerMass;     // m_j / (2 pi r_i)
    const V wPair = 0.5 * (wOwn + areaMass); // the symmetric viscous weight
    const V dvz = di.vz - dj.vz, dvr = di.vr - sg * dj.vr;
    // Artificial viscosity for approaching pairs (mu <= 0 there; 0 for receding ones).
    const V dot = dvz * dz + dvr * dr;
    const V muAll = hij * dot / (dist2 + c.eta2 * hij * hij);
    const V mu = selectLess(dot, V(0.0), muAll, V(0.0));
    const V cbar = 0.5 * (di.cs + dj.cs);
    const V rhobar = 0.5 * (di.rho + dj.rho);
    const V visc = (-c.alpha * cbar * mu + c.beta * mu * mu) / rhobar;
    s.maxMu = maxOf(s.maxMu, -mu);
    V ozz = di.bzz, orr = di.brr, orz = di.brz;      // own
    V nzz = dj.bzz, nrr = dj.brr, nrz = sg * dj.brz; // neighbour's
    if constexpr (kArtificialStress) {
        const V f = Shape::shapeInSupport(q) * c.invShapeAtSpacing;
        const V f2 = f * f;
        const V fn = f2 * f2; // n = 4 (Gray, Monaghan & Swift 2001)
        ozz += fn * di.azz;
        orr += fn * di.arr;
        orz += fn * di.arz;
        nzz += fn * dj.azz;
        nrr += fn * dj.arr;
        nrz += fn * sg * dj.arz;
    }
    const V ownZ = ozz * wz + orz * wr, ownR = orz * wz + orr * wr;
    const V nbrZ = nzz * wz + nrz * wr, nbrR = nrz * wz + nrr * wr;
    s.az += wOwn * ownZ + areaMass * nbrZ - wPair * visc * wz;
    s.ar += wOwn * ownR + areaMass * nbrR - wPair * visc * wr;
    // Particle i's share of the pair's work (the compatible energy split). The stress part of
    // the pair's work is m_i m_j (B_i / 2 pi r_i + B_j / 2 pi r_j) : v_ij grad W; i takes
    // m_i A_j B_i of it and j takes m_j A_i B_j, and each half the remainder
    // m_i m_j (1 / 2 pi r_i - 1 / 2 pi r_j)(B_i - B_j), which is small (a stress difference
    // times a radius difference). Exact per pair. Taking instead the whole own-stress part
    // (weight w_own) heated the first column 1.49 times as fast as its row under a uniform
    // compression: next to the axis w_own sums the mirror images' |r|, not their signed r.
    // The viscous work is halved between the pair as before: split with the area weights
    // too, the cylindrical Noh shock ran 10 % ahead instead of 3 %.
    const V halfExcess = 0.5 * (wOwn - areaMass);
    s.de -= wPair * (dvz * ownZ + dvr * ownR) - halfExcess * (dvz * nbrZ + dvr * nbrR) -
            wPair * 0.5 * visc * (dvz * wz + dvr * wr);
    if constexpr (kKeepWork) {
        // The same terms by component, and below the axial excess's work where it is taken off.
        work.gz = halfExcess * nbrZ + wPair * 0.5 * visc * wz - wPair * ownZ;
        work.gr = halfExcess * nbrR + wPair * 0.5 * visc * wr - wPair * ownR;
    }
    // The pairwise density rate, and whether this neighbour's density stands out.
    s.pairDivergence += areaMass * (dvz * wz + dvr * wr);
    s.contrast = maxOf(s.contrast, selectLess(kDensityContrast * di.rho, dj.rho, V(1.0), V(0.0)));
    s.contrast =
        maxOf(s.contrast, selectLess(kDensityContrast * dj.rho, V(di.rho), V(1.0), V(0.0)));
    // Velocity gradient and its linear correction matrix.
    const V vol = dj.volume;
    s.lzz -= vol * dvz * wz;
    s.lzr -= vol * dvz * wr;
    s.lrz -= vol * dvr * wz;
    s.lrr -= vol * dvr * wr;
    s.mzz -= vol * dz * wz;
    s.mzr -= vol * dz * wr;
    s.mrz -= vol * dr * wz;
    s.mrr -= vol * dr * wr;
    if constexpr (kAxi) {
        const V excess = (wPair - areaMass) * wr;
        s.gr += excess;
        s.viscHoop += excess * visc;
        if constexpr (kMirrored) {
            s.ownExcessZ += (wOwn - areaMass) * ozz * wz;
            s.viscExcessZ -= (wPair - areaMass) * visc * wz;
            const V excessWork = halfExcess * (ozz - nzz) - 0.5 * (wPair - areaMass) * visc;
            s.workExcessZ += excessWork * dvz * wz;
            if constexpr (kKeepWork) {
                work.gz += excessOn * (excessWork * wz);
            }
        }
    }
}

HVI_INLINE double maxLane(double x) {
    return x;
}

/// The lanes' sums, each added in one fixed order (core/Lanes.hpp).
template <class V>
HVI_INLINE PairSums reduceLanes(const PairAccumulators<V>& s) {
    PairSums sum;
    sum.az = sumOf(s.az);
    sum.ar = sumOf(s.ar);
    sum.de = sumOf(s.de);
    sum.lzz = sumOf(s.lzz);
    sum.lzr = sumOf(s.lzr);
    sum.lrz = sumOf(s.lrz);
    sum.lrr = sumOf(s.lrr);
    sum.mzz = sumOf(s.mzz);
    sum.mzr = sumOf(s.mzr);
    sum.mrz = sumOf(s.mrz);
    sum.mrr = sumOf(s.mrr);
    sum.gr = sumOf(s.gr);
    sum.ownExcessZ = sumOf(s.ownExcessZ);
    sum.viscExcessZ = sumOf(s.viscExcessZ);
    sum.workExcessZ = sumOf(s.workExcessZ);
    sum.viscHoop = sumOf(s.viscHoop);
    sum.maxMu = maxLane(s.maxMu);
    sum.pairDivergence = sumOf(s.pairDivergence);
    sum.contrast = maxLane(s.contrast) > 0.0;
    return sum;
}

/// Where the pair loop writes each pair's heating coefficients (sph/PairWork.hpp): slot
/// arrays with room for the padded row, or none.
struct WorkSlot {
    double* gz = nullptr;
    double* gr = nullptr;
    double excessOn = 0.0; ///< 1 where the axial excess's work is taken off (addHoopTerms)
};

#if HVI_HAVE_LANES4
using PairLanes = Lanes4;
#else
using PairLanes = double;
#endif

/// How many pair entries sumPairs computes for a row of `count` inside the support, `padded`
/// with null pairs: all of them four at a time, only the real ones one at a time.
HVI_INLINE std::size_t computedPairs(std::size_t count, std::size_t padded) {
    return HVI_HAVE_LANES4 ? padded : count;
}

/// Pass 2: the pair sums of particle i over its neighbours inside the support. Where the
/// build has AVX, four neighbours at a time over the `padded` entries (the padding's null
/// pairs add nothing), each lane summing its own share; otherwise one at a time. Either way
/// the order of the sums is fixed by the row, so the same build gives the same sums whatever
/// the thread count. `kKeepWork`: each pair's heating coefficients go to `slot`, one entry per
/// pair computed (padded ones included).
template <class Shape, bool kArtificialStress, bool kAxi, bool kMirrored, bool kKeepWork>
HVI_INLINE PairSums sumPairs(const PairData& di, const PairData* pd, const InsideNeighbours& inside,
                             std::size_t count, std::size_t padded, double ownPerMass,
                             const PairCoefficients& c, const WorkSlot& slot) {
    constexpr std::size_t step = HVI_HAVE_LANES4 ? kPairLanes : 1;
    PairAccumulators<PairLanes> s;
    PairWorkLanes<PairLanes> work;
    const std::size_t computed = computedPairs(count, padded);
    for (std::size_t k = 0; k < computed; k += step) {
#if HVI_HAVE_LANES4
        const Neighbour<PairLanes> dj = neighboursAt(pd, inside, k);
#else
        const Neighbour<PairLanes> dj = neighbourAt(pd, inside, k);
#endif
        addPair<Shape, kArtificialStress, kAxi, kMirrored, kKeepWork>(s, work, di, dj, ownPerMass,
                                                                      slot.excessOn, c);
        if constexpr (kKeepWork) {
            storeTo(slot.gz + k, work.gz);
            storeTo(slot.gr + k, work.gr);
        }
    }
    return reduceLanes(s);
}

/// sumPairs with the scene's geometry and the particle's mirror flag as compile-time
/// choices (the mirrored particles are few; the rest carry none of the axial-excess sums).
template <class Shape, bool kArtificialStress, bool kKeepWork>
HVI_INLINE PairSums sumPairsOf(bool axi, bool mirrored, const PairData& di, const PairData* pd,
                               const InsideNeighbours& inside, std::size_t count,
                               std::size_t padded, double ownPerMass, const PairCoefficients& c,
                               const WorkSlot& slot) {
    if (!axi) {
        return sumPairs<Shape, kArtificialStress, false, false, kKeepWork>(
            di, pd, inside, count, padded, ownPerMass, c, slot);
    }
    if (mirrored) {
        return sumPairs<Shape, kArtificialStress, true, true, kKeepWork>(
            di, pd, inside, count, padded, ownPerMass, c, slot);
    }
    return sumPairs<Shape, kArtificialStress, true, false, kKeepWork>(di, pd, inside, count,
                                                                      padded, ownPerMass, c, slot);
}

/// Corrected gradient L M^-1 where M is well conditioned (enough neighbours around);
/// otherwise the raw estimate (an isolated particle or a lone pair).
HVI_INLINE void correctGradient(PairSums& sum) {
    const double det = sum.mzz * sum.mrr - sum.mzr * sum.mrz;
    if (std::fabs(det) > 0.01) {
        const double izz = sum.mrr / det, izr = -sum.mzr / det, irz = -sum.mrz / det,
                     irr = sum.mzz / det;
        const double czz = sum.lzz * izz + sum.lzr * irz, czr = sum.lzz * izr + sum.lzr * irr;
        const double crz = sum.lrz * izz + sum.lrr * irz, crr = sum.lrz * izr + sum.lrr * irr;
        sum.lzz = czz;
        sum.lzr = czr;
        sum.lrz = crz;
        sum.lrr = crr;
    }
}

/// The axisymmetric terms of particle i: the hoop force, the viscous stress's hoop part and
/// the axial excess next to the axis, added to the sums; returns the hoop strain rate.
HVI_INLINE double addHoopTerms(PairSums& sum, const ParticleSet& ps, std::size_t i,
                               const PairData& di, bool strength, bool mirrored) {
    const double grr = 2.0 * sum.gr / di.rho;
    // D_thth = v_r / r, the exact rate of a ring's circumference, except where the
    // neighbourhood cannot hold a hoop stress (g_r < 1/r: a particle with few neighbours, e.g.
    // a lone debris particle near the axis): there it follows the hoop force's g_r, so a ring
    // cannot be compressed by converging motion that no hoop stress resists.
    const double hoopRate = di.vr * std::min(std::max(grr, 0.0), 1.0 / di.r);
    const double sThTh = strength ? -(ps.szz[i] + ps.srr[i]) : 0.0;
    const double sigmaThTh = sThTh - ps.p[i];
    // The radial hoop force. It has no axial part: an axial force on one particle would break
    // the pairwise cancellation that conserves z-momentum, and no antisymmetric pair term can
    // stand in for it (docs/formulation.md).
    const double hoopR = -(sigmaThTh / di.rho) * grr;
    // The viscous stress's hoop part. The pair-weighted viscous sum gives the in-plane viscous
    // stress its cylindrical divergence term sigma_rr^v / r, which only a hoop stress
    // sigma_thth^v can balance. The pair viscosity has a sigma_rr^v even where nothing is
    // compressed radially (the diagonal pairs of a compression along z); r and theta are then
    // both transverse and equivalent, so sigma_thth^v = sigma_rr^v, which
    // sum (w_pair - A) Pi grad_r W adds exactly. Without it a plate's impact shock pulled
    // particles towards the axis with a force growing as 1/r and held the first particle
    // column on the axis (tests/unit/sph/AxisForces_test.cpp). Where the flow is compressed
    // radially (a converging shock, as in the Noh problem) sigma_rr^v is that compression's
    // own viscous stress and the hoop direction need not share it, so the hoop part fades with
    // the radial share of the in-plane compression.
    const double compressZ = std::max(-sum.lzz, 0.0);
    const double compressR = std::max(-sum.lrr, 0.0);
    const double compressMax = std::max(compressZ, compressR);
    const double hoopShare = compressMax > 0.0 ? 1.0 - compressR / compressMax : 1.0;
    const double hoopViscR = hoopShare * sum.viscHoop;
    // The own-stress part of the pair sum, B_i . sum (w_own - A) grad W = B_i . (rho g) with
    // g ~ e_r / r, is the cylindrical divergence's sigma_rr / (rho r) and sigma_rz / (rho r);
    // the neighbours' part is area-weighted, so no second moment of the stress differences
    // enters the force (docs/formulation.md).
    sum.ar += hoopR + hoopViscR;
    sum.de -= di.vr * (hoopR + hoopViscR);
    sum.hoopPower = -(hoopR + hoopViscR);
    // Next to the axis the axial sums are the area-weighted ones (header comment): the own
    // and viscous excess over them is taken off, and its work with it (the work split's
    // remainder and the viscous work beyond A_j, both along z), so the particle heats as its
    // row does. Only an awake particle: one at rest and unstressed can only have a viscous
    // excess, from a neighbour closing in, and skipping dormant particles must not change it.
    if (mirrored && isAwake(ps, i)) {
        sum.az -= sum.ownExcessZ + sum.viscExcessZ;
        sum.de += sum.workExcessZ;
    }
    return hoopRate;
}

/// `pairwiseAtContrast`: particle i's body takes the pairwise density rate where its
/// neighbours' densities stand out (HydroOptions::pairwiseContinuityAtContrast).
HVI_INLINE void storeRates(ParticleRates& rates, std::size_t i, const PairSums& sum,
                           const PairData& di, double hoopRate, bool pairwiseAtContrast) {
    rates.az[i] += sum.az;
    rates.ar[i] += sum.ar;
    rates.de[i] += sum.de;
    const double divergence = sum.lzz + sum.lrr;
    rates.drho[i] += (pairwiseAtContrast && sum.contrast) ? sum.pairDivergence - di.rho * hoopRate
                                                          : -di.rho * (divergence + hoopRate);
    rates.dh[i] += 0.5 * di.h * divergence;
    rates.dvzDz[i] = sum.lzz;
    rates.dvzDr[i] = sum.lzr;
    rates.dvrDz[i] = sum.lrz;
    rates.dvrDr[i] = sum.lrr;
    rates.hoopRate[i] = hoopRate;
    // Equivalent strain rate sqrt(2/3 e':e') of the deviatoric strain rate.
    const double mean = (sum.lzz + sum.lrr + hoopRate) / 3.0;
    const double ezz = sum.lzz - mean, err = sum.lrr - mean, ett = hoopRate - mean;
    const double ezr = 0.5 * (sum.lzr + sum.lrz);
    rates.strainRate[i] =
        std::sqrt((2.0 / 3.0) * (ezz * ezz + err * err + ett * ett + 2.0 * ezr * ezr));
}

/// Particle i's time-step vote. The Courant condition bounds how far a signal crosses between
/// neighbours in a step, so a particle with no neighbour inside its support (a lone debris
/// particle, whose sound speed may be that of a strongly shocked state) sets none: it only
/// must not cross its own support in a step, which could carry it past a particle it has not
/// met yet (dt <= h / |v|; FE surfaces have their own vote in contact).
HVI_INLINE double particleStep(const PairSums& sum, const PairData& di, std::size_t count,
                               const PairCoefficients& c) {
    double dtI = std::numeric_limits<double>::infinity();
    if (count > 0) {
        const double signal = di.cs + 1.2 * (c.alpha * di.cs + c.beta * sum.maxMu);
        if (signal > 0.0) {
            dtI = di.h / signal;
        }
    } else {
        const double speed = std::sqrt(di.vz * di.vz + di.vr * di.vr);
        if (speed > 0.0) {
            dtI = di.h / speed;
        }
    }
    const double acc = std::sqrt(sum.az * sum.az + sum.ar * sum.ar);
    if (acc > 0.0) {
        dtI = std::min(dtI, std::sqrt(di.h / acc));
    }
    return dtI;
}

/// The longest neighbour row of the active particles (the size of the per-thread scratch).
int64_t longestRow(const NeighbourList& list) {
    int64_t longest = 0;
    for (std::size_t a = 0; a < list.active.size(); ++a) {
        const int32_t row = list.row[a];
        longest = std::max(longest, list.offset[row + 1] - list.offset[row]);
    }
    return longest;
}

/// `kArtificialStress`: the artificial-stress terms are compiled in (chosen once per scene, so
/// the default path carries no per-pair test).
/// `kKeepWork`: every pair's heating coefficients go to `work`, laid out for `list`.
template <class Kern, bool kArtificialStress, bool kKeepWork>
void evaluatePairs(const ParticleSet& ps, const NeighbourList& list, const HydroOptions& opt,
                   const std::vector<PairData>& data, ParticleRates& rates, double* steps,
                   StepVote& vote, PairCounts& pairs, PairWork* work,
                   const std::vector<int32_t>* slots) {
    using Shape = typename Kern::ShapeType;
    const bool axi = opt.axisymmetric;
    const bool strength = ps.hasStrength();
    const PairCoefficients coeff{opt.avAlpha, opt.avBeta, opt.avEta2,
                                 1.0 / Shape::shape(opt.spacingOverH)};
    const double inv2Pi = 0.5 / units::kPi;
    const std::size_t activeCount = slots ? slots->size() : list.active.size();
    const PairData* pd = data.data();
    const auto pairwiseAtContrast = [&](std::size_t i) {
        const auto b = static_cast<std::size_t>(ps.body[i]);
        return b < opt.pairwiseContinuityAtContrast.size() &&
               opt.pairwiseContinuityAtContrast[b] != 0;
    };

    // Thread-local vote, combined in a fixed order afterwards (min is order-independent,
    // ties broken by the lowest particle index, so the result is thread-count independent).
    std::vector<StepVote> threadVotes(static_cast<std::size_t>(omp_get_max_threads()));
    std::vector<PairCounts> threadPairs(threadVotes.size());
    const int64_t rowCapacity = longestRow(list);
#pragma omp parallel if (activeCount > kParallelMinHeavyItems)
    {
        StepVote local;
        PairCounts localPairs;
        // This particle's neighbours within the support (sized once: no per-particle fill).
        InsideNeighbours inside(static_cast<std::size_t>(rowCapacity));
        // Dynamic chunks balance the threads (a particle's cost varies with its neighbours);
        // each particle's sums are its own, so who computes it does not change the result.
#pragma omp for schedule(dynamic, 256)
        for (std::size_t s = 0; s < activeCount; ++s) {
            const std::size_t a = slots ? static_cast<std::size_t>((*slots)[s]) : s;
            const int32_t i = list.active[a];
            const PairData& di = pd[i];
            const std::size_t count = keepInside(list, list.row[a], i, pd, inside);
            const std::size_t padded = (count + kPairLanes - 1) / kPairLanes * kPairLanes;
            localPairs.inside += count;
            localPairs.computed += padded;
            // A mirror image is among the neighbours (ghosts come last in a row).
            const bool mirrored = count > 0 && inside.sign[count - 1] < 0.0;
            const double ownPerMass = axi ? inv2Pi / di.r : 1.0; // w_own = m_j / (2 pi r_i)
            WorkSlot slot;
            if constexpr (kKeepWork) {
                slot = {work->gz(a), work->gr(a),
                        mirrored && axi && isAwake(ps, static_cast<std::size_t>(i)) ? 1.0 : 0.0};
            }
            PairSums sum = sumPairsOf<Shape, kArtificialStress, kKeepWork>(
                axi, mirrored, di, pd, inside, count, padded, ownPerMass, coeff, slot);
            correctGradient(sum);
            const double hoopRate =
                axi ? addHoopTerms(sum, ps, static_cast<std::size_t>(i), di, strength, mirrored)
                    : 0.0;
            if constexpr (kKeepWork) {
                const std::size_t kept = computedPairs(count, padded);
                std::copy_n(inside.source.data(), kept, work->source(a));
                std::copy_n(inside.sign.data(), kept, work->sign(a));
                work->close(a, i, kept, sum.hoopPower);
            }
            storeRates(rates, static_cast<std::size_t>(i), sum, di, hoopRate,
                       pairwiseAtContrast(static_cast<std::size_t>(i)));
            const double dtI = particleStep(sum, di, count, coeff);
            steps[a] = dtI;
            if (dtI < local.dt || (dtI == local.dt && i < local.particle)) {
                local.dt = dtI;
                local.particle = i;
            }
        }
        threadVotes[static_cast<std::size_t>(omp_get_thread_num())] = local;
        threadPairs[static_cast<std::size_t>(omp_get_thread_num())] = localPairs;
    }
    for (const auto& c : threadPairs) {
        pairs.inside += c.inside;
        pairs.computed += c.computed;
    }
    for (const auto& v : threadVotes) {
        if (v.particle >= 0 &&
            (v.dt < vote.dt || (v.dt == vote.dt && v.particle < vote.particle))) {
            vote = v;
        }
    }
}

#undef HVI_INLINE

} // namespace

void SphHydro::evaluate(const ParticleSet& ps, const NeighbourList& list, ParticleRates& rates,
                        const std::vector<int32_t>* changed, const std::vector<int32_t>* slots) {
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
    m_pairs = PairCounts{};
    m_particleSteps.resize(list.active.size());
    double* steps = m_particleSteps.data();
    withKernel(m_options.kernel, [&](auto kernel) {
        using Kern = decltype(kernel);
        const auto run = [&](auto stress, auto keep) {
            evaluatePairs<Kern, decltype(stress)::value, decltype(keep)::value>(
                ps, list, m_options, m_data, rates, steps, vote, m_pairs, &m_work, slots);
        };
        const bool stress = m_options.artificialStress > 0.0;
        if (m_options.keepPairWork) {
            m_work.layOut(list, kPairLanes);
            stress ? run(std::true_type{}, std::true_type{})
                   : run(std::false_type{}, std::true_type{});
        } else {
            stress ? run(std::true_type{}, std::false_type{})
                   : run(std::false_type{}, std::false_type{});
        }
    });
    m_stableDt = vote.dt;
    m_limitingParticle = vote.particle;
}

} // namespace hvi::sph
