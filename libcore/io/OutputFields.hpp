// THE table of run-file fields (STYLE practice 7, after SWIFT's io_make_output_field): every
// particle field, finite-element node and element field, and history column that hvi-run
// writes is declared here once, with its HDF5 dataset name, element type, components, unit
// and description. The writer, the reader, the XDMF sidecar and the docs all iterate these
// tables; none of them names a field by hand.
//
// One struct template per kind of record, instantiated with three storages:
//
//   ParticleFieldsOf<ConstSpanOf>  = ParticleFieldsView  what the solver hands to the writer:
//                                    spans over its structure-of-arrays storage, no copy
//   ParticleFieldsOf<VectorOf>     = ParticleFields      what the reader returns
//   HistoryOf<ValueOf>             = HistoryRow          one history row (appendHistory)
//   HistoryOf<VectorOf>            = HistoryColumns      the history as read back
//
// Each table entry binds a FieldSpec to a member pointer; the element type is deduced from
// the member, and static_asserts check that every member is in the table exactly once.
//
// Units are those of the hydrocode (docs/conventions.md): length mm, time us, mass mg, so
// velocity km/s (= mm/us), density g/cm3 (= mg/mm3), pressure GPa, energy J, specific energy
// MJ/kg (= J/mg). Each field also records its dimensions as powers of (length, mass, time),
// from which the SWIFT-style CGS conversion factor is derived; a unit test checks that the
// unit string and the dimensions agree.
//
// Multi-component fields (StressDeviator: 3 per particle; Connectivity: 4 per element) are
// interleaved, row-major: item i's components are at [C*i, C*i+1, ..., C*i+C-1], and the
// dataset has shape (N, C). This is the layout of an Eigen::Matrix<double, C, Dynamic>
// (column-major), so the solver can view such storage without copying.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace hvi::io {

/// Element type of a dataset (HDF5 file types: IEEE F64LE, STD I32LE, STD U8LE, STD I64LE,
/// IEEE F32LE). Float32 only in the run file's view for ParaView (RunFileView.hpp).
enum class ElementType { Float64, Int32, UInt8, Int64, Float32 };

std::string_view toString(ElementType type);

template <class T>
constexpr ElementType elementTypeOf() {
    if constexpr (std::is_same_v<T, double>) {
        return ElementType::Float64;
    } else if constexpr (std::is_same_v<T, float>) {
        return ElementType::Float32;
    } else if constexpr (std::is_same_v<T, std::int32_t>) {
        return ElementType::Int32;
    } else if constexpr (std::is_same_v<T, std::uint8_t>) {
        return ElementType::UInt8;
    } else {
        static_assert(std::is_same_v<T, std::int64_t>, "unsupported run-file element type");
        return ElementType::Int64;
    }
}

/// Powers of the base units (length mm, mass mg, time us) of a quantity.
struct UnitDimensions {
    int length = 0;
    int mass = 0;
    int time = 0;
    friend constexpr bool operator==(const UnitDimensions&, const UnitDimensions&) = default;
};

inline constexpr UnitDimensions kDimensionless{0, 0, 0};
inline constexpr UnitDimensions kLength{1, 0, 0};
inline constexpr UnitDimensions kMass{0, 1, 0};
inline constexpr UnitDimensions kTime{0, 0, 1};
inline constexpr UnitDimensions kVelocity{1, 0, -1};       ///< km/s = mm/us
inline constexpr UnitDimensions kDensity{-3, 1, 0};        ///< g/cm3 = mg/mm3
inline constexpr UnitDimensions kPressure{-1, 1, -2};      ///< GPa = mg/(mm us^2)
inline constexpr UnitDimensions kSpecificEnergy{2, 0, -2}; ///< MJ/kg = mm^2/us^2
inline constexpr UnitDimensions kEnergy{2, 1, -2};         ///< J = mg mm^2/us^2
inline constexpr UnitDimensions kMomentum{1, 1, -1};       ///< mg mm/us = 1e-3 N s

/// The value in CGS of one unit of a quantity with these dimensions
/// (1 mm = 0.1 cm, 1 mg = 1e-3 g, 1 us = 1e-6 s): 1 km/s -> 1e5 cm/s, 1 GPa -> 1e10 Ba.
double cgsConversionFactor(UnitDimensions dimensions);

/// Whether a field must be present whenever its record kind is written.
/// Optional fields (e.g. StressDeviator for a strengthless scene) are left out of a snapshot
/// when their span is empty: a scene builds only the physics it contains.
enum class Presence { Required, Optional };

/// One output field: what the file says about a dataset.
struct FieldSpec {
    std::string_view name;        ///< HDF5 dataset name, CamelCase
    ElementType type;             ///< element type in the file and in memory
    int components;               ///< values per item (1 = scalar)
    std::string_view units;       ///< `Units` attribute, ASCII ("-" = dimensionless or count)
    UnitDimensions dimensions;    ///< powers of (mm, mg, us); must agree with `units`
    Presence presence;            ///< required, or left out when the solver has no such data
    std::string_view description; ///< `Description` attribute
};

// ---- storages -----------------------------------------------------------------------------

template <class T>
using ConstSpanOf = std::span<const T>;
template <class T>
using VectorOf = std::vector<T>;
template <class T>
using ValueOf = T;

/// The element type stored in a member (span<const T>, vector<T> or T itself).
template <class M>
struct StoredElement {
    using type = M;
};
template <class T>
struct StoredElement<std::span<const T>> {
    using type = T;
};
template <class T>
struct StoredElement<std::vector<T>> {
    using type = T;
};

/// A pointer to one member of a record, whatever its element type.
template <class Fields>
using FieldMember = std::variant<typename Fields::template Storage<double> Fields::*,
                                 typename Fields::template Storage<std::int32_t> Fields::*,
                                 typename Fields::template Storage<std::uint8_t> Fields::*,
                                 typename Fields::template Storage<std::int64_t> Fields::*>;

/// A table entry: the spec and the member it describes.
template <class Fields>
struct FieldBinding {
    FieldSpec spec;
    FieldMember<Fields> member;
};

/// Builds a table entry; the element type comes from the member's type.
template <class Fields, class M>
constexpr FieldBinding<Fields> bindField(M Fields::*member, std::string_view name, int components,
                                         std::string_view units, UnitDimensions dimensions,
                                         Presence presence, std::string_view description) {
    return FieldBinding<Fields>{{name, elementTypeOf<typename StoredElement<M>::type>(), components,
                                 units, dimensions, presence, description},
                                member};
}

// ---- records ------------------------------------------------------------------------------

/// Per-particle state of an SPH snapshot. N = z.size(); each field holds N * components values
/// (an empty optional field is left out of the snapshot).
template <template <class> class S>
struct ParticleFieldsOf {
    template <class T>
    using Storage = S<T>;
    S<double> z{};
    S<double> r{};
    S<double> vz{};
    S<double> vr{};
    S<double> mass{};
    S<double> density{};
    S<double> pressure{};
    S<double> internalEnergy{};
    S<double> smoothingLength{};
    S<double> damage{};
    S<double> plasticStrain{};
    S<double> stressDeviator{}; ///< 3 per particle: (zz, rr, rz), interleaved
    S<std::int32_t> bodyId{};
    S<std::uint8_t> alive{};
};

/// Per-node state of the finite-element mesh. Nn = z.size().
template <template <class> class S>
struct FeNodeFieldsOf {
    template <class T>
    using Storage = S<T>;
    S<double> z{};
    S<double> r{};
    S<double> vz{};
    S<double> vr{};
    S<double> mass{};
};

/// Per-element state of the finite-element mesh. Ne = connectivity.size() / 4.
template <template <class> class S>
struct FeElementFieldsOf {
    template <class T>
    using Storage = S<T>;
    S<std::int32_t> connectivity{}; ///< 4 per element: 0-based node indices, interleaved
    S<std::uint8_t> alive{};
    S<double> damage{};
    S<double> plasticStrain{};
    S<double> geometricStrain{};
    S<double> pressure{};
    S<double> density{};
    S<std::int32_t> bodyId{};
};

template <template <class> class S>
struct FeFieldsOf {
    FeNodeFieldsOf<S> nodes{};
    FeElementFieldsOf<S> elements{};
};

/// One row of the time history (one per step, or every few steps, as the solver chooses).
template <template <class> class S>
struct HistoryOf {
    template <class T>
    using Storage = S<T>;
    S<double> timeUs{};
    S<double> dtUs{};
    S<std::int64_t> step{};
    S<double> kineticEnergy{};  ///< J
    S<double> internalEnergy{}; ///< J
    S<double> totalEnergy{};    ///< J, kinetic + internal of the material in the calculation
    S<double> energyError{};    ///< see relativeEnergyError()
    S<double> deletedEnergy{};  ///< J, cumulative
    S<double> mass{};           ///< mg
    S<double> momentumZ{};      ///< mg mm/us
    S<std::int64_t> aliveCount{};
    S<std::int64_t> deletedCount{};
    S<std::int64_t> activeCount{};
};

using ParticleFieldsView = ParticleFieldsOf<ConstSpanOf>;
using ParticleFields = ParticleFieldsOf<VectorOf>;
using FeNodeFieldsView = FeNodeFieldsOf<ConstSpanOf>;
using FeElementFieldsView = FeElementFieldsOf<ConstSpanOf>;
using FeFieldsView = FeFieldsOf<ConstSpanOf>;
using FeFields = FeFieldsOf<VectorOf>;
using HistoryRow = HistoryOf<ValueOf>;
using HistoryColumns = HistoryOf<VectorOf>;

/// The EnergyError history column: the relative energy error counting what deleted
/// particles and eroded elements carried away as accounted for,
///   (totalEnergy + deletedEnergy - initialTotalEnergy) / |initialTotalEnergy|.
/// Signed: > 0 means energy was created. Returns 0 when the initial total is 0.
constexpr double relativeEnergyError(double totalEnergy, double deletedEnergy,
                                     double initialTotalEnergy) {
    const double scale = initialTotalEnergy < 0 ? -initialTotalEnergy : initialTotalEnergy;
    return scale > 0 ? (totalEnergy + deletedEnergy - initialTotalEnergy) / scale : 0.0;
}

// ---- the tables ---------------------------------------------------------------------------

template <class Fields>
struct FieldTable; // specialised below for each record kind

template <template <class> class S>
struct FieldTable<ParticleFieldsOf<S>> {
    using F = ParticleFieldsOf<S>;
    static constexpr auto req = Presence::Required;
    static constexpr auto opt = Presence::Optional;
    static constexpr std::array entries{
        bindField(&F::z, "Z", 1, "mm", kLength, req,
                  "Axial position z of the particle, along the shot line (the symmetry axis)"),
        bindField(&F::r, "R", 1, "mm", kLength, req,
                  "Radial position r >= 0 of the particle (distance from the shot line)"),
        bindField(&F::vz, "Vz", 1, "km/s", kVelocity, req, "Axial velocity (km/s = mm/us)"),
        bindField(&F::vr, "Vr", 1, "km/s", kVelocity, req, "Radial velocity (km/s = mm/us)"),
        bindField(&F::mass, "Mass", 1, "mg", kMass, req,
                  "Particle mass; in axisymmetric runs the mass of the whole ring (2 pi rad) "
                  "the particle stands for, so sums over particles are real masses"),
        bindField(&F::density, "Density", 1, "g/cm3", kDensity, req,
                  "Mass density (g/cm3 = mg/mm3)"),
        bindField(&F::pressure, "Pressure", 1, "GPa", kPressure, req,
                  "Pressure from the equation of state, positive in compression"),
        bindField(&F::internalEnergy, "InternalEnergy", 1, "MJ/kg", kSpecificEnergy, req,
                  "Specific internal energy (MJ/kg = J/mg)"),
        bindField(&F::smoothingLength, "SmoothingLength", 1, "mm", kLength, req,
                  "SPH smoothing length h (the cubic B-spline kernel reaches 2h)"),
        bindField(&F::damage, "Damage", 1, "-", kDimensionless, opt,
                  "Scalar damage D in [0, 1] of the failure model (1 = fully failed); absent "
                  "when no body has a failure model"),
        bindField(&F::plasticStrain, "PlasticStrain", 1, "-", kDimensionless, opt,
                  "Equivalent plastic strain; absent when no body has a strength model"),
        bindField(&F::stressDeviator, "StressDeviator", 3, "GPa", kPressure, opt,
                  "Deviatoric stress components (S_zz, S_rr, S_rz) per particle; the hoop "
                  "component is S_tt = -(S_zz + S_rr); absent when no body has strength"),
        bindField(&F::bodyId, "BodyId", 1, "-", kDimensionless, req,
                  "Index (0-based) of the scene body the particle belongs to, in the order "
                  "of the bodies in /scene"),
        bindField(&F::alive, "Alive", 1, "-", kDimensionless, req,
                  "1 while the particle takes part in the calculation, 0 once deleted "
                  "(runaway speed, density cut-off); a deleted particle keeps its last state. "
                  "0 with Mass 0: a slot held in reserve for an element of an FE body, "
                  "used when that element erodes (not material)"),
    };
};

template <template <class> class S>
struct FieldTable<FeNodeFieldsOf<S>> {
    using F = FeNodeFieldsOf<S>;
    static constexpr auto req = Presence::Required;
    static constexpr std::array entries{
        bindField(&F::z, "Z", 1, "mm", kLength, req, "Axial position z of the node"),
        bindField(&F::r, "R", 1, "mm", kLength, req, "Radial position r >= 0 of the node"),
        bindField(&F::vz, "Vz", 1, "km/s", kVelocity, req, "Axial velocity of the node"),
        bindField(&F::vr, "Vr", 1, "km/s", kVelocity, req, "Radial velocity of the node"),
        bindField(&F::mass, "Mass", 1, "mg", kMass, req,
                  "Lumped nodal mass (whole ring in axisymmetric runs); an eroded element's "
                  "share leaves with the particle it becomes (fe.eroded_material particles), "
                  "or stays on its nodes (free_nodes)"),
    };
};

template <template <class> class S>
struct FieldTable<FeElementFieldsOf<S>> {
    using F = FeElementFieldsOf<S>;
    static constexpr auto req = Presence::Required;
    static constexpr auto opt = Presence::Optional;
    static constexpr std::array entries{
        bindField(&F::connectivity, "Connectivity", 4, "-", kDimensionless, req,
                  "The 4 nodes of the quadrilateral element as 0-based indices into this "
                  "snapshot's Nodes datasets, counter-clockwise in the (z, r) plane"),
        bindField(&F::alive, "Alive", 1, "-", kDimensionless, req,
                  "1 for an intact element, 0 once eroded: inverted or folded, geometric "
                  "strain above the erosion factor, crushed past the density ceiling, or "
                  "failed completely (docs/fe-erosion.md)"),
        bindField(&F::damage, "Damage", 1, "-", kDimensionless, opt,
                  "Scalar damage D in [0, 1] of the failure model (1 = fully failed)"),
        bindField(&F::plasticStrain, "PlasticStrain", 1, "-", kDimensionless, opt,
                  "Equivalent plastic strain"),
        bindField(&F::geometricStrain, "GeometricStrain", 1, "-", kDimensionless, req,
                  "Geometric strain compared with the erosion factor (fe.erosion_strain: "
                  "equivalent logarithmic strain of the current shape, or the integral of the "
                  "equivalent strain rate)"),
        bindField(&F::pressure, "Pressure", 1, "GPa", kPressure, req,
                  "Pressure from the equation of state, positive in compression"),
        bindField(&F::density, "Density", 1, "g/cm3", kDensity, req,
                  "Mass density (g/cm3 = mg/mm3)"),
        bindField(&F::bodyId, "BodyId", 1, "-", kDimensionless, req,
                  "Index (0-based) of the scene body the element belongs to"),
    };
};

template <template <class> class S>
struct FieldTable<HistoryOf<S>> {
    using F = HistoryOf<S>;
    static constexpr auto req = Presence::Required;
    static constexpr std::array entries{
        bindField(&F::timeUs, "Time", 1, "us", kTime, req, "Simulated time of the row"),
        bindField(&F::dtUs, "Dt", 1, "us", kTime, req,
                  "Time step taken from this row's time to the next"),
        bindField(&F::step, "Step", 1, "-", kDimensionless, req, "Step number (0 = initial)"),
        bindField(&F::kineticEnergy, "KineticEnergy", 1, "J", kEnergy, req,
                  "Kinetic energy of the material in the calculation (alive particles, all "
                  "FE nodes)"),
        bindField(&F::internalEnergy, "InternalEnergy", 1, "J", kEnergy, req,
                  "Internal energy of the material in the calculation (alive particles, "
                  "intact elements)"),
        bindField(&F::totalEnergy, "TotalEnergy", 1, "J", kEnergy, req,
                  "KineticEnergy + InternalEnergy"),
        bindField(&F::energyError, "EnergyError", 1, "-", kDimensionless, req,
                  "Relative energy error (TotalEnergy + DeletedEnergy - TotalEnergy[0]) / "
                  "|TotalEnergy[0]|: energy carried away by deleted particles and eroded "
                  "elements counts as accounted for; > 0 means energy was created"),
        bindField(&F::deletedEnergy, "DeletedEnergy", 1, "J", kEnergy, req,
                  "Cumulative energy that left the calculation: deleted particles and free "
                  "nodes (kinetic and internal), eroded elements whose mass stays on their "
                  "nodes (internal; fe.eroded_material free_nodes), free nodes' contact heat"),
        bindField(&F::mass, "Mass", 1, "mg", kMass, req,
                  "Mass of the material in the calculation (alive particles, FE nodes); the "
                  "deleted mass is Mass[0] - Mass"),
        bindField(&F::momentumZ, "MomentumZ", 1, "mg*mm/us", kMomentum, req,
                  "Axial momentum of the material in the calculation (mg*mm/us = mg*km/s = "
                  "1e-3 N*s); the radial momentum vanishes by symmetry"),
        bindField(&F::aliveCount, "AliveCount", 1, "-", kDimensionless, req,
                  "Number of particles and elements still in the calculation"),
        bindField(&F::deletedCount, "DeletedCount", 1, "-", kDimensionless, req,
                  "Number of particles deleted and elements eroded so far"),
        bindField(&F::activeCount, "ActiveCount", 1, "-", kDimensionless, req,
                  "Number of alive particles and elements the solver advanced in this step "
                  "(material no signal has reached yet is skipped)"),
    };
};

// ---- generic operations over a record -----------------------------------------------------

/// Calls fn(const FieldSpec&, member) for every field of `fields`, in table order.
template <class Fields, class Fn>
void forEachField(Fields& fields, Fn&& fn) {
    for (const auto& binding : FieldTable<std::remove_const_t<Fields>>::entries) {
        std::visit([&](auto member) { fn(binding.spec, fields.*member); }, binding.member);
    }
}

/// A read-only view of owned fields (e.g. a snapshot read back, to write it again).
template <template <template <class> class> class Fields>
Fields<ConstSpanOf> viewOf(const Fields<VectorOf>& data) {
    Fields<ConstSpanOf> view{};
    const auto& from = FieldTable<Fields<VectorOf>>::entries;
    const auto& to = FieldTable<Fields<ConstSpanOf>>::entries;
    for (std::size_t i = 0; i < from.size(); ++i) {
        std::visit(
            [&](auto source) {
                using T = typename std::remove_cvref_t<decltype(data.*source)>::value_type;
                view.*std::get<std::span<const T> Fields<ConstSpanOf>::*>(to[i].member) =
                    data.*source;
            },
            from[i].member);
    }
    return view;
}

inline FeFieldsView viewOf(const FeFields& data) {
    return FeFieldsView{viewOf(data.nodes), viewOf(data.elements)};
}

/// An owned copy of a view (the solver's state as the snapshot hvi-assess reads).
template <template <template <class> class> class Fields>
Fields<VectorOf> ownedOf(const Fields<ConstSpanOf>& view) {
    Fields<VectorOf> data{};
    const auto& from = FieldTable<Fields<ConstSpanOf>>::entries;
    const auto& to = FieldTable<Fields<VectorOf>>::entries;
    for (std::size_t i = 0; i < from.size(); ++i) {
        std::visit(
            [&](auto source) {
                using T = typename std::remove_cvref_t<decltype(view.*source)>::value_type;
                const std::span<const T> span = view.*source;
                auto& into = data.*std::get<std::vector<T> Fields<VectorOf>::*>(to[i].member);
                into.resize(span.size());
                std::copy_n(span.data(), span.size(), into.data());
            },
            from[i].member);
    }
    return data;
}

inline FeFields ownedOf(const FeFieldsView& view) {
    return FeFields{ownedOf(view.nodes), ownedOf(view.elements)};
}

/// Row k of a history read back (to write it again).
inline HistoryRow rowOf(const HistoryColumns& history, std::size_t k) {
    HistoryRow row{};
    const auto& from = FieldTable<HistoryColumns>::entries;
    const auto& to = FieldTable<HistoryRow>::entries;
    for (std::size_t i = 0; i < from.size(); ++i) {
        std::visit(
            [&](auto source) {
                using T = typename std::remove_cvref_t<decltype(history.*source)>::value_type;
                row.*std::get<T HistoryRow::*>(to[i].member) = (history.*source)[k];
            },
            from[i].member);
    }
    return row;
}

// ---- compile-time checks: every member in its table exactly once, names unique ------------

template <class Table>
constexpr bool tableIsConsistent(const Table& entries) {
    for (std::size_t i = 0; i < entries.size(); ++i) {
        if (entries[i].spec.components < 1 || entries[i].spec.name.empty()) {
            return false;
        }
        for (std::size_t j = i + 1; j < entries.size(); ++j) {
            if (entries[i].member == entries[j].member ||
                entries[i].spec.name == entries[j].spec.name) {
                return false;
            }
        }
    }
    return true;
}

static_assert(tableIsConsistent(FieldTable<ParticleFieldsView>::entries));
static_assert(tableIsConsistent(FieldTable<FeNodeFieldsView>::entries));
static_assert(tableIsConsistent(FieldTable<FeElementFieldsView>::entries));
static_assert(tableIsConsistent(FieldTable<HistoryRow>::entries));
// A member missing from a table would not be written: the counts must match the struct sizes.
static_assert(sizeof(ParticleFieldsView) ==
              FieldTable<ParticleFieldsView>::entries.size() * sizeof(std::span<const double>));
static_assert(sizeof(FeNodeFieldsView) ==
              FieldTable<FeNodeFieldsView>::entries.size() * sizeof(std::span<const double>));
static_assert(sizeof(FeElementFieldsView) ==
              FieldTable<FeElementFieldsView>::entries.size() * sizeof(std::span<const double>));
static_assert(sizeof(HistoryRow) == FieldTable<HistoryRow>::entries.size() * sizeof(double) &&
              sizeof(double) == sizeof(std::int64_t));

// ---- the specs alone (for the XDMF sidecar, docs, --list-fields) --------------------------

std::span<const FieldSpec> particleFieldSpecs();
std::span<const FieldSpec> nodeFieldSpecs();
std::span<const FieldSpec> elementFieldSpecs();
std::span<const FieldSpec> historyColumnSpecs();

/// The spec named `name` in `specs`, or nullptr.
const FieldSpec* findFieldSpec(std::span<const FieldSpec> specs, std::string_view name);

} // namespace hvi::io
