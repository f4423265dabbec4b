// What the XDMF sidecar shows of a snapshot: the live material only, in the shapes every
// ParaView XDMF reader takes. The run file keeps every particle slot and element so that the
// tools can follow them from snapshot to snapshot; a viewer drawing those would show the
// reserved slots of eroded elements, deleted particles where they died, eroded elements and
// the nodes they left behind. So each snapshot also holds a `View/` group (run-file format 2):
//
//   View/Particles/       the alive particles: Points (N, 3) = (Z, R, 0), Cells (N) = 0..N-1
//                         (one vertex cell per particle), and one cell array per field
//   View/FiniteElements/  the alive elements: Cells (Ne, 4) into Points (Nn, 3), the nodes of
//                         alive elements only; node arrays (Node*) and cell arrays
//
// Every field both blocks have (Density, Pressure, Damage, PlasticStrain, BodyId, Velocity)
// is cell data in both, so one colour map serves both blocks. Particle and element fields are
// copied from the run-file tables (OutputFields.hpp) by their names; the view adds the
// velocity as a vector (for glyphs), the stress deviator as named components with the hoop
// one, an element's velocity (the mean of its nodes'), and Slot, the index of the item in the
// snapshot's own datasets. Points are three-component (R = Y, 0 = Z in ParaView) because the
// Xdmf3 readers crash on a geometry assembled from two arrays.
//
// The view's reals are single precision: it is for looking at, and the run file keeps every
// value in double (seven digits resolve 0.01 mm over 100 mm and any field to 1e-7 of itself).
// Units are those of the run file (docs/conventions.md): mm, km/s, g/cm3, GPa, MJ/kg, mg.
#pragma once

#include "io/OutputFields.hpp"

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace hvi::io {

enum class ViewBlockKind { Particles, FiniteElements };
enum class ViewCentre { Point, Cell };

/// One array of a view block: its dataset (name in the view, type, components, units,
/// description) and whether ParaView gets it per point or per cell.
struct ViewArraySpec {
    FieldSpec field;
    ViewCentre centre;
};

/// Every array a block of this kind may hold, in the order they are written.
std::span<const ViewArraySpec> viewArraySpecs(ViewBlockKind kind);

/// The spec named `name` among the block's arrays, or nullptr.
const ViewArraySpec* findViewArraySpec(ViewBlockKind kind, std::string_view name);

/// The geometry dataset ("Points", (N, 3): Z, R, 0) and topology dataset ("Cells") of a block.
const FieldSpec& viewPointsSpec();
const FieldSpec& viewCellsSpec(ViewBlockKind kind);

/// The block's name in the run file and the XDMF: "Particles" or "FiniteElements".
std::string_view viewBlockName(ViewBlockKind kind);

/// Vertices per cell: 1 (a particle is a vertex cell) or 4 (a quadrilateral element).
int viewNodesPerCell(ViewBlockKind kind);

struct ViewArray {
    const ViewArraySpec* spec = nullptr;
    std::vector<float> real;           ///< when spec->field.type is Float32
    std::vector<std::int32_t> integer; ///< when it is Int32
};

/// One block of a snapshot's view. Empty (no points) when nothing of the kind is alive.
struct ViewBlock {
    ViewBlockKind kind = ViewBlockKind::Particles;
    std::size_t pointCount = 0;
    std::size_t cellCount = 0;
    std::vector<float> points;       ///< 3 per point: (Z, R, 0)
    std::vector<std::int32_t> cells; ///< viewNodesPerCell(kind) per cell, into points
    std::vector<ViewArray> arrays;   ///< the present ones, in viewArraySpecs order
};

/// The alive particles (Alive != 0) of a snapshot.
ViewBlock particleView(const ParticleFieldsView& particles);

/// The alive elements of a snapshot and the nodes they use, renumbered in node order.
ViewBlock meshView(const FeFieldsView& fe);

} // namespace hvi::io
