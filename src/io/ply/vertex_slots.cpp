#include "io/ply/vertex_slots.hpp"

#include <algorithm>
#include <bit>
#include <utility>

namespace raster::detail {
namespace {

// Property names as assimp 5.2.5's PLY reader takes them (PlyParser's semantics).
constexpr std::array<std::pair<std::string_view, VertexSlots::Slot>, 21> kNames{{
    {"x", VertexSlots::x},         {"y", VertexSlots::y},     {"z", VertexSlots::z},       {"nx", VertexSlots::nx},
    {"ny", VertexSlots::ny},       {"nz", VertexSlots::nz},   {"red", VertexSlots::red},   {"r", VertexSlots::red},
    {"green", VertexSlots::green}, {"g", VertexSlots::green}, {"blue", VertexSlots::blue}, {"b", VertexSlots::blue},
    {"alpha", VertexSlots::alpha}, {"u", VertexSlots::u},     {"s", VertexSlots::u},       {"tx", VertexSlots::u},
    {"texture_u", VertexSlots::u}, {"v", VertexSlots::v},     {"t", VertexSlots::v},       {"ty", VertexSlots::v},
    {"texture_v", VertexSlots::v},
}};

}  // namespace

VertexSlots::VertexSlots(const PlyElement& element, bool keep_places) : keep_places_(keep_places) {
    for (std::size_t k = 0; k < element.properties.size(); ++k) {
        const PlyProperty& p = element.properties[k];
        if (p.list) continue;
        for (const auto& [name, slot] : kNames) {
            if (name != p.name) continue;
            at_[slot] = k;  // the last of a name, as assimp reads it
            types_[slot] = p.type;
        }
    }
    normals_ = any(nx, red);
    colours_ = any(red, u);
    uvs_ = any(u, count);
    for (std::size_t b = 0; b < linear_bytes_.size(); ++b)
        linear_bytes_[b] = static_cast<float>(linear_from_srgb_channel(static_cast<float>(b) / 255.0F));
}

bool VertexSlots::reads(std::string_view name) noexcept {
    return std::any_of(kNames.begin(), kNames.end(), [&](const auto& known) { return known.first == name; });
}

void VertexSlots::reserve(PlyBody& body, std::uint64_t vertices) const {
    body.places_kept = keep_places_;
    body.positions.reserve(vertices);
    if (normals_) body.normals.reserve(vertices);
    if (uvs_) body.uvs.reserve(vertices);
    if (colours_) body.colours.reserve(vertices);
    if (at_[alpha] != kNone) body.alphas.reserve(vertices);
}

bool VertexSlots::plain(bool big) const noexcept {
    if (big != (std::endian::native == std::endian::big)) return false;
    const auto all = [&](Slot from, Slot to, PlyType type) {
        return std::all_of(at_.begin() + from, at_.begin() + to, [](std::size_t p) { return p != kNone; }) &&
               std::all_of(types_.begin() + from, types_.begin() + to, [&](PlyType t) { return t == type; });
    };
    return all(x, nx, PlyType::float32) && (!normals_ || all(nx, red, PlyType::float32)) &&
           (!colours_ || all(red, alpha, PlyType::uint8)) && at_[alpha] == kNone && !uvs_;
}

float VertexSlots::scaled(double value, PlyType type) noexcept {
    // assimp's NormalizeColorValue, its quirks for signed and 32-bit integers kept.
    switch (type) {
    case PlyType::float32:
    case PlyType::float64: return static_cast<float>(value);
    case PlyType::uint8: return static_cast<float>(value) / 255.0F;
    case PlyType::int8: return static_cast<float>(value + 127.0) / 255.0F;
    case PlyType::uint16: return static_cast<float>(value) / 65535.0F;
    case PlyType::int16: return static_cast<float>(value + 32767.0) / 65535.0F;
    case PlyType::uint32: return static_cast<float>(value) / 65535.0F;
    case PlyType::int32: return static_cast<float>(value) / 255.0F + 0.5F;
    }
    return 0.0F;
}

}  // namespace raster::detail
