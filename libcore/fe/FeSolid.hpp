// The Lagrange finite-element package: 4-node quadrilaterals with one-point integration,
// viscous hourglass control, artificial bulk viscosity and erosion, sharing the material
// pipeline (material::MaterialPackage) with the SPH particles.
//
// One update, inside the time loop's kick-drift-kick step (central difference, Hallquist,
// LS-DYNA Theory Manual section 2): the nodes have drifted to x^{n+1} with the half-step
// velocities v^{n+1/2}; update() then
//   1. forms the velocity gradient at the mid-step geometry x^{n+1/2} = x^{n+1} - dt/2 v,
//      with the hoop rate D_thth = mean(v_r) / mean(r) (axisymmetric);
//   2. density from the exact swept volume, rho = m / V (as rho0 V0 / V), V = 2 pi integral(r dA)
//   (mass is
//      conserved per element by construction);
//   3. deviator: Jaumann rate, radial return and Johnson-Cook damage (material::MaterialPackage);
//   4. energy: e^{n+1} = e^n - (p-bar + q) dV/m + dt S-bar:D V-bar/m, with p-bar the mean of
//      the start and a predicted end pressure (one predictor pass of the EOS), so the
//      pressure work is second-order accurate;
//   5. erosion (below);
//   6. nodal forces at x^{n+1}: f_a = -V (B_a^T sigma) - V sigma_thth / (4 r-bar) e_r, plus
//      the viscous hourglass force (Flanagan & Belytschko 1981, eq. 51 in 2D form)
//      f_a = -c_hg (sum_b gamma_b v_b) gamma_a, c_hg = kappa rho c V / (4 sqrt(A)), whose
//      dissipated power goes back into the element's internal energy, so energy is conserved.
// Artificial bulk viscosity (von Neumann-Richtmyer quadratic + Landshoff linear, as LS-DYNA):
//   q = rho l (C_Q l (tr D)^2 - C_L c tr D) for tr D < 0, else 0;  l = sqrt(A).
// Time step (LS-DYNA Theory Manual eq. 22.6 in 2D): dt_e = l_e / (Q + sqrt(Q^2 + c^2)),
//   Q = C_Q l |tr D| + C_L c for compression (else 0), l_e = A / longest diagonal.
// Erosion (ANSYS Autodyn's geometric-strain erosion, the source study's calibrated rule): an
// element is removed when its geometric strain exceeds the body's erosion factor, when it has
// failed completely, when it inverts or folds over at a corner (a corner turning clockwise:
// the energy error of a 2.2 km/s perforation rose from 2.3 % to 8.4 % while such elements
// stayed), or when it is crushed past its equation of state's range (the particles' density
// ceiling; an hourglassed element's mean strain need not show it). The geometric strain is by
// default the equivalent logarithmic strain of its current shape (fe/ErosionStrain.hpp), optionally
// the accumulated integral(sqrt(2/3 D':D') dt), which also counts elastic ringing. Failed
// completely: Johnson-Cook damage 1 *and* expanded below the stress cut-off density, so that it
// carries no stress at all. A failed element (no deviator, no tension) that is still compact
// carries pressure and stays, as failed SPH particles do: with the thesis constants the failure
// strain falls to its 0.01 floor at high triaxiality, so erosion at D = 1 alone deleted every
// element a small fragment's stress pulse put into triaxial tension (the axis elements of a thin
// rear wall hit by 3e-4 mg free nodes), which made the geometric-strain factor, the rule the study
// calibrated, nearly irrelevant. What becomes of an eroded element is the caller's choice
// (FeOptions::erodedBecomeParticles): either it becomes an SPH particle
// (solver/ErodedParticles.hpp, which takes its mass off the nodes), or its mass stays on its nodes
// and its internal energy leaves the calculation, booked in the ledger (erodedEnergy); a node left
// with no alive element is then a free mass point that keeps its momentum and still takes part in
// contact. Dormant elements (all nodes at rest, no pressure, no deviator) have exactly zero rates
// and forces, and are skipped (the same "compute only what the scene needs" rule as SPH). An
// element wakes when one of its nodes first moves and is evaluated from then on, so the
// selection costs a pass over the nodes not yet moving, not a test of every element.
//
// Units: mm, us, mg (km/s, GPa, g/cm^3, MJ/kg; force mg mm/us^2 = kN, energy J).
#pragma once

#include "fe/ElementRates.hpp"
#include "fe/ErosionStrain.hpp"
#include "fe/FeMesh.hpp"
#include "material/MaterialPackage.hpp"

#include <cstdint>
#include <limits>
#include <span>
#include <vector>

namespace hvi::fe {

struct FeOptions {
    bool axisymmetric = true;
    double hourglassCoefficient = 0.1; ///< kappa [-]
    double bulkLinear = 0.06;          ///< C_L [-]
    double bulkQuadratic = 1.5;        ///< C_Q [-]
    /// Eroded elements are handed to the caller (erodedThisUpdate()) to become SPH
    /// particles, which take their mass and energy; otherwise their mass stays on the nodes
    /// and their internal energy goes to the eroded-energy ledger.
    bool erodedBecomeParticles = false;
    /// Skip dormant elements (exact; off only for tests that check it).
    bool skipDormant = true;
    /// The geometric strain that erosion tests: the current strain (true,
    /// fe/ErosionStrain.hpp), or the integral of the equivalent strain rate (false).
    bool instantaneousErosionStrain = true;
};

class FeSolid {
public:
    /// Takes the meshed nodes and elements. `erosionFactor[b]` is body b's erosion strain
    /// (scene bodies; ignored for bodies without elements).
    FeSolid(FeOptions options, NodeSet nodes, ElementSet elements,
            std::vector<double> erosionFactor);

    /// Advances the element state over dt [us] with the nodes at x^{n+1} carrying v^{n+1/2},
    /// erodes, and leaves the internal + hourglass force of every node in nodes().fz/fr.
    void update(double dt, const material::MaterialPackage& materials);

    /// Forces at the current state without advancing anything (start of a run, resume).
    void computeForces(const material::MaterialPackage& materials);

    /// Time-step bins (solver/FePackage.hpp) take the update in three parts, and the node
    /// forces as impulses:
    /// wake() selects the elements to evaluate from now on and returns those that woke in
    /// this step (alive, ascending; they join the evaluated list);
    /// updateElements() advances the listed elements (ascending), each over its own interval
    /// `steps.interval[i]` [us]: its strain rates from the mean velocities of its corners over
    /// the interval, (x - x_start) / interval with x_start = `steps.start[8 i + 2 a]` (z, r of
    /// corner a), or from the node velocities when the interval is one base step; it erodes and
    /// votes as update() does, the stale votes of the other evaluated elements included;
    /// gatherImpulses() sets the force of every node of the listed elements to the sum of
    /// `weight[k]` times element `elements[k]`'s corner force, and zeroes the others it set
    /// before (the node kick of dt/2 f/m then applies weight dt/2 times the element force).
    struct Intervals {
        const std::vector<double>* interval = nullptr; ///< per element [us]
        const std::vector<double>* start = nullptr;    ///< 8 per element [mm]
        double baseStep = 0.0;                         ///< [us]
    };
    std::span<const int32_t> wake();
    void updateElements(std::span<const int32_t> elements, const Intervals& steps,
                        const material::MaterialPackage& materials);
    void gatherImpulses(std::span<const int32_t> elements, std::span<const double> weight);
    /// The alive, non-dormant elements (ascending), and each element's corner forces of its
    /// last evaluation (8 per element), its own stable step then [us], its awake flag and its
    /// volume (checkpointed with time-step bins: at a resume they are not those of the
    /// current positions).
    const std::vector<int32_t>& evaluatedElements() const { return m_evaluated; }
    std::vector<double>& cornerForces() { return m_elementForce; }
    const std::vector<double>& cornerForces() const { return m_elementForce; }
    std::vector<double>& ownSteps() { return m_ownStep; }
    const std::vector<double>& ownSteps() const { return m_ownStep; }
    const std::vector<uint8_t>& awakeFlags() const { return m_elementAwake; }
    /// Each element's swept volume at its last evaluation [mm^3].
    std::vector<double>& volumes() { return m_volume; }
    const std::vector<double>& volumes() const { return m_volume; }
    /// After a restore: the awake set is the checkpoint's, the element forces are kept.
    void restoreAwake(const std::vector<uint8_t>& awake);
    const NodeCorners& nodeCorners() const { return m_nodeCorners; }
    /// The nodes whose force the last gatherImpulses() set (null before the first).
    const std::vector<int32_t>* impulseNodes() const {
        return m_impulseFull ? nullptr : &m_impulseNodes;
    }

    /// Stable time step of the last update, before the Courant factor [us] (+inf: no element).
    double stableTimeStep() const { return m_stableDt; }
    /// Each evaluated element's own vote in the last assembly [us] (+inf: none cast).
    const std::vector<double>& elementSteps() const { return m_elementSteps; }
    int32_t limitingElement() const { return m_limitingElement; }

    NodeSet& nodes() { return m_nodes; }
    const NodeSet& nodes() const { return m_nodes; }
    ElementSet& elements() { return m_elements; }
    const ElementSet& elements() const { return m_elements; }

    /// Internal energy that eroded elements took out of the calculation [J], and their count.
    double erodedEnergy() const { return m_erodedEnergy; }
    std::size_t erodedCount() const { return m_erodedCount; }
    /// The elements the last update eroded, in ascending order.
    const std::vector<int32_t>& erodedThisUpdate() const { return m_erodedNow; }
    /// The elements the last update evaluated.
    std::size_t evaluatedCount() const { return m_updatedCount; }
    /// The erosion strain of every element: of its current shape for an alive element when
    /// the strain is instantaneous (the update evaluates it only where erosion is possible),
    /// otherwise (incremental, or eroded) the stored geometricStrain.
    std::vector<double> erosionStrain() const;
    /// The nodes whose force the last assembly may have left non-zero (the nodes of the
    /// elements it evaluated); every other node's force is exactly zero. Null when any node may
    /// hold a force (a resumed run before its first update).
    const std::vector<int32_t>* forcedNodes() const {
        return m_fullAssembly ? nullptr : &m_gatherNodes;
    }
    void restoreErosion(double energy, std::size_t count);
    /// The state of the last update that the next one reads (checkpointed for an exact
    /// resume): tr D and the hourglass damping rate of each element, the time-step vote.
    std::vector<double>& volumetricRate() { return m_volumetricRate; }
    const std::vector<double>& volumetricRate() const { return m_volumetricRate; }
    std::vector<double>& hourglassRate() { return m_hourglassRate; }
    const std::vector<double>& hourglassRate() const { return m_hourglassRate; }
    void restoreStableTimeStep(double dt, int32_t element) {
        m_stableDt = dt;
        m_limitingElement = element;
    }
    /// Recounts the alive elements of every node (after the alive flags were restored).
    void recountNodeElements();

private:
    /// The smallest stable time step offered, ties to the lowest element (thread-count free).
    struct StepVote {
        double dt = std::numeric_limits<double>::infinity();
        int32_t element = -1;
        void offer(double candidate, int32_t i) {
            if (candidate < dt || (candidate == dt && i < element)) {
                dt = candidate;
                element = i;
            }
        }
    };
    /// Elements per tile of the update: its stages' arrays for a tile (about 40 doubles an
    /// element) stay within a core's L2 cache between the stages.
    static constexpr std::size_t kTileSize = 128;

    void selectEvaluated();
    /// Adds a woken element, if alive, to the merged list.
    void admit(int32_t element);
    /// Adds an element's nodes to the gathered set.
    void gatherNodesOf(std::size_t element);
    /// What the energy update needs of an element's step start and of steps 1-2, per tile
    /// slot: kept on the stack (in cache), not in element arrays that every update would
    /// stream through.
    struct StepStart {
        double energy, pressure, szz, srr, srz;
        double volumeChange;  ///< [mm^3]
        double hourglassWork; ///< of the hourglass force over the step [J]
    };
    /// Every element over the one step dt, or each over its own interval (bins).
    struct SameStep;
    struct OwnInterval;
    /// Steps 1-4 and 6 of update() for the listed elements (ascending).
    template <class Steps>
    void updateTile(std::span<const int32_t> tile, const Steps& steps,
                    const material::MaterialPackage& materials, StepVote& vote);
    /// Step 4: the energy with the pressure work at the mean of the start and a predicted end
    /// pressure; then erosion of the elements that failed completely.
    template <class Steps>
    void updateEnergy(std::span<const int32_t> tile, const StepStart* start, const Steps& steps,
                      const material::MaterialPackage& materials);
    /// Steps 1-6 over the listed elements in tiles, the threads' votes in `votes`.
    template <class Steps>
    void updateList(std::span<const int32_t> list, const Steps& steps,
                    const material::MaterialPackage& materials, std::vector<StepVote>& votes);
    /// Element forces at the current geometry and state, gathered per node; the time-step vote.
    void assembleForces();
    /// Element i's corner forces (zeros when it is eroded or about to be) and its vote, kept
    /// as its own step too (kNoLimit when it casts none).
    void elementForces(std::size_t i, StepVote& vote);
    static constexpr double kNoLimit = std::numeric_limits<double>::infinity();
    void zeroForcesIfFull();
    /// The time step from the threads' votes, then each node's force from its elements'.
    void finishAssembly(const std::vector<StepVote>& votes);
    void erode(std::size_t element);

    FeOptions m_options;
    NodeSet m_nodes;
    ElementSet m_elements;
    ElementRates m_rates;
    std::vector<double> m_erosionFactor;
    std::vector<double> m_strainRatioLimit; ///< stretchRatioLimit(erosion factor) per body
    // Node -> elements adjacency (CSR, ascending element order): forces are gathered per node
    // in a fixed order, so the sums do not depend on the thread count.
    NodeCorners m_nodeCorners;              ///< of every element
    std::vector<double> m_elementForce;     ///< 8 per element: (fz, fr) of corners 0..3
    std::vector<double> m_hourglassRate;    ///< c_hg per element [mg/us], set in update()
    std::vector<int32_t> m_evaluated;       ///< alive, non-dormant elements of this update
    std::vector<double> m_elementSteps;     ///< their votes in the last assembly [us]
    std::size_t m_updatedCount = 0;         ///< elements the last update evaluated
    std::vector<double> m_cornerWeight;     ///< per element, of gatherImpulses() (0 otherwise)
    std::vector<int32_t> m_wokenAlive;      ///< of wake()
    std::vector<int32_t> m_impulseNodes;    ///< nodes whose force gatherImpulses() set
    std::vector<uint8_t> m_impulseMarked;   ///< in m_impulseNodes
    bool m_impulseFull = true;              ///< any node may hold a force (start, resume)
    std::vector<double> m_ownStep;          ///< per element, its last vote [us]
    std::vector<int32_t> m_woken, m_merged; ///< scratch of selectEvaluated()
    bool m_erodedSinceSelection = false;    ///< the list holds eroded elements
    // The awake set only grows: an element wakes when one of its nodes first moves (or, at a
    // start or resume, when its material is out of its reference state) and stays awake.
    std::vector<uint8_t> m_elementAwake, m_nodeAwake;
    bool m_fullSelection = true;          ///< check every element's state (first update, resume)
    std::vector<double> m_volumetricRate; ///< tr D of the last update [1/us]
    std::vector<double> m_volume;         ///< swept volume [mm^3]
    std::vector<double> m_referenceVolume, m_referenceDensity; ///< V0 [mm^3], rho0 [g/cm^3]
    /// Each element's reference shape (the instantaneous erosion strain's deformation gradient).
    std::vector<ReferenceShape> m_referenceShape;
    std::vector<uint8_t> m_erode;       ///< to erode at the end of this update
    std::vector<int32_t> m_erodedNow;   ///< eroded by the last update
    std::vector<int32_t> m_gatherNodes; ///< nodes of the evaluated elements
    std::vector<uint8_t> m_nodeMarked;  ///< in m_gatherNodes
    bool m_fullAssembly = true;         ///< zero and gather everything (first time, resume)
    double m_referenceDt = std::numeric_limits<double>::infinity(); ///< undisturbed elements
    double m_stableDt = 0.0;
    int32_t m_limitingElement = -1;
    double m_erodedEnergy = 0.0;
    std::size_t m_erodedCount = 0;
};

} // namespace hvi::fe
