#include "io/vertex_ids.hpp"

namespace raster::detail {

std::pair<std::uint32_t, bool> VertexIds::find_or_add(int material, const VertexKey& key, std::uint32_t id) {
    std::uint32_t& head = heads_[static_cast<std::size_t>(key.position)];
    for (std::uint32_t at = head; at != 0; at = made_[at - 1].next) {
        const Made& made = made_[at - 1];
        if (made.material == material && made.key == key) return {made.id, false};
    }
    made_.push_back({key, material, id, head});
    head = static_cast<std::uint32_t>(made_.size());
    return {id, true};
}

}  // namespace raster::detail
