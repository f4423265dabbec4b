// The XDMF sidecar of a run file (run.h5 -> run.xmf), so ParaView and VisIt can open the
// snapshots (after SWIFT's xmf.c; XDMF 2 syntax, heavy data referenced as
// `run.h5:/snapshots/000000/View/Particles/Points`).
//
// It describes each snapshot's View/ group (RunFileView.hpp: the live material only), as one
// temporal collection per block, so a block keeps its name at every time:
//  - "Particles": vertex cells (Polyvertex, one point each), every field cell data;
//  - "FiniteElements" (runs with a mesh): Quadrilateral cells, node fields point data,
//    element fields cell data.
// Geometry is XYZ = (Z, R, 0): the shot travels along +X and the symmetry axis is the X axis
// (the convention of 2D axisymmetric hydrocodes such as AUTODYN). Lengths are in mm, time in
// us. A block with nothing alive at a time is a grid of one point at the origin and no cells
// (XDMF readers reject zero-sized arrays, and a time left out would show the previous one).
//
// Checked with Debian's ParaView 5.11 (tests/paraview/): the "XDMF Reader" names the blocks
// Particles and FiniteElements; "Xdmf3 Reader T" gives the same blocks as Block0 and Block1;
// "Xdmf3 Reader S", which pvpython's OpenDataFile picks, reads the blocks as two pieces of
// one dataset. All three give the same time values, points, cells and arrays.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace hvi::io {

/// What one block of a snapshot's view holds (RunFileView.hpp).
struct ViewBlockLayout {
    std::size_t pointCount = 0;
    std::size_t cellCount = 0;
    std::vector<std::string> arrays; ///< datasets present, viewArraySpecs order
};

/// What one snapshot group holds: enough to describe it without reading the data.
struct SnapshotLayout {
    std::string group; ///< "/snapshots/000000"
    double timeUs = 0.0;
    long step = 0;
    bool hasFe = false;
    ViewBlockLayout particles; ///< group/View/Particles
    ViewBlockLayout mesh;      ///< group/View/FiniteElements, when hasFe
};

/// The XDMF text for the run file named `h5FileName` (a file name relative to the XDMF file,
/// normally just "run.h5": the two files sit side by side).
std::string runFileXdmf(const std::string& h5FileName, const std::vector<SnapshotLayout>& layout);

} // namespace hvi::io
