#include <raster/io/ply_file.hpp>

#include "io/ply/ply_body.hpp"
#include "io/ply/ply_bytes.hpp"
#include "io/ply/ply_layout.hpp"
#include "io/ply/ply_model.hpp"
#include "io/ply/ply_unread.hpp"
#include "io/ply_header.hpp"

#include <raster/io/input_file.hpp>
#include <raster/io/model_file.hpp>

#include <algorithm>
#include <cstring>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace raster {
namespace {

// The model in `bytes`, or what `assimp` reads for a file that needs assimp's reader.
Model ply_model(detail::PlyBytes& bytes, const std::string& name, const ObjOptions& options, Model model,
                const std::function<Model()>& assimp) {
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
        theirs.warnings.insert(theirs.warnings.end(), unread.begin(), unread.end());
        return theirs;
    }
    bytes.advance(layout.header_bytes);
    detail::model_from_ply(detail::read_ply_body(layout, bytes, name), name, options, model);
    model.warnings.insert(model.warnings.end(), unread.begin(), unread.end());
    return model;
}

}  // namespace

Model read_ply(const std::filesystem::path& path, const ObjOptions& options) {
    const std::string name = printable(path.string());
    InputRules rules;
    rules.role = "model";
    rules.max_bytes = kMaxModelFileBytes;
    rules.confine = options.confine;
    try {
        InputFile file(path, rules);
        Model model;
        model.sources.push_back(file.record());
        detail::PlyBytes bytes([&file](std::span<std::uint8_t> into) { return file.read_some(into); }, file.size());
        return ply_model(bytes, name, options, std::move(model), [&] { return read_scene_file(path, options); });
    } catch (const std::runtime_error& problem) {
        const std::string what = problem.what();
        if (what.starts_with(name + ":")) throw;
        throw std::runtime_error(name + ": " + what);  // InputFile's reasons do not name the file
    }
}

Model parse_ply(std::span<const std::uint8_t> bytes, const ObjOptions& options) {
    std::size_t at = 0;
    detail::PlyBytes source(
        [&](std::span<std::uint8_t> into) {
            const std::size_t n = std::min(into.size(), bytes.size() - at);
            if (n > 0) std::memcpy(into.data(), bytes.data() + at, n);
            at += n;
            return n;
        },
        bytes.size());
    return ply_model(source, "<memory>", options, Model{}, [&] { return parse_scene_file(bytes, "ply", options); });
}

}  // namespace raster
