#include "delivery.hpp"

#include "terminal_preview.hpp"

#include <raster/io/input_file.hpp>
#include <raster/io/output_file.hpp>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <unistd.h>

void check_output(const CLI::App& app, const ExportOptions& options) {
    if (options.output == "-" && options.preview) {
        throw CLI::ValidationError(
            "--preview shows the picture on standard output, which - takes for the file; name a file to write");
    }
    if (options.output == "-") {
        if (::isatty(1) == 1) {
            throw std::runtime_error("standard output is a terminal; redirect it to a file or a pipe");
        }
        return;
    }
    raster::check_output_path(options.output, options.policy, options.inputs);
    const bool png = options.image_format() == ImageFormat::png;
    if (lowered_extension(options.output) != file_extension(options.image_format()) && !options.quiet) {
        std::cerr << app.get_name() << ": warning: '" << raster::printable(options.output) << "' does not end in "
                  << (png ? ".png, but it will hold PNG data\n" : ".webp, but it will hold WebP data\n");
    }
}

void preview(const CLI::App& app, const ExportOptions& options, const raster::Framebuffer& image,
             std::span<const std::uint8_t> alpha) {
    if (!options.preview) return;
    const std::string why_not = show_on_terminal(image, alpha);
    if (!why_not.empty() && !options.quiet)
        std::cerr << app.get_name() << ": no preview: " << why_not << '\n' << std::flush;
}

void deliver(const ExportOptions& options, std::span<const std::uint8_t> bytes) {
    if (options.held != nullptr) {
        options.held->push_back({options, {bytes.begin(), bytes.end()}});
        options.held->back().options.held = nullptr;
        return;
    }
    if (options.output != "-") {
        raster::write_output_file(options.output, bytes, options.policy, options.inputs);
        return;
    }
    while (!bytes.empty()) {
        const ::ssize_t written = ::write(1, bytes.data(), bytes.size());
        if (written < 0 && errno == EINTR) continue;
        if (written <= 0) {
            throw std::runtime_error(std::string("cannot write to standard output: ") +
                                     std::strerror(written < 0 ? errno : EIO));
        }
        bytes = bytes.subspan(static_cast<std::size_t>(written));
    }
}

std::string describe_destination(const ExportOptions& options) {
    return options.output == "-" ? "Wrote standard output" : "Wrote " + raster::printable(options.output);
}
