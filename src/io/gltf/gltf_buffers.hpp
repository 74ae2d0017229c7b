#pragma once

#include "io/gltf/json_fields.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string_view>
#include <vector>

// glTF's buffers, buffer views and accessors: every size checked against the bytes behind it.
namespace raster::detail::gltf_json {

struct View {
    std::uint64_t length;
    std::uint64_t stride;
};

// Each buffer's declared length, checked against the bytes behind it: the binary chunk's for a
// .glb's first buffer without a URI, else `external_size` of its URI (nothing: not checked).
std::vector<std::uint64_t> buffer_lengths(
    const Json& root, std::optional<std::uint64_t> binary_chunk,
    const std::function<std::optional<std::uint64_t>(std::string_view)>& external_size);

// Each buffer view, checked to lie inside its buffer.
std::vector<View> buffer_views(const Json& root, const std::vector<std::uint64_t>& buffers);

// Throws Broken for an accessor (or its sparse part) that reads past its buffer view.
void check_accessors(const Json& root, const std::vector<View>& views);

}  // namespace raster::detail::gltf_json
