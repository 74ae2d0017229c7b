#include <raster/io/model_file.hpp>

#include "io/model_format.hpp"
#include "io/reader_process.hpp"

#include <raster/io/input_file.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace raster {

Model read_model(const std::filesystem::path& path, const ObjOptions& options) {
    const detail::ModelFormat format = detail::model_format_of(path);
    const std::string name = printable(path.string());
    const auto read = [&] {
        // The first bytes decide whether the named reader may run at all (doc/conventions.md#models).
        InputRules rules;
        rules.role = "model";
        rules.max_bytes = kMaxModelFileBytes;
        rules.confine = options.confine;
        std::vector<std::uint8_t> head(detail::kSignatureBytes);
        std::uintmax_t size = 0;
        try {
            InputFile file(path, rules);
            size = file.size();
            std::size_t got = 0;
            while (got < head.size()) {
                const std::size_t more = file.read_some(std::span(head).subspan(got));
                if (more == 0) break;
                got += more;
            }
            head.resize(got);
        } catch (const std::runtime_error& problem) {
            throw std::runtime_error(name + ": " + problem.what());
        }
        if (const std::string problem = detail::content_problem(format, head, size); !problem.empty()) {
            throw std::runtime_error(name + ": " + problem);
        }
        return format == detail::ModelFormat::obj ? read_obj(path, options) : read_scene_file(path, options);
    };
    return detail::read_in_child(read, name, detail::format_name(format), options.limits);
}

}  // namespace raster
