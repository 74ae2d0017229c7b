#include "io/model_blocks.hpp"

#include <raster/io/input_file.hpp>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <utility>

namespace raster::detail {

Model read_model_blocks(const std::filesystem::path& path, const ObjOptions& options, const BlockReader& read) {
    const std::string name = printable(path.string());
    InputRules rules;
    rules.role = "model";
    rules.max_bytes = kMaxModelFileBytes;
    rules.confine = options.confine;
    try {
        InputFile file(path, rules);
        Model model;
        model.sources.push_back(file.record());
        PlyBytes bytes([&file](std::span<std::uint8_t> into) { return file.read_some(into); }, file.size());
        return read(bytes, file.size(), name, std::move(model));
    } catch (const std::runtime_error& problem) {
        const std::string what = problem.what();
        if (what.starts_with(name + ":")) throw;
        throw std::runtime_error(name + ": " + what);  // InputFile's reasons do not name the file
    }
}

PlyBytes blocks_in_memory(std::span<const std::uint8_t> bytes) {
    return PlyBytes(
        [bytes, at = std::size_t{0}](std::span<std::uint8_t> into) mutable {
            const std::size_t n = std::min(into.size(), bytes.size() - at);
            if (n > 0) std::memcpy(into.data(), bytes.data() + at, n);
            at += n;
            return n;
        },
        bytes.size());
}

}  // namespace raster::detail
