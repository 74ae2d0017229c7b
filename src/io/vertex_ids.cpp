#include "io/vertex_ids.hpp"

namespace raster::detail {

std::size_t VertexIds::SpilledHash::operator()(const Spilled& s) const noexcept {
    const auto mix = [](std::uint64_t h, std::uint64_t v) { return (h ^ v) * 0x9E3779B97F4A7C15ULL; };
    std::uint64_t h = mix(static_cast<std::uint64_t>(s.key.position), static_cast<std::uint32_t>(s.material));
    h = mix(h, (std::uint64_t{s.key.normal_x} << 32) | s.key.normal_y);
    h = mix(h, (std::uint64_t{s.key.normal_z} << 32) ^ static_cast<std::uint64_t>(s.key.uv));
    h = mix(h, static_cast<std::uint64_t>(s.key.colour) ^ (static_cast<std::uint64_t>(s.key.tangent) << 17));
    return static_cast<std::size_t>(h ^ (h >> 31));
}

std::pair<std::uint32_t, bool> VertexIds::find_or_add(int material, const VertexKey& key, std::uint32_t id) {
    std::uint32_t& head = heads_[static_cast<std::size_t>(key.position)];
    if (head == kInTable) {
        const auto [at, added] = spilled_.try_emplace({key, material}, id);
        return {at->second, added};
    }
    std::size_t length = 0;
    for (std::uint32_t at = head; at != 0; at = made_[at - 1].next, ++length) {
        const Made& made = made_[at - 1];
        if (made.material == material && made.key == key) return {made.id, false};
    }
    if (length < kLongestChain) {
        made_.push_back({key, material, id, head});
        head = static_cast<std::uint32_t>(made_.size());
        return {id, true};
    }
    for (std::uint32_t at = head; at != 0; at = made_[at - 1].next)
        spilled_.try_emplace({made_[at - 1].key, made_[at - 1].material}, made_[at - 1].id);
    head = kInTable;
    spilled_.try_emplace({key, material}, id);
    return {id, true};
}

}  // namespace raster::detail
