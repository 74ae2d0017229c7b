#include "command_line.hpp"
#include "delivery.hpp"
#include "export_options.hpp"
#include "help_format.hpp"

#include <raster/io/input_file.hpp>
#include <raster/io/webp_parts.hpp>

#include <stdexcept>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    CLI::App app(
        "Joins the parts of an animation rendered with --frame-range (on several machines, or one range at a time) "
        "into the whole clip, copying every frame as it is: no pixel is encoded again. The parts may come in any "
        "order; they must cover every frame once, at one size and one frame rate.",
        "webp-assemble");
    app.footer("Examples:\n"
               "  animated-scene --frame-range 0..179 a.webp\n"
               "  animated-scene --frame-range 180..359 b.webp\n"
               "  webp-assemble scene.webp a.webp b.webp    # the same frames as animated-scene scene.webp\n"
               "  webp-assemble scene.webp part-*.webp\n"
               "  webp-assemble - part-*.webp | webpinfo -quiet -- -");
    configure_app(app);
    ExportOptions options{""};
    app.add_option(
           "output", options.output,
           "The whole animation to write, replaced whole or not at all; never one of the parts; - writes to standard output")
        ->required()
        ->option_text("OUT.webp");
    std::vector<std::string> names;
    app.add_option("parts", names, "The parts, each made with --frame-range")->required()->option_text("PART...");
    app.add_flag("-q,--quiet", options.quiet, "Print nothing when all goes well");

    return run_exporter(app, options, argc, argv, [&] {
        std::vector<raster::AnimationPart> parts;
        const raster::InputRules rules{"part", raster::kMaxWebpFileBytes, raster::looks_like_webp, 12, "a WebP file",
                                       {}};
        for (const std::string& name : names) {
            try {
                parts.push_back({name, raster::read_input_file(name, rules, &options.inputs)});
            } catch (const std::runtime_error& problem) {
                throw std::runtime_error("'" + raster::printable(name) + "' " + problem.what());
            }
        }
        options.format = ImageFormat::webp;
        check_output(app, options);
        const std::vector<std::uint8_t> bytes = raster::assemble_parts(std::move(parts));
        deliver(options, bytes);
        return describe_destination(options) + ": " + std::to_string(raster::webp_frame_count(bytes)) +
               " frames from " + std::to_string(names.size()) + (names.size() == 1 ? " part, " : " parts, ") +
               std::to_string(bytes.size()) + " bytes";
    });
}
