#include "io/gltf/gltf_buffers.hpp"

#include <algorithm>

namespace raster::detail::gltf_json {
namespace {

std::uint64_t component_bytes(std::uint64_t type, const std::string& what) {
    switch (type) {
    case 5120:
    case 5121: return 1;
    case 5122:
    case 5123: return 2;
    case 5125:
    case 5126: return 4;
    default: throw Broken(what + " has component type " + std::to_string(type) + ", which glTF does not define");
    }
}

std::uint64_t components(const Json& accessor, const std::string& what) {
    const std::string type = accessor.value("type", std::string());
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4" || type == "MAT2") return 4;
    if (type == "MAT3") return 9;
    if (type == "MAT4") return 16;
    throw Broken(what + " has type '" + type.substr(0, 16) + "', which glTF does not define");
}

// `count` items of `size` bytes, `stride` apart, from `offset` in a view of `length` bytes.
bool fits(std::uint64_t offset, std::uint64_t count, std::uint64_t stride, std::uint64_t size, std::uint64_t length) {
    if (count == 0) return offset <= length;
    if (offset > length || size > length - offset) return false;
    return count - 1 <= (length - offset - size) / std::max<std::uint64_t>(stride, 1);
}

}  // namespace

// Each buffer's declared length, checked against the bytes behind it.
std::vector<std::uint64_t> buffer_lengths(
    const Json& root, std::optional<std::uint64_t> binary_chunk,
    const std::function<std::optional<std::uint64_t>(std::string_view)>& external_size) {
    std::vector<std::uint64_t> lengths;
    const Json& buffers = array_of(root, "buffers");
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        const std::string what = "buffer " + std::to_string(i);
        const std::uint64_t length = number_at(buffers[i], "byteLength", what);
        const auto uri = buffers[i].is_object() ? buffers[i].find("uri") : buffers[i].end();
        std::optional<std::uint64_t> there;
        if (uri == buffers[i].end() || !uri->is_string()) {
            there = i == 0 && binary_chunk ? *binary_chunk : 0;
        } else if (const std::string text = uri->get<std::string>(); text.starts_with("data:")) {
            const std::size_t comma = text.find(',');
            there = comma == std::string::npos ? 0 : (text.size() - comma - 1) / 4 * 3 + 2;
        } else {
            there = external_size(text);
        }
        if (there && length > *there) {
            throw Broken(what + " claims " + std::to_string(length) + " bytes, but only " + std::to_string(*there) +
                         " are there");
        }
        lengths.push_back(length);
    }
    return lengths;
}

std::vector<View> buffer_views(const Json& root, const std::vector<std::uint64_t>& buffers) {
    std::vector<View> views;
    const Json& list = array_of(root, "bufferViews");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string what = "buffer view " + std::to_string(i);
        const std::uint64_t buffer = index_at(list[i], "buffer", buffers.size(), what, "buffer").value_or(UINT64_MAX);
        if (buffer == UINT64_MAX) throw Broken(what + " names no buffer");
        const std::uint64_t offset = number_at(list[i], "byteOffset", what),
                            length = number_at(list[i], "byteLength", what);
        if (offset > buffers[buffer] || length > buffers[buffer] - offset)
            throw Broken(what + " runs past the end of buffer " + std::to_string(buffer));
        const std::uint64_t stride = number_at(list[i], "byteStride", what);
        if (stride != 0 && (stride < 4 || stride > 252))
            throw Broken(what + " has a byte stride of " + std::to_string(stride) + ", outside 4..252");
        views.push_back({length, stride});
    }
    return views;
}

void check_accessors(const Json& root, const std::vector<View>& views) {
    const Json& list = array_of(root, "accessors");
    for (std::size_t i = 0; i < list.size(); ++i) {
        const std::string what = "accessor " + std::to_string(i);
        const Json& accessor = list[i];
        if (!accessor.is_object()) throw Broken(what + " is not an object");
        const std::uint64_t element =
            component_bytes(number_at(accessor, "componentType", what), what) * components(accessor, what);
        const std::uint64_t count = number_at(accessor, "count", what);
        if (const auto view = index_at(accessor, "bufferView", views.size(), what, "buffer view")) {
            const std::uint64_t stride = views[*view].stride != 0 ? views[*view].stride : element;
            if (!fits(number_at(accessor, "byteOffset", what), count, stride, element, views[*view].length)) {
                throw Broken(what + " reads " + std::to_string(count) + " items past the end of buffer view " +
                             std::to_string(*view));
            }
        } else if (count > (std::uint64_t{1} << 30) / element) {
            throw Broken(what + " claims " + std::to_string(count) + " items with no data behind them");
        }
        const auto sparse = accessor.find("sparse");
        if (sparse == accessor.end()) continue;
        const std::uint64_t changed = number_at(*sparse, "count", what + "'s sparse part");
        if (changed > count)
            throw Broken(what + " changes " + std::to_string(changed) + " of its " + std::to_string(count) + " items");
        for (const char* part : {"indices", "values"}) {
            const auto found = sparse->find(part);
            if (found == sparse->end()) throw Broken(what + "'s sparse part has no " + part);
            const std::string where = what + "'s sparse " + part;
            const auto view = index_at(*found, "bufferView", views.size(), where, "buffer view");
            if (!view) throw Broken(where + " name no buffer view");
            const std::uint64_t size = std::string_view(part) == "indices"
                                           ? component_bytes(number_at(*found, "componentType", where), where)
                                           : element;
            if (!fits(number_at(*found, "byteOffset", where), changed, size, size, views[*view].length)) {
                throw Broken(where + " run past the end of buffer view " + std::to_string(*view));
            }
        }
    }
}

}  // namespace raster::detail::gltf_json
