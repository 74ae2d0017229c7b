#pragma once

#include <raster/image/colour.hpp>

#include "io/ply/ply_body.hpp"
#include "io/ply/ply_layout.hpp"
#include "io/vertex_alpha.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string_view>

// Which of a vertex element's properties raster reads, by the names assimp's PLY reader gives
// meaning to, and one vertex's values turned into raster's (doc/conventions.md#ply-reader).
namespace raster::detail {

class VertexSlots {
public:
    enum Slot : std::size_t { x, y, z, nx, ny, nz, red, green, blue, alpha, u, v, count };

    VertexSlots() = default;
    // `keep_places`: a vertex whose position is not finite stays, as NaN, so that faces count right.
    VertexSlots(const PlyElement& element, bool keep_places);

    // Whether a vertex property of this name (not a list) is one raster reads.
    [[nodiscard]] static bool reads(std::string_view name) noexcept;
    // Whether any property is one raster reads (assimp reads no vertex of an element without one).
    [[nodiscard]] bool readable() const noexcept { return any(x, count); }
    void reserve(PlyBody& body, std::uint64_t vertices) const;

    // Appends the vertex whose property p has the value value_of(p) to `body`.
    template <typename ValueOf>
    void keep(const ValueOf& value_of, PlyBody& body) const {
        const auto read = [&](Slot s) { return at_[s] == kNone ? 0.0F : static_cast<float>(value_of(at_[s])); };
        const float px = read(x), py = read(y), pz = read(z);
        if (!std::isfinite(px) || !std::isfinite(py) || !std::isfinite(pz)) return keep_non_finite(body);
        body.positions.emplace_back(px, py, -pz);
        if (normals_) keep_normal(read(nx), read(ny), read(nz), body);
        if (uvs_) {
            const float s = read(u), t = read(v);
            body.uvs.emplace_back(std::isfinite(s) ? s : 0.0F, std::isfinite(t) ? t : 0.0F);
        }
        if (colours_)
            body.colours.push_back({channel(red, value_of), channel(green, value_of), channel(blue, value_of)});
        // Alpha is coverage, scaled like the colour bytes but not decoded from sRGB.
        if (at_[alpha] != kNone)
            body.alphas.push_back(vertex_alpha(scaled(value_of(at_[alpha]), types_[alpha]), body.unreadable_alphas));
    }

    // Whether every property read is a float32 position or normal or a uint8 colour, written in
    // the machine's byte order (`big` or not): then a record is read as it lies (keep_plain).
    [[nodiscard]] bool plain(bool big) const noexcept;
    // keep() for a plain binary record at `record`, property p at byte offsets[p] in it.
    void keep_plain(const std::uint8_t* record, const std::size_t* offsets, PlyBody& body) const {
        const auto at = [&](Slot s) {
            float value = 0.0F;
            std::memcpy(&value, record + offsets[at_[s]], sizeof value);
            return value;
        };
        const float px = at(x), py = at(y), pz = at(z);
        if (!std::isfinite(px) || !std::isfinite(py) || !std::isfinite(pz)) return keep_non_finite(body);
        body.positions.emplace_back(px, py, -pz);
        if (normals_) keep_normal(at(nx), at(ny), at(nz), body);
        if (colours_) {
            body.colours.push_back({linear_bytes_[record[offsets[at_[red]]]],
                                    linear_bytes_[record[offsets[at_[green]]]],
                                    linear_bytes_[record[offsets[at_[blue]]]]});
        }
    }

private:
    static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

    // A vertex whose position is not finite: counted, and kept as NaN where places count.
    void keep_non_finite(PlyBody& body) const {
        ++body.non_finite;
        if (!keep_places_) return;
        body.positions.emplace_back(std::numeric_limits<float>::quiet_NaN());
        if (normals_) body.normals.emplace_back(0.0F);
        if (uvs_) body.uvs.emplace_back(0.0F);
        if (colours_) body.colours.push_back({1.0F, 1.0F, 1.0F});
        if (at_[alpha] != kNone) body.alphas.push_back(1.0F);
    }
    void keep_normal(float a, float b, float c, PlyBody& body) const {
        const bool finite = std::isfinite(a) && std::isfinite(b) && std::isfinite(c);
        const glm::vec3 n = finite ? glm::vec3(a, b, -c) : glm::vec3(0.0F);
        // A cloud's points keep the file's normal made unit; faces' corners are made so later.
        body.normals.push_back(keep_places_ ? n : unit_or_zero(n));
    }

    [[nodiscard]] bool any(Slot from, Slot to) const noexcept {
        return std::any_of(at_.begin() + from, at_.begin() + to, [](std::size_t p) { return p != kNone; });
    }

    // A colour channel in [0, 1] as assimp scales each type (doc/conventions.md#vertex-colours),
    // then decoded from sRGB: bytes through the table, as the formula gives them.
    template <typename ValueOf>
    float channel(Slot s, const ValueOf& value_of) const {
        // A byte is its own table index, the value the general path gives it; ASCII may write more than 255.
        if (types_[s] == PlyType::uint8 && at_[s] != kNone) {
            if (const double byte = value_of(at_[s]); byte <= 255.0)
                return linear_bytes_[static_cast<std::size_t>(byte)];
        }
        const float written = at_[s] == kNone ? 0.0F : scaled(value_of(at_[s]), types_[s]);
        const float c = std::isfinite(written) ? std::clamp(written, 0.0F, 1.0F) : 1.0F;
        const auto b = static_cast<std::size_t>(c * 255.0F + 0.5F);
        if (static_cast<float>(b) / 255.0F == c) return linear_bytes_[b];
        return static_cast<float>(linear_from_srgb_channel(c));
    }
    [[nodiscard]] static float scaled(double value, PlyType type) noexcept;

    std::array<std::size_t, count> at_{kNone, kNone, kNone, kNone, kNone, kNone,
                                       kNone, kNone, kNone, kNone, kNone, kNone};
    std::array<PlyType, count> types_{};
    bool keep_places_ = false, normals_ = false, uvs_ = false, colours_ = false;
    std::array<float, 256> linear_bytes_{};
};

}  // namespace raster::detail
