#include "io/RunFileView.hpp"

#include <algorithm>
#include <deque>
#include <stdexcept>
#include <string>

namespace hvi::io {

namespace {

constexpr auto kRequired = Presence::Required;
constexpr auto kOptional = Presence::Optional;

// Run-file fields the view carries in another shape: the positions become Points, the
// velocity components a vector, the deviator named components; Alive is 1 for all it shows.
constexpr std::string_view kReshaped[] = {
    "Z", "R", "Vz", "Vr", "Alive", "Connectivity", "StressDeviator"};

constexpr std::string_view kNodePrefix = "Node";

const FieldSpec kVelocity3{"Velocity",
                           ElementType::Float32,
                           3,
                           "km/s",
                           kVelocity,
                           kRequired,
                           "Velocity (Vz, Vr, 0) in ParaView's frame, where X = Z (the shot line) "
                           "and Y = R; of an element, the mean of its four nodes'"};
const FieldSpec kNodeVelocity3{"NodeVelocity", ElementType::Float32,       3, "km/s", kVelocity,
                               kRequired,      "Node velocity (Vz, Vr, 0)"};
const FieldSpec kSlot{"Slot",
                      ElementType::Int32,
                      1,
                      "-",
                      kDimensionless,
                      kRequired,
                      "Index of the particle or element in this snapshot's own datasets "
                      "(/snapshots/NNNNNN/... or .../Elements/...)"};
// The deviator's components (S_zz, S_rr, S_rz) as stored, then the hoop one.
const FieldSpec kDeviator[] = {
    {"StressDeviatorZZ", ElementType::Float32, 1, "GPa", kPressure, kOptional,
     "Deviatoric stress S_zz (axial)"},
    {"StressDeviatorRR", ElementType::Float32, 1, "GPa", kPressure, kOptional,
     "Deviatoric stress S_rr (radial)"},
    {"StressDeviatorRZ", ElementType::Float32, 1, "GPa", kPressure, kOptional,
     "Deviatoric stress S_rz (shear in the (z, r) plane)"},
    {"StressDeviatorTT", ElementType::Float32, 1, "GPa", kPressure, kOptional,
     "Deviatoric stress S_tt (hoop) = -(S_zz + S_rr)"},
};
const FieldSpec kPoints{"Points",
                        ElementType::Float32,
                        3,
                        "mm",
                        kLength,
                        kRequired,
                        "Positions (Z, R, 0): X = Z along the shot line, Y = R"};
const FieldSpec kParticleCells{"Cells",
                               ElementType::Int32,
                               1,
                               "-",
                               kDimensionless,
                               kRequired,
                               "The point of each vertex cell (one per particle): 0..N-1"};
const FieldSpec kElementCells{"Cells",
                              ElementType::Int32,
                              4,
                              "-",
                              kDimensionless,
                              kRequired,
                              "The 4 points of each alive element, counter-clockwise in the "
                              "(z, r) plane, 0-based into this block's Points"};

bool reshaped(std::string_view name) {
    return std::find(std::begin(kReshaped), std::end(kReshaped), name) != std::end(kReshaped);
}

struct Tables {
    std::deque<std::string> names; // storage of the derived names (stable addresses)
    std::vector<ViewArraySpec> particles;
    std::vector<ViewArraySpec> mesh;

    /// The scalar fields of a run-file table that the view copies as they are.
    void copies(std::vector<ViewArraySpec>& into, std::span<const FieldSpec> specs,
                std::string_view prefix, ViewCentre centre) {
        for (const FieldSpec& spec : specs) {
            if (reshaped(spec.name) || spec.components != 1) {
                continue;
            }
            FieldSpec copy = spec;
            if (copy.type == ElementType::Float64) {
                copy.type = ElementType::Float32;
            }
            if (!prefix.empty()) {
                names.push_back(std::string(prefix) + std::string(spec.name));
                copy.name = names.back();
            }
            into.push_back({copy, centre});
        }
    }

    Tables() {
        particles.push_back({kVelocity3, ViewCentre::Cell});
        copies(particles, particleFieldSpecs(), {}, ViewCentre::Cell);
        for (const FieldSpec& component : kDeviator) {
            particles.push_back({component, ViewCentre::Cell});
        }
        particles.push_back({kSlot, ViewCentre::Cell});

        mesh.push_back({kNodeVelocity3, ViewCentre::Point});
        copies(mesh, nodeFieldSpecs(), kNodePrefix, ViewCentre::Point);
        mesh.push_back({kVelocity3, ViewCentre::Cell});
        copies(mesh, elementFieldSpecs(), {}, ViewCentre::Cell);
        mesh.push_back({kSlot, ViewCentre::Cell});
    }
};

const Tables& tables() {
    static const Tables instance;
    return instance;
}

const ViewArraySpec& requiredSpec(ViewBlockKind kind, std::string_view name) {
    const ViewArraySpec* spec = findViewArraySpec(kind, name);
    if (spec == nullptr) {
        throw std::logic_error("run-file view: no array " + std::string(name));
    }
    return *spec;
}

/// values[index[k]] for every k, into the array's storage of the spec's type.
template <class T>
void gather(ViewBlock& block, const ViewArraySpec& spec, std::span<const T> values,
            const std::vector<std::size_t>& index) {
    ViewArray array{&spec, {}, {}};
    if constexpr (std::is_same_v<T, double>) {
        array.real.reserve(index.size());
        for (std::size_t i : index) {
            array.real.push_back(static_cast<float>(values[i]));
        }
    } else if constexpr (std::is_same_v<T, std::int32_t>) {
        array.integer.reserve(index.size());
        for (std::size_t i : index) {
            array.integer.push_back(values[i]);
        }
    } else {
        throw std::logic_error("run-file view: " + std::string(spec.field.name) +
                               " has a type the view does not carry");
    }
    block.arrays.push_back(std::move(array));
}

/// Copies every field of `fields` that the view table of `kind` names (with `prefix`).
template <class Fields>
void copyTableFields(ViewBlock& block, const Fields& fields, std::string_view prefix,
                     const std::vector<std::size_t>& index) {
    forEachField(fields, [&](const FieldSpec& spec, const auto& values) {
        if (values.empty() || reshaped(spec.name) || spec.components != 1) {
            return;
        }
        const std::string name = std::string(prefix) + std::string(spec.name);
        gather(block, requiredSpec(block.kind, name), values, index);
    });
}

void addReal(ViewBlock& block, std::string_view name, std::vector<float> values) {
    block.arrays.push_back({&requiredSpec(block.kind, name), std::move(values), {}});
}

void addSlot(ViewBlock& block, const std::vector<std::size_t>& index) {
    ViewArray slot{&requiredSpec(block.kind, kSlot.name), {}, {}};
    slot.integer.assign(index.begin(), index.end());
    block.arrays.push_back(std::move(slot));
}

/// (a[i], b[i], 0) for every i of `index`.
std::vector<float> vector3(std::span<const double> a, std::span<const double> b,
                           const std::vector<std::size_t>& index) {
    std::vector<float> out;
    out.reserve(3 * index.size());
    for (std::size_t i : index) {
        out.insert(out.end(), {static_cast<float>(a[i]), static_cast<float>(b[i]), 0.0F});
    }
    return out;
}

/// Arrays in table order, so a block written and one read back list them alike (the specs
/// point into one table, so their addresses are in table order).
void sortByTable(ViewBlock& block) {
    std::sort(block.arrays.begin(), block.arrays.end(),
              [](const ViewArray& a, const ViewArray& b) { return a.spec < b.spec; });
}

} // namespace

std::span<const ViewArraySpec> viewArraySpecs(ViewBlockKind kind) {
    return kind == ViewBlockKind::Particles ? tables().particles : tables().mesh;
}

const ViewArraySpec* findViewArraySpec(ViewBlockKind kind, std::string_view name) {
    for (const auto& spec : viewArraySpecs(kind)) {
        if (spec.field.name == name) {
            return &spec;
        }
    }
    return nullptr;
}

const FieldSpec& viewPointsSpec() {
    return kPoints;
}

const FieldSpec& viewCellsSpec(ViewBlockKind kind) {
    return kind == ViewBlockKind::Particles ? kParticleCells : kElementCells;
}

std::string_view viewBlockName(ViewBlockKind kind) {
    return kind == ViewBlockKind::Particles ? "Particles" : "FiniteElements";
}

int viewNodesPerCell(ViewBlockKind kind) {
    return viewCellsSpec(kind).components;
}

ViewBlock particleView(const ParticleFieldsView& particles) {
    ViewBlock block;
    block.kind = ViewBlockKind::Particles;
    std::vector<std::size_t> live;
    for (std::size_t i = 0; i < particles.alive.size(); ++i) {
        if (particles.alive[i] != 0) {
            live.push_back(i);
        }
    }
    if (live.empty()) {
        return block;
    }
    block.pointCount = block.cellCount = live.size();
    block.points = vector3(particles.z, particles.r, live);
    block.cells.resize(live.size());
    for (std::size_t k = 0; k < live.size(); ++k) {
        block.cells[k] = static_cast<std::int32_t>(k);
    }
    addReal(block, kVelocity3.name, vector3(particles.vz, particles.vr, live));
    copyTableFields(block, particles, {}, live);
    if (!particles.stressDeviator.empty()) {
        std::vector<float> component[4];
        for (std::size_t i : live) {
            const double* s = &particles.stressDeviator[3 * i];
            component[0].push_back(static_cast<float>(s[0]));
            component[1].push_back(static_cast<float>(s[1]));
            component[2].push_back(static_cast<float>(s[2]));
            component[3].push_back(static_cast<float>(-(s[0] + s[1])));
        }
        for (int c = 0; c < 4; ++c) {
            addReal(block, kDeviator[c].name, std::move(component[c]));
        }
    }
    addSlot(block, live);
    sortByTable(block);
    return block;
}

ViewBlock meshView(const FeFieldsView& fe) {
    ViewBlock block;
    block.kind = ViewBlockKind::FiniteElements;
    constexpr std::size_t kCorners = 4;
    const auto& connectivity = fe.elements.connectivity;
    const std::size_t elementCount = connectivity.size() / kCorners;
    std::vector<std::size_t> liveElements;
    std::vector<std::int32_t> pointOf(fe.nodes.z.size(), -1);
    for (std::size_t e = 0; e < elementCount; ++e) {
        if (fe.elements.alive[e] == 0) {
            continue;
        }
        liveElements.push_back(e);
        for (std::size_t k = 0; k < kCorners; ++k) {
            pointOf[static_cast<std::size_t>(connectivity[kCorners * e + k])] = 0;
        }
    }
    if (liveElements.empty()) {
        return block;
    }
    // The nodes of alive elements, renumbered in node order.
    std::vector<std::size_t> liveNodes;
    for (std::size_t n = 0; n < pointOf.size(); ++n) {
        if (pointOf[n] == 0) {
            pointOf[n] = static_cast<std::int32_t>(liveNodes.size());
            liveNodes.push_back(n);
        }
    }
    block.pointCount = liveNodes.size();
    block.cellCount = liveElements.size();
    block.points = vector3(fe.nodes.z, fe.nodes.r, liveNodes);
    block.cells.reserve(kCorners * liveElements.size());
    std::vector<float> cellVelocity;
    cellVelocity.reserve(3 * liveElements.size());
    for (std::size_t e : liveElements) {
        double vz = 0.0;
        double vr = 0.0;
        for (std::size_t k = 0; k < kCorners; ++k) {
            const auto node = static_cast<std::size_t>(connectivity[kCorners * e + k]);
            block.cells.push_back(pointOf[node]);
            vz += fe.nodes.vz[node];
            vr += fe.nodes.vr[node];
        }
        cellVelocity.insert(cellVelocity.end(), {static_cast<float>(vz / kCorners),
                                                 static_cast<float>(vr / kCorners), 0.0F});
    }
    addReal(block, kNodeVelocity3.name, vector3(fe.nodes.vz, fe.nodes.vr, liveNodes));
    copyTableFields(block, fe.nodes, kNodePrefix, liveNodes);
    addReal(block, kVelocity3.name, std::move(cellVelocity));
    copyTableFields(block, fe.elements, {}, liveElements);
    addSlot(block, liveElements);
    sortByTable(block);
    return block;
}

} // namespace hvi::io
