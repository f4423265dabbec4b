#include "io/RunFileXdmf.hpp"

#include "io/OutputFields.hpp"

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

    void geometry(int indent, const FieldSpec& z, const FieldSpec& r, std::size_t count,
                  const std::string& group) {
        line(indent, "<Geometry GeometryType=\"X_Y\">");
        dataItem(indent + 1, z, count, group + "/" + std::string(z.name));
        dataItem(indent + 1, r, count, group + "/" + std::string(r.name));
        line(indent, "</Geometry>");
    }

    void attribute(int indent, const FieldSpec& spec, std::size_t count, const std::string& group,
                   const char* center) {
        const char* kind = spec.components == 1 ? "Scalar" : "Vector";
        line(indent, "<Attribute Name=\"" + std::string(spec.name) + "\" AttributeType=\"" + kind +
                         "\" Center=\"" + center + "\">");
        dataItem(indent + 1, spec, count, group + "/" + std::string(spec.name));
        line(indent, "</Attribute>");
    }

    std::string str() const { return m_out.str(); }

private:
    std::string m_file;
    std::ostringstream m_out;
};

const FieldSpec& spec(std::span<const FieldSpec> specs, std::string_view name) {
    const FieldSpec* found = findFieldSpec(specs, name);
    if (found == nullptr) {
        // Layouts are built from the same tables, so a miss is a programming error.
        throw std::logic_error("runFileXdmf: unknown field " + std::string(name));
    }
    return *found;
}

void particleGrid(XdmfText& x, const SnapshotLayout& snap) {
    const auto specs = particleFieldSpecs();
    const std::size_t n = snap.particleCount;
    x.line(4, "<Grid Name=\"Particles\" GridType=\"Uniform\">");
    x.line(5, "<Topology TopologyType=\"Polyvertex\" NumberOfElements=\"" + std::to_string(n) +
                  "\"/>");
    x.geometry(5, spec(specs, "Z"), spec(specs, "R"), n, snap.group);
    for (const auto& name : snap.particleFields) {
        x.attribute(5, spec(specs, name), n, snap.group, "Node");
    }
    x.line(4, "</Grid>");
}

void feGrid(XdmfText& x, const SnapshotLayout& snap) {
    const auto nodeSpecs = nodeFieldSpecs();
    const auto elementSpecs = elementFieldSpecs();
    const std::string nodes = snap.group + "/Nodes";
    const std::string elements = snap.group + "/Elements";
    x.line(4, "<Grid Name=\"FiniteElements\" GridType=\"Uniform\">");
    x.line(5, "<Topology TopologyType=\"Quadrilateral\" NumberOfElements=\"" +
                  std::to_string(snap.elementCount) + "\">");
    x.dataItem(6, spec(elementSpecs, "Connectivity"), snap.elementCount,
               elements + "/Connectivity");
    x.line(5, "</Topology>");
    x.geometry(5, spec(nodeSpecs, "Z"), spec(nodeSpecs, "R"), snap.nodeCount, nodes);
    for (const auto& name : snap.nodeFields) {
        x.attribute(5, spec(nodeSpecs, name), snap.nodeCount, nodes, "Node");
    }
    for (const auto& name : snap.elementFields) {
        if (name != "Connectivity") {
            x.attribute(5, spec(elementSpecs, name), snap.elementCount, elements, "Cell");
        }
    }
    x.line(4, "</Grid>");
}

} // namespace

std::string runFileXdmf(const std::string& h5FileName, const std::vector<SnapshotLayout>& layout) {
    XdmfText x(h5FileName);
    x.line(0, "<?xml version=\"1.0\" ?>");
    x.line(0, "<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>");
    x.line(0, "<!-- Snapshots of an hvi-run file. Geometry X_Y: X = Z (axial, along the shot "
              "line), Y = R (radial); "
              "lengths in mm, velocities in km/s, time in us. -->");
    x.line(0, "<Xdmf Version=\"2.0\">");
    x.line(1, "<Domain>");
    x.line(2, "<Grid Name=\"Snapshots\" GridType=\"Collection\" CollectionType=\"Temporal\">");
    for (const auto& snap : layout) {
        const bool particles = snap.particleCount > 0;
        const bool fe = snap.hasFe && snap.elementCount > 0 && snap.nodeCount > 0;
        if (!particles && !fe) {
            continue;
        }
        const std::string name = snap.group.substr(snap.group.rfind('/') + 1);
        x.line(3, "<Grid Name=\"" + xmlEscape(name) +
                      "\" GridType=\"Collection\" CollectionType=\"Spatial\">");
        x.line(4, "<Time Type=\"Single\" Value=\"" + exactNumber(snap.timeUs) + "\"/>");
        if (particles) {
            particleGrid(x, snap);
        }
        if (fe) {
            feGrid(x, snap);
        }
        x.line(3, "</Grid>");
    }
    x.line(2, "</Grid>");
    x.line(1, "</Domain>");
    x.line(0, "</Xdmf>");
    return x.str();
}

} // namespace hvi::io
