#include <raster/io/stl_file.hpp>

#include "io/model_blocks.hpp"
#include "io/ply/ply_bytes.hpp"
#include "io/stl/stl_ascii.hpp"
#include "io/stl/stl_binary.hpp"
#include "io/stl/stl_words.hpp"

#include <raster/io/input_file.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

namespace raster {
namespace {

// Whether the text starts with "solid" in any letter case, after a byte order mark and white space.
bool says_solid(std::span<const std::uint8_t> head) {
    std::string_view text(reinterpret_cast<const char*>(head.data()), head.size());
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    const std::size_t first = text.find_first_not_of(" \t\r\n");
    return first != std::string_view::npos && detail::is_keyword(text.substr(first, 5), "solid");
}

// Binary by the size rule first (a binary header may well begin "solid"), then ASCII
// (doc/conventions.md#stl-reader).
Model stl_model(detail::PlyBytes& bytes, std::uint64_t size, const std::string& name, const ObjOptions& options,
                Model model) {
    const std::span<const std::uint8_t> head = bytes.ahead(512);
    if (detail::is_binary_stl(head, size)) return detail::read_binary_stl(bytes, name, options, std::move(model));
    const std::uint32_t claimed = detail::stl_claimed_count(head);
    const std::string as_binary =
        size < detail::kStlHeaderBytes
            ? "too short for a binary STL's 84-byte header"
            : "as a binary STL its triangle count, " + std::to_string(claimed) + ", needs " +
                  std::to_string(detail::kStlHeaderBytes + detail::kStlRecordBytes * std::uint64_t{claimed}) +
                  " bytes, and it has " + std::to_string(size);
    if (!says_solid(head)) throw std::runtime_error(name + ": not an STL model: not 'solid' text, and " + as_binary);
    const std::span<const std::uint8_t> first = head.first(std::min<std::size_t>(head.size(), 512));
    if (std::find(first.begin(), first.end(), std::uint8_t{0}) != first.end())  // later, StlWords names the line
        throw std::runtime_error(name + ": a binary STL whose count lies (" + as_binary + ")");
    return detail::read_ascii_stl(bytes, name, options, std::move(model));
}

}  // namespace

Model read_stl(const std::filesystem::path& path, const ObjOptions& options) {
    return detail::read_model_blocks(
        path, options, [&](detail::PlyBytes& bytes, std::uint64_t size, const std::string& name, Model model) {
            return stl_model(bytes, size, name, options, std::move(model));
        });
}

Model parse_stl(std::span<const std::uint8_t> bytes, const ObjOptions& options) {
    detail::PlyBytes source = detail::blocks_in_memory(bytes);
    return stl_model(source, bytes.size(), "<memory>", options, Model{});
}

}  // namespace raster
