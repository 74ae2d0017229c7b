#pragma once

#include "io/gltf/gltf_facts.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

// A glTF file's structure checked before assimp reads it: every size it declares against the
// bytes there are, every index against what it indexes, the nesting of its JSON and its nodes,
// so that a few hundred bytes cannot overflow a stack or claim gigabytes (doc/conventions.md#models).
namespace raster::detail {

// The deepest JSON nesting read; real files nest under 20 deep.
inline constexpr int kMaxJsonDepth = 64;
// The deepest node hierarchy read, and the most node instances a scene may expand to when
// nodes are shared (a graph of reused nodes grows exponentially).
inline constexpr int kMaxGltfNodeDepth = 256;
inline constexpr std::uint64_t kMaxGltfNodeInstances = std::uint64_t{1} << 18;

// "" when the .gltf text or .glb file `bytes` holds together, else the first problem, as the end
// of a sentence about the file. `external_size` gives the size of a buffer the file names by
// URI, or nothing when it cannot be read (its reader says why later).
// What the file says beyond what assimp reads goes to `facts` when given: the names in
// extensionsUsed and extensionsRequired once each, the materials' extensions and the cameras.
[[nodiscard]] std::string gltf_structure_problem(
    std::span<const std::uint8_t> bytes, bool binary,
    const std::function<std::optional<std::uint64_t>(std::string_view uri)>& external_size, GltfFacts* facts = nullptr);

}  // namespace raster::detail
