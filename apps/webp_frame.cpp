#include "command_line.hpp"
#include "delivery.hpp"
#include "help_format.hpp"
#include "option_checks.hpp"
#include "shared_options.hpp"

#include <raster/io/png.hpp>

#include <algorithm>

#include <span>
#include <stdexcept>

int main(int argc, char** argv) {
    CLI::App app("Writes one frame of an animated WebP as a full lossless still, composited as a "
                 "player shows it (webpmux -get frame returns only the changed rectangle).",
                 "webp-frame");
    app.footer("Examples:\n"
               "  webp-frame spin.webp 0 first.webp       # the first frame\n"
               "  webp-frame spin.webp 90 - | dwebp -o frame.png -- -");
    configure_app(app);
    std::string input;
    app.add_option("input", input, "The animated (or still) WebP file to read")->required()->option_text("FILE");
    int index = 0;
    add_integer_option(app, "frame", index, 0, 1 << 30, "Which frame, counting from 0")->required()->option_text("N");
    ExportOptions options{"frame.webp"};
    add_output_options(app, options);

    return run_exporter(app, options, argc, argv, [&] {
        // The input's identity before it is read, so that naming it as the output fails at once.
        if (raster::FileIdentity identity; raster::identity_of(input, identity))
            options.inputs.push_back({input, identity, "animation"});
        check_output(app, options);
        // The frame is encoded from the reader's canvas, not a copy: memory is one canvas and one frame.
        raster::WebpFrameReader reader(input, &options.inputs);
        const raster::WebpInfo& info = reader.info();
        const raster::DecodedFrame* found = nullptr;
        for (int seen = 0; seen <= index; ++seen) {
            if ((found = reader.next()) == nullptr) break;
        }
        if (found == nullptr) {
            throw std::runtime_error("'" + input + "' has " + std::to_string(info.frame_count) +
                                     " frame(s), numbered 0.." + std::to_string(info.frame_count - 1));
        }
        // An opaque frame stays opaque; a transparent one keeps its alpha.
        const bool opaque =
            std::all_of(found->alpha.begin(), found->alpha.end(), [](std::uint8_t a) { return a == 255; });
        const std::span<const std::uint8_t> alpha =
            opaque ? std::span<const std::uint8_t>() : std::span<const std::uint8_t>(found->alpha);
        preview(app, options, found->image, alpha);
        const std::vector<std::uint8_t> bytes = options.image_format() == ImageFormat::png
                                                    ? raster::encode_png(found->image, alpha)
                                                    : raster::encode_webp_still(found->image, options.effort, alpha);
        deliver(options, bytes);
        return describe_destination(options) + ": frame " + std::to_string(index) + " of " + raster::printable(input) +
               ", " + std::to_string(info.width) + "x" + std::to_string(info.height) + ", " +
               std::to_string(bytes.size()) + " bytes";
    });
}
