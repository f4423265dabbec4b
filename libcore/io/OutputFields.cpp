#include "io/OutputFields.hpp"

#include <cmath>

namespace hvi::io {

std::string_view toString(ElementType type) {
    switch (type) {
    case ElementType::Float64:
        return "float64";
    case ElementType::Int32:
        return "int32";
    case ElementType::UInt8:
        return "uint8";
    case ElementType::Int64:
        return "int64";
    case ElementType::Float32:
        return "float32";
    }
    return "?";
}

double cgsConversionFactor(UnitDimensions dimensions) {
    constexpr double kCmPerMm = 0.1;
    constexpr double kGramPerMg = 1.0e-3;
    constexpr double kSecondPerUs = 1.0e-6;
    return std::pow(kCmPerMm, dimensions.length) * std::pow(kGramPerMg, dimensions.mass) *
           std::pow(kSecondPerUs, dimensions.time);
}

namespace {

template <class Fields>
constexpr auto specsOf() {
    constexpr const auto& entries = FieldTable<Fields>::entries;
    std::array<FieldSpec, entries.size()> specs{};
    for (std::size_t i = 0; i < entries.size(); ++i) {
        specs[i] = entries[i].spec;
    }
    return specs;
}

constexpr auto kParticleSpecs = specsOf<ParticleFieldsView>();
constexpr auto kNodeSpecs = specsOf<FeNodeFieldsView>();
constexpr auto kElementSpecs = specsOf<FeElementFieldsView>();
constexpr auto kHistorySpecs = specsOf<HistoryRow>();

} // namespace

std::span<const FieldSpec> particleFieldSpecs() {
    return kParticleSpecs;
}
std::span<const FieldSpec> nodeFieldSpecs() {
    return kNodeSpecs;
}
std::span<const FieldSpec> elementFieldSpecs() {
    return kElementSpecs;
}
std::span<const FieldSpec> historyColumnSpecs() {
    return kHistorySpecs;
}

const FieldSpec* findFieldSpec(std::span<const FieldSpec> specs, std::string_view name) {
    for (const auto& spec : specs) {
        if (spec.name == name) {
            return &spec;
        }
    }
    return nullptr;
}

} // namespace hvi::io
