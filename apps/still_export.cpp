#include "still_export.hpp"

#include "delivery.hpp"
#include "progress.hpp"

#include <raster/io/png.hpp>
#include <raster/io/webp.hpp>

#include <memory>
#include <utility>

std::function<FinishedPicture()> render_still(const CLI::App& app, const ExportOptions& options,
                                              const RenderStill& render) {
    check_output(app, options);
    auto progress = std::make_shared<Progress>(app.get_name(), options);
    progress->stage("rendering");
    auto frame = std::make_shared<raster::Framebuffer>(options.width, options.height);
    auto alpha = std::make_shared<std::vector<std::uint8_t>>();
    render(*frame, *alpha);
    progress->pause();
    preview(app, options, *frame, *alpha);
    return [options, progress, frame, alpha] {
        progress->stage("encoding");
        const std::vector<std::uint8_t> bytes = options.image_format() == ImageFormat::png
                                                    ? raster::encode_png(*frame, *alpha)
                                                    : raster::encode_webp_still(*frame, options.effort, *alpha);
        std::string report = describe_destination(options) + ": " + std::to_string(options.width) + "x" +
                             std::to_string(options.height) +
                             (alpha->empty() ? " still, " : " still on a transparent background, ") +
                             std::to_string(bytes.size()) + " bytes";
        return FinishedPicture{bytes, std::move(report)};
    };
}

std::string export_still(const CLI::App& app, const ExportOptions& options, const RenderStill& render) {
    const FinishedPicture done = render_still(app, options, render)();
    deliver(options, done.bytes);
    return done.report;
}

std::string export_still(const CLI::App& app, const ExportOptions& options,
                         const std::function<void(raster::Framebuffer&)>& render) {
    return export_still(app, options, [&](raster::Framebuffer& frame, std::vector<std::uint8_t>&) { render(frame); });
}
