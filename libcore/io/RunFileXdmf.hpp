// The XDMF sidecar of a run file (run.h5 -> run.xmf), so ParaView and VisIt can open the
// snapshots (after SWIFT's xmf.c; XDMF 2 syntax, heavy data referenced as
// `run.h5:/snapshots/000000/Z`).
//
// Layout: one temporal collection; per snapshot a spatial collection holding
//  - grid "Particles": Polyvertex topology, every particle dataset of the snapshot as a
//    node-centred attribute;
//  - grid "FiniteElements" (when the snapshot has a mesh): Quadrilateral topology from
//    Elements/Connectivity, node datasets node-centred, element datasets cell-centred.
// Geometry is GeometryType "X_Y" with X = Z (axial, along the shot line) and Y = R (radial),
// so the shot travels along +X in ParaView and the symmetry axis is the X axis (the
// convention of 2D axisymmetric hydrocodes such as AUTODYN). Lengths are in mm, time in us.
// A grid with no items (no particles, or no elements) is left out: XDMF readers reject
// zero-sized arrays.
//
// In ParaView open it with the "XDMF Reader" (checked with ParaView 5.11's pvbatch: time
// steps, both grids, every array with its type). ParaView 5.11's "Xdmf3 Reader S/T" crash
// on any geometry assembled from two arrays (X_Y, or a JOIN function) -- they need one
// (N, 2) coordinates dataset, which would duplicate Z and R in every snapshot.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace hvi::io {

/// What one snapshot group holds: enough to describe it without reading the data.
struct SnapshotLayout {
    std::string group; ///< "/snapshots/000000"
    double timeUs = 0.0;
    long step = 0;
    std::size_t particleCount = 0;
    std::vector<std::string> particleFields; ///< datasets present, table order
    bool hasFe = false;
    std::size_t nodeCount = 0;
    std::size_t elementCount = 0;
    std::vector<std::string> nodeFields;    ///< datasets present under group/Nodes
    std::vector<std::string> elementFields; ///< datasets present under group/Elements
};

/// The XDMF text for the run file named `h5FileName` (a file name relative to the XDMF file,
/// normally just "run.h5": the two files sit side by side).
std::string runFileXdmf(const std::string& h5FileName, const std::vector<SnapshotLayout>& layout);

} // namespace hvi::io
