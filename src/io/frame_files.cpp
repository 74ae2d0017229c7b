#include <raster/io/frame_files.hpp>

#include <algorithm>

namespace raster {

std::string frame_file_name(int index, int frame_count) {
    const std::size_t digits = std::max<std::size_t>(4, std::to_string(std::max(frame_count - 1, 0)).size());
    std::string number = std::to_string(index);
    if (number.size() < digits) number.insert(0, digits - number.size(), '0');
    return number + ".png";
}

}  // namespace raster
