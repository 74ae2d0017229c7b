#pragma once

#include <raster/image/framebuffer.hpp>

#include <chrono>
#include <cstdint>
#include <span>
#include <string>

// How long the terminal has to answer the graphics query before it counts as unable.
inline constexpr std::chrono::milliseconds kPreviewAnswerTimeout{1000};

// Shows the picture (with `alpha`, one byte per pixel, when given) inline on the terminal that
// is standard output, through the Kitty graphics protocol, scaled to its window, after asking
// the terminal whether it can. Returns "" when shown, else why not, in a few words.
std::string show_on_terminal(const raster::Framebuffer& image, std::span<const std::uint8_t> alpha,
                             std::chrono::milliseconds timeout = kPreviewAnswerTimeout);
