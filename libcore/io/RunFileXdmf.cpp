#include "io/RunFileXdmf.hpp"

#include "io/OutputFields.hpp"
#include "io/RunFileView.hpp"

#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace hvi::io {

namespace {

std::string xmlEscape(const std::string& text) {
    std::string out;
    for (char c : text) {
        switch (c) {
        case '&':
            out += "&amp;";
            break;
        case '<':
            out += "&lt;";
            break;
        case '>':
            out += "&gt;";
            break;
        case '"':
            out += "&quot;";
            break;
        case '\'':
            out += "&apos;";
            break;
        default:
            out += c;
        }
    }
    return out;
}

/// Shortest text that reads back as the same double.
std::string exactNumber(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof(buffer), "%.17g", value);
    return buffer;
}

struct XdmfType {
    const char* numberType;
    int precision;
};

XdmfType xdmfType(ElementType type) {
    switch (type) {
    case ElementType::Float64:
        return {"Float", 8};
    case ElementType::Int32:
        return {"Int", 4};
    case ElementType::UInt8:
        return {"UChar", 1};
    case ElementType::Int64:
        return {"Int", 8};
    case ElementType::Float32:
        return {"Float", 4};
    }
    return {"Float", 8};
}

class XdmfText {
public:
    explicit XdmfText(std::string h5FileName) : m_file(xmlEscape(h5FileName)) {}

    void line(int indent, const std::string& text) {
        m_out << std::string(static_cast<std::size_t>(indent), ' ') << text << '\n';
    }

    void dataItem(int indent, const FieldSpec& spec, std::size_t count, const std::string& path) {
        const XdmfType type = xdmfType(spec.type);
        std::string dims = std::to_string(count);
        if (spec.components > 1) {
            dims += " " + std::to_string(spec.components);
        }
        line(indent, "<DataItem Dimensions=\"" + dims + "\" NumberType=\"" + type.numberType +
                         "\" Precision=\"" + std::to_string(type.precision) + "\" Format=\"HDF\">" +
                         m_file + ":" + xmlEscape(path) + "</DataItem>");
    }

    std::string str() const { return m_out.str(); }

private:
    std::string m_file;
    std::ostringstream m_out;
};

std::string blockGroup(const SnapshotLayout& snap, ViewBlockKind kind) {
    return snap.group + "/View/" + std::string(viewBlockName(kind));
}

/// A time at which nothing of the block is alive: one point at the origin, no cells.
void emptyGrid(XdmfText& x) {
    x.line(5, "<Topology TopologyType=\"Polyvertex\" NumberOfElements=\"0\" "
              "NodesPerElement=\"1\"/>");
    x.line(5, "<Geometry GeometryType=\"XYZ\">");
    x.line(6, "<DataItem Dimensions=\"1 3\" NumberType=\"Float\" Precision=\"8\" "
              "Format=\"XML\">0 0 0</DataItem>");
    x.line(5, "</Geometry>");
}

void blockGrid(XdmfText& x, const SnapshotLayout& snap, ViewBlockKind kind,
               const ViewBlockLayout& block) {
    const std::string name(viewBlockName(kind));
    x.line(4, "<Grid Name=\"" + name + "\" GridType=\"Uniform\">");
    x.line(5, "<Time Type=\"Single\" Value=\"" + exactNumber(snap.timeUs) + "\"/>");
    if (block.cellCount == 0) {
        emptyGrid(x);
        x.line(4, "</Grid>");
        return;
    }
    const std::string group = blockGroup(snap, kind);
    const char* topology = kind == ViewBlockKind::Particles ? "Polyvertex" : "Quadrilateral";
    x.line(5, "<Topology TopologyType=\"" + std::string(topology) + "\" NumberOfElements=\"" +
                  std::to_string(block.cellCount) + "\" NodesPerElement=\"" +
                  std::to_string(viewNodesPerCell(kind)) + "\">");
    x.dataItem(6, viewCellsSpec(kind), block.cellCount, group + "/Cells");
    x.line(5, "</Topology>");
    x.line(5, "<Geometry GeometryType=\"XYZ\">");
    x.dataItem(6, viewPointsSpec(), block.pointCount, group + "/Points");
    x.line(5, "</Geometry>");
    for (const auto& arrayName : block.arrays) {
        const ViewArraySpec* spec = findViewArraySpec(kind, arrayName);
        if (spec == nullptr) {
            // Layouts are built from the same table, so a miss is a programming error.
            throw std::logic_error("runFileXdmf: unknown view array " + arrayName);
        }
        const bool cell = spec->centre == ViewCentre::Cell;
        const char* type = spec->field.components == 1 ? "Scalar" : "Vector";
        x.line(5, "<Attribute Name=\"" + xmlEscape(arrayName) + "\" AttributeType=\"" + type +
                      "\" Center=\"" + (cell ? "Cell" : "Node") + "\">");
        x.dataItem(6, spec->field, cell ? block.cellCount : block.pointCount,
                   group + "/" + arrayName);
        x.line(5, "</Attribute>");
    }
    x.line(4, "</Grid>");
}

} // namespace

std::string runFileXdmf(const std::string& h5FileName, const std::vector<SnapshotLayout>& layout) {
    XdmfText x(h5FileName);
    x.line(0, "<?xml version=\"1.0\" ?>");
    x.line(0, "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>");
    x.line(0, "<!-- Snapshots of an hvi-run file, the live material only. Geometry XYZ = (Z, R, "
              "0): X along the shot line, Y radial; lengths in mm, velocities in km/s, "
              "pressures in GPa, time in us. -->");
    x.line(0, "<Xdmf Version=\"2.0\">");
    x.line(1, "<Domain>");
    bool anyParticles = false;
    bool anyMesh = false;
    for (const auto& snap : layout) {
        anyParticles = anyParticles || snap.particles.cellCount > 0;
        anyMesh = anyMesh || snap.hasFe;
    }
    for (const ViewBlockKind kind : {ViewBlockKind::Particles, ViewBlockKind::FiniteElements}) {
        const bool particles = kind == ViewBlockKind::Particles;
        if (!(particles ? anyParticles : anyMesh)) {
            continue;
        }
        x.line(2, "<Grid Name=\"" + std::string(viewBlockName(kind)) +
                      "\" GridType=\"Collection\" CollectionType=\"Temporal\">");
        for (const auto& snap : layout) {
            if (particles || snap.hasFe) {
                blockGrid(x, snap, kind, particles ? snap.particles : snap.mesh);
            }
        }
        x.line(2, "</Grid>");
    }
    x.line(1, "</Domain>");
    x.line(0, "</Xdmf>");
    return x.str();
}

} // namespace hvi::io
