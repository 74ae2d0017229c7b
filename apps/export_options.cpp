#include "export_options.hpp"

#include <raster/platform/cores.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>

ImageFormat ExportOptions::image_format() const {
    if (format) return *format;
    return lowered_extension(output) == ".png" ? ImageFormat::png : ImageFormat::webp;
}

int ExportOptions::threads_in_use() const {
    const int cores = raster::available_cores();
    return threads == 0 ? cores : std::min(threads, cores);
}

std::string file_extension(ImageFormat format) { return format == ImageFormat::png ? ".png" : ".webp"; }

std::string lowered_extension(const std::string& name) {
    std::string extension = std::filesystem::path(name).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}
