#include <raster/io/model_file.hpp>

#include "io/model_format.hpp"
#include "io/model_formats.hpp"
#include "io/model_reading.hpp"
#include "io/reader_process.hpp"

#include <raster/io/input_file.hpp>
#include <raster/io/ply_file.hpp>
#include <raster/io/reader_service.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace raster {
namespace detail {

std::string reader_name(const std::filesystem::path& path) { return format_name(model_format_of(path), path); }

Model read_model_here(const std::filesystem::path& path, const ObjOptions& options) {
    const ModelFormat format = model_format_of(path);
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
    if (format == ModelFormat::obj) return read_obj(path, options);
    if (format == ModelFormat::ply)
        return read_ply(path, options);  // raster's own reader (doc/conventions.md#ply-reader)
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
    // In a child, this thread's own time is the copy back (a batch reads while it draws on others).
    Stopwatch clock(apart ? Counted::thread : Counted::process);
    double child = 0.0;
    Model model = apart && options.limits.service != nullptr
                      ? options.limits.service->read(path, options, &child)
                      : detail::read_in_child([&] { return detail::read_model_here(path, options); },
                                              printable(path.string()), reader, options.limits, &child);
    if (spent != nullptr) {
        *spent = clock.lap();
        spent->processor += child;
    }
    return model;
}

}  // namespace raster
