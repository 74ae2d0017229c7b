#pragma once

#include <string>

// Animations written as one PNG file per frame, for video tools. Body in frame_files.cpp.
namespace raster {

// Frame `index`'s file name: its number in at least four digits, "0000.png", "0001.png", ...,
// the names ffmpeg's -i DIR/%04d.png reads. Given the clip's `frame_count`, the number takes as
// many digits as the last frame's needs, so that the names of a longer clip still sort.
[[nodiscard]] std::string frame_file_name(int index, int frame_count = 0);

}  // namespace raster
