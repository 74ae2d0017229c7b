#include <raster/io/ply_file.hpp>

#include "io/model_blocks.hpp"
#include "io/ply/ply_body.hpp"
#include "io/ply/ply_bytes.hpp"
#include "io/ply/ply_layout.hpp"
#include "io/ply/ply_model.hpp"
#include "io/ply/ply_reading.hpp"
#include "io/ply/ply_unread.hpp"
#include "io/ply_header.hpp"
#include "io/reader_process.hpp"

#include <raster/io/input_file.hpp>
#include <raster/io/model_file.hpp>

#include <algorithm>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace raster {
namespace {

// Checks the header's counts before anything is read: throws when they need too much memory.
// Sees the least the model takes by the header's counts, then what the body read turned out to need.
using Admission = std::function<void(std::uint64_t bytes)>;

// The model in `bytes`, or what `assimp` reads for a file that needs assimp's reader.
Model ply_model(detail::PlyBytes& bytes, const std::string& name, const ObjOptions& options, Model model,
                const std::function<Model()>& assimp, const Admission& admit = {}) {
    const std::span<const std::uint8_t> head = bytes.ahead(detail::kMaxPlyHeaderBytes);
    if (const std::string problem = detail::ply_header_problem(head); !problem.empty())
        throw std::runtime_error(name + ": " + problem);
    detail::PlyLayout layout;
    try {
        layout = detail::ply_layout(head);
    } catch (const std::runtime_error& problem) {
        throw std::runtime_error(name + ": " + problem.what());
    }
    // Named once, by this reader, whichever reads the file: scene files' reader knows nothing of PLY.
    const std::vector<std::string> unread = detail::ply_unread_warnings(layout, name, layout.needs_assimp);
    if (layout.needs_assimp) {
        Model theirs = assimp();
        // Read here (admitted), the fallback is a child whose own pass through this function named them.
        if (!admit) theirs.warnings.insert(theirs.warnings.end(), unread.begin(), unread.end());
        return theirs;
    }
    bytes.advance(layout.header_bytes);
    if (admit) admit(detail::least_ply_memory(layout, bytes.left()));
    detail::PlyBody body = detail::read_ply_body(layout, bytes, name);
    if (admit) admit(detail::ply_body_memory(body));  // a face of many corners is many triangles
    detail::model_from_ply(std::move(body), name, options, model);
    model.warnings.insert(model.warnings.end(), unread.begin(), unread.end());
    return model;
}

// Read by raster's own reader, or handed to `assimp`; `admit` sees the header first.
Model read_ply_file(const std::filesystem::path& path, const ObjOptions& options, const std::function<Model()>& assimp,
                    const Admission& admit) {
    return detail::read_model_blocks(path, options,
                                     [&](detail::PlyBytes& bytes, std::uint64_t, const std::string& name, Model model) {
                                         return ply_model(bytes, name, options, std::move(model), assimp, admit);
                                     });
}

}  // namespace

Model read_ply(const std::filesystem::path& path, const ObjOptions& options) {
    return read_ply_file(path, options, [&] { return read_scene_file(path, options); }, {});
}

namespace detail {

std::uint64_t least_ply_memory(const PlyLayout& layout, std::uint64_t body_bytes) noexcept {
    std::uint64_t bytes = 0;
    for (const PlyElement& element : layout.elements) {
        const std::uint64_t each = element.name == "vertex" ? 24 : element.name == "face" ? 36 : 0;
        const std::uint64_t most = body_bytes / ply_least_bytes(element, layout.encoding == PlyEncoding::ascii);
        bytes += std::min(element.count, most) * each;
    }
    return bytes;
}

std::uint64_t ply_body_memory(const PlyBody& body) noexcept {
    const std::uint64_t faces = body.face_starts.size(), corners = body.corners.size();
    return body.positions.size() * std::uint64_t{24} + (corners > 2 * faces ? corners - 2 * faces : 0) * 36;
}

Model read_ply_here(const std::filesystem::path& path, const ObjOptions& options,
                    const std::function<Model()>& elsewhere) {
    const std::string name = printable(path.string());
    return read_ply_file(path, options, elsewhere, [&](std::uint64_t bytes) {
        if (bytes > memory_in_force(options.limits))
            throw std::runtime_error(memory_refusal(name, "PLY", options.limits));
    });
}

}  // namespace detail

Model parse_ply(std::span<const std::uint8_t> bytes, const ObjOptions& options) {
    detail::PlyBytes source = detail::blocks_in_memory(bytes);
    return ply_model(source, "<memory>", options, Model{}, [&] { return parse_scene_file(bytes, "ply", options); });
}

}  // namespace raster
