#include <raster/io/model_file.hpp>

#include "io/model_format.hpp"
#include "io/model_formats.hpp"
#include "io/model_reading.hpp"
#include "io/ply/ply_reading.hpp"
#include "io/reader_process.hpp"
#include "io/stl/stl_binary.hpp"

#include <raster/io/input_file.hpp>
#include <raster/io/ply_file.hpp>
#include <raster/io/reader_service.hpp>
#include <raster/io/stl_file.hpp>
#include <raster/platform/stopwatch.hpp>

#include <new>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace raster {
namespace detail {

std::string reader_name(const std::filesystem::path& path) { return format_name(model_format_of(path), path); }

namespace {

// The first bytes and the size; throws std::runtime_error with one line when they do not fit the format.
std::pair<std::vector<std::uint8_t>, std::uintmax_t> check_content(const std::filesystem::path& path,
                                                                   const ObjOptions& options, ModelFormat format) {
    const std::string name = printable(path.string());
    // The first bytes decide whether the named reader may run at all (doc/conventions.md#reader-process).
    InputRules rules;
    rules.role = "model";
    rules.max_bytes = kMaxModelFileBytes;
    rules.confine = options.confine;
    std::vector<std::uint8_t> head;
    std::uintmax_t size = 0;
    try {
        InputFile file(path, rules);
        size = file.size();
        head = file.read_head(kSignatureBytes);
    } catch (const std::runtime_error& problem) {
        throw std::runtime_error(name + ": " + problem.what());
    }
    if (const std::string problem = content_problem(format, head, size, path); !problem.empty())
        throw std::runtime_error(name + ": " + problem);
    return {std::move(head), size};
}

// The least an STL's mesh takes: 96 bytes a triangle (three corners' positions and normals, a
// facet), a binary one's count from its size, an ASCII one's at most one a 86 bytes of text (the
// shortest facet: "facet normal 0 0 0 outer loop vertex 0 0 0 ... endloop endfacet").
std::uint64_t least_stl_memory(std::span<const std::uint8_t> head, std::uintmax_t size) {
    const std::uint64_t triangles = is_binary_stl(head, size) ? (size - kStlHeaderBytes) / kStlRecordBytes : size / 86;
    return triangles * 96;
}

}  // namespace

Model read_model_here(const std::filesystem::path& path, const ObjOptions& options) {
    const ModelFormat format = model_format_of(path);
    (void)check_content(path, options, format);
    if (format == ModelFormat::obj) return read_obj(path, options);
    if (format == ModelFormat::ply)
        return read_ply(path, options);  // raster's own reader (doc/conventions.md#ply-reader)
    if (format == ModelFormat::stl) return read_stl(path, options);  // and STL's (doc/conventions.md#stl-reader)
    return read_scene_file(path, options);
}

}  // namespace detail

std::string model_endings() { return std::string(detail::kModelEndings); }

bool has_model_ending(const std::filesystem::path& path) {
    const std::string ending = detail::ending_of(path);
    return ending == ".obj" || ending == ".gltf" || ending == ".glb" || ending == ".stl" || ending == ".ply" ||
           detail::other_format(ending) != nullptr;
}

Model read_model(const std::filesystem::path& path, const ObjOptions& options, Spent* spent) {
    const std::string reader = detail::reader_name(path);  // an unknown ending is refused here, before any fork
    const bool apart = options.limits.separate_process;
    // This thread's own time: the reading itself, or the copy back from a child (a batch reads while it draws).
    Stopwatch clock(Counted::thread);
    double child = 0.0;
    const auto in_child = [&] {
        if (apart && options.limits.service != nullptr) return options.limits.service->read(path, options, &child);
        return detail::read_in_child([&] { return detail::read_model_here(path, options); }, printable(path.string()),
                                     reader, options.limits, &child);
    };
    const auto read = [&] {
        const detail::ModelFormat format = detail::model_format_of(path);
        if (!apart || (format != detail::ModelFormat::ply && format != detail::ModelFormat::stl)) return in_child();
        // raster's own readers run here, with no copy back (doc/conventions.md#reader-process)
        const auto [head, size] = detail::check_content(path, options, format);
        if (format == detail::ModelFormat::ply) return detail::read_ply_here(path, options, in_child);
        if (detail::least_stl_memory(head, size) > detail::memory_in_force(options.limits))
            throw std::runtime_error(detail::memory_refusal(printable(path.string()), reader, options.limits));
        return read_stl(path, options);
    };
    Model model;
    try {
        model = read();
    } catch (const std::bad_alloc&) {  // read here, beyond what its counts promised
        throw std::runtime_error(detail::memory_refusal(printable(path.string()), reader, options.limits));
    }
    if (spent != nullptr) {
        *spent = clock.lap();
        spent->processor += child;
    }
    return model;
}

}  // namespace raster
