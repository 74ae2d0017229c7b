#pragma once

#include "export_options.hpp"

#include <raster/image/framebuffer.hpp>

#include <cstdint>
#include <span>
#include <string>
#include <CLI/CLI.hpp>

// Where a finished picture goes: a file, replaced atomically, or standard output.

// Fails early (a bad path, an input of this run, stdout on a terminal) and warns once about a
// name not ending in the format's extension.
void check_output(const CLI::App& app, const ExportOptions& options);
// With --preview, shows the picture on the terminal through the Kitty graphics protocol, or says
// in one line on stderr why it cannot (not with --quiet); the file is written either way.
void preview(const CLI::App& app, const ExportOptions& options, const raster::Framebuffer& image,
             std::span<const std::uint8_t> alpha = {});
// Writes the finished bytes to the output file (atomically) or to standard output.
void deliver(const ExportOptions& options, std::span<const std::uint8_t> bytes);
// "Wrote out.webp" or "Wrote standard output": how a report line begins.
[[nodiscard]] std::string describe_destination(const ExportOptions& options);
