// Structured quadrilateral meshes of the FE bodies of a scene, written with the gmsh C++ API
// so that a designer can look at the reduced geometry (gmsh, ParaView via meshio) before a
// run. hvi-run builds its own FE mesh from the scene; this file is for the eye.
//
// Every body is a rectangle in the (z, r) half-plane; the mesh lies in gmsh's (x, y) plane
// with x = z and y = r (mm). Each rectangle is meshed on its own (bodies do not share
// nodes: in the scene they are separate bodies in contact) as a transfinite surface with
// n_z × n_r quadrilaterals, n = ceil(length / element size) (a length within 1e-9 relative
// of a whole number of elements counts as that number), at least 1. So the element edge is
// at most the requested size. Each rectangle is a physical surface named after its body;
// only those are saved (no boundary line elements), as MSH 4.1 ASCII.
//
// gmsh keeps global state: a session is opened (gmsh::initialize, no configuration files,
// terminal output off) and closed (gmsh::finalize) around each write, also when it fails,
// and two sessions never overlap in one process.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace hvi::geometry {

/// One FE body as an axis-aligned rectangle in (z, r).
struct MeshRectangle {
    std::string name;
    double zMinMm;
    double zMaxMm;
    double rMinMm;
    double rMaxMm;
    double elementSizeMm;
};

struct MeshCounts {
    std::size_t elements = 0; ///< quadrilaterals
    std::size_t nodes = 0;
};

class GmshMesher {
public:
    /// Elements along a length: ceil(length / size) with the 1e-9 snap, at least 1.
    static std::size_t divisions(double lengthMm, double elementSizeMm);
    /// The structured counts the rectangles will get (n_z·n_r quads, (n_z+1)(n_r+1) nodes).
    static MeshCounts expectedCounts(const std::vector<MeshRectangle>& rectangles);

    /// Meshes the rectangles and writes them to `path` (MSH 4.1 ASCII, whatever the name:
    /// gmsh writes `path`.msh, which is then renamed to `path`). Returns the counts gmsh
    /// produced. Throws RuntimeFailure when gmsh fails or the file cannot be written, and
    /// std::invalid_argument for an empty or degenerate rectangle.
    static MeshCounts write(const std::vector<MeshRectangle>& rectangles,
                            const std::filesystem::path& path);
};

} // namespace hvi::geometry
