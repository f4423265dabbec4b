// Structured quad meshes with gmsh; conventions in the header.
#include "geometry/GmshMesher.hpp"

#include "core/Error.hpp"

#include <atomic>
#include <cmath>
#include <exception>
#include <gmsh.h>
#include <omp.h>
#include <stdexcept>
#include <system_error>

namespace hvi::geometry {

namespace fs = std::filesystem;

namespace {

/// A count within this (relative) of a whole number is that number: 0.03 / 0.015 must give
/// 2 elements, not 3, whatever the rounding of the quotient.
constexpr double kWholeSnap = 1e-9;

/// Above this many quadrilaterals the request is surely a unit mistake (and the file would
/// be gigabytes).
constexpr double kMaxElements = 5.0e7;

/// gmsh element type of the 4-node quadrilateral.
constexpr int kQuad4 = 3;

std::atomic<bool> g_sessionOpen{false};

/// One gmsh session: initialised quietly, always finalised, and the caller's OpenMP thread
/// count restored. gmsh sets the OpenMP thread count to its General.NumThreads (1 by
/// default) for the whole process; left so, every scene with an FE body ran its simulation
/// on one thread whatever --threads asked for.
class GmshSession {
public:
    GmshSession() : m_threads(omp_get_max_threads()) {
        if (g_sessionOpen.exchange(true)) {
            throw std::logic_error("GmshMesher: a gmsh session is already open");
        }
        try {
            gmsh::initialize(0, nullptr, false); // no gmshrc / option files
            gmsh::option::setNumber("General.Terminal", 0);
            gmsh::option::setNumber("General.Verbosity", 0);
        } catch (...) {
            g_sessionOpen = false;
            throw;
        }
    }
    ~GmshSession() {
        try {
            gmsh::finalize();
        } catch (...) {
            // finalize only frees memory; nothing a caller could do about a failure here
        }
        omp_set_num_threads(m_threads);
        g_sessionOpen = false;
    }
    GmshSession(const GmshSession&) = delete;
    GmshSession& operator=(const GmshSession&) = delete;

private:
    int m_threads;
};

void checkRectangle(const MeshRectangle& rect) {
    const bool ok = std::isfinite(rect.zMinMm) && std::isfinite(rect.zMaxMm) &&
                    std::isfinite(rect.rMinMm) && std::isfinite(rect.rMaxMm) &&
                    rect.zMaxMm > rect.zMinMm && rect.rMaxMm > rect.rMinMm && rect.rMinMm >= 0.0 &&
                    std::isfinite(rect.elementSizeMm) && rect.elementSizeMm > 0.0;
    if (!ok) {
        throw std::invalid_argument("GmshMesher: body '" + rect.name +
                                    "' is not a non-empty rectangle with r >= 0 and a positive "
                                    "element size");
    }
}

} // namespace

std::size_t GmshMesher::divisions(double lengthMm, double elementSizeMm) {
    const double exact = lengthMm / elementSizeMm;
    const double nearest = std::round(exact);
    const double n = std::fabs(exact - nearest) <= kWholeSnap * std::max(1.0, nearest)
                         ? nearest
                         : std::ceil(exact);
    return static_cast<std::size_t>(std::max(1.0, n));
}

MeshCounts GmshMesher::expectedCounts(const std::vector<MeshRectangle>& rectangles) {
    MeshCounts counts;
    for (const auto& rect : rectangles) {
        checkRectangle(rect);
        const std::size_t nz = divisions(rect.zMaxMm - rect.zMinMm, rect.elementSizeMm);
        const std::size_t nr = divisions(rect.rMaxMm - rect.rMinMm, rect.elementSizeMm);
        counts.elements += nz * nr;
        counts.nodes += (nz + 1) * (nr + 1);
    }
    return counts;
}

MeshCounts GmshMesher::write(const std::vector<MeshRectangle>& rectangles, const fs::path& path) {
    if (rectangles.empty()) {
        throw std::invalid_argument("GmshMesher: no rectangle to mesh");
    }
    const MeshCounts expected = expectedCounts(rectangles);
    if (static_cast<double>(expected.elements) > kMaxElements) {
        throw RuntimeFailure("mesh of " + std::to_string(expected.elements) +
                             " quadrilaterals is too large to write (limit " +
                             std::to_string(static_cast<long long>(kMaxElements)) +
                             "); use a larger element size");
    }

    // gmsh chooses the format from the extension: write NAME.msh, then rename to NAME.
    fs::path gmshPath = path;
    gmshPath += ".msh";
    struct RemoveOnExit {
        fs::path file;
        ~RemoveOnExit() {
            std::error_code ignored;
            fs::remove(file, ignored);
        }
    } cleanup{gmshPath};

    MeshCounts counts;
    GmshSession session;
    try {
        gmsh::model::add("scene");
        gmsh::option::setNumber("Mesh.MshFileVersion", 4.1);
        gmsh::option::setNumber("Mesh.Binary", 0);
        gmsh::option::setNumber("Mesh.SaveAll", 0);
        std::vector<int> surfaces;
        for (const auto& rect : rectangles) {
            namespace geo = gmsh::model::geo;
            const int p1 = geo::addPoint(rect.zMinMm, rect.rMinMm, 0.0);
            const int p2 = geo::addPoint(rect.zMaxMm, rect.rMinMm, 0.0);
            const int p3 = geo::addPoint(rect.zMaxMm, rect.rMaxMm, 0.0);
            const int p4 = geo::addPoint(rect.zMinMm, rect.rMaxMm, 0.0);
            const int lz1 = geo::addLine(p1, p2);
            const int lr1 = geo::addLine(p2, p3);
            const int lz2 = geo::addLine(p3, p4);
            const int lr2 = geo::addLine(p4, p1);
            const int loop = geo::addCurveLoop({lz1, lr1, lz2, lr2});
            const int surface = geo::addPlaneSurface({loop});
            const auto nz =
                static_cast<int>(divisions(rect.zMaxMm - rect.zMinMm, rect.elementSizeMm));
            const auto nr =
                static_cast<int>(divisions(rect.rMaxMm - rect.rMinMm, rect.elementSizeMm));
            geo::mesh::setTransfiniteCurve(lz1, nz + 1);
            geo::mesh::setTransfiniteCurve(lz2, nz + 1);
            geo::mesh::setTransfiniteCurve(lr1, nr + 1);
            geo::mesh::setTransfiniteCurve(lr2, nr + 1);
            geo::mesh::setTransfiniteSurface(surface);
            geo::mesh::setRecombine(2, surface);
            surfaces.push_back(surface);
        }
        gmsh::model::geo::synchronize();
        for (std::size_t i = 0; i < rectangles.size(); ++i) {
            const int group = gmsh::model::addPhysicalGroup(2, {surfaces[i]});
            gmsh::model::setPhysicalName(2, group, rectangles[i].name);
        }
        gmsh::model::mesh::generate(2);

        std::vector<int> types;
        std::vector<std::vector<std::size_t>> tags;
        std::vector<std::vector<std::size_t>> nodeTags;
        gmsh::model::mesh::getElements(types, tags, nodeTags, 2);
        for (std::size_t i = 0; i < types.size(); ++i) {
            if (types[i] != kQuad4) {
                throw RuntimeFailure("gmsh produced elements of type " + std::to_string(types[i]) +
                                     ", not only 4-node quadrilaterals");
            }
            counts.elements += tags[i].size();
        }
        std::vector<std::size_t> allNodes;
        std::vector<double> coords;
        std::vector<double> parametric;
        gmsh::model::mesh::getNodes(allNodes, coords, parametric, -1, -1, false, false);
        counts.nodes = allNodes.size();
        gmsh::write(gmshPath.string());
    } catch (const RuntimeFailure&) {
        throw;
    } catch (...) {
        // gmsh reports errors by throwing (General.AbortOnError 2), not always a
        // std::exception; its logger holds the message.
        std::string message;
        try {
            gmsh::logger::getLastError(message);
        } catch (...) {
            message.clear();
        }
        if (message.empty()) {
            try {
                throw;
            } catch (const std::exception& e) {
                message = e.what();
            } catch (...) {
                message = "unknown gmsh error";
            }
        }
        throw RuntimeFailure("gmsh failed to mesh or write " + path.string() + ": " + message);
    }
    if (counts.elements != expected.elements) {
        throw RuntimeFailure("gmsh produced " + std::to_string(counts.elements) +
                             " quadrilaterals, expected the structured " +
                             std::to_string(expected.elements));
    }
    std::error_code ec;
    fs::rename(gmshPath, path, ec);
    if (ec) {
        throw RuntimeFailure("cannot move " + gmshPath.string() + " to " + path.string() + ": " +
                             ec.message());
    }
    return counts;
}

} // namespace hvi::geometry
