#pragma once

#include "export_options.hpp"

#include <filesystem>

// --skip-existing: which outputs count as finished.

// A regular file (not a link) that is not empty.
[[nodiscard]] bool is_nonempty_regular_file(const std::filesystem::path& path);
// --skip-existing: whether `path` is a finished picture of `format`, a regular file (not a link)
// that is not empty and decodes whole; anything else under that name is drawn again.
[[nodiscard]] bool holds_finished_picture(const std::filesystem::path& path, ImageFormat format);
