#include "io/webp/lossless_picture.hpp"

#include <memory>
#include <stdexcept>
#include <string>

namespace raster::detail {

std::vector<std::uint8_t> encode_lossless(const std::uint8_t* rgb, int width, int height, int stride,
                                          const WebPConfig& config, int channels) {
    WebPPicture picture;
    if (!WebPPictureInit(&picture)) throw std::runtime_error("libwebp version mismatch");
    picture.use_argb = 1;
    picture.width = width;
    picture.height = height;
    const std::unique_ptr<WebPPicture, void (*)(WebPPicture*)> owned(&picture, WebPPictureFree);
    const int imported =
        channels == 4 ? WebPPictureImportRGBA(&picture, rgb, stride) : WebPPictureImportRGB(&picture, rgb, stride);
    if (!imported) throw std::runtime_error("out of memory importing a frame");
    WebPMemoryWriter memory;
    WebPMemoryWriterInit(&memory);
    picture.writer = WebPMemoryWrite;
    picture.custom_ptr = &memory;
    const bool encoded = WebPEncode(&config, &picture) != 0;
    std::vector<std::uint8_t> bytes(memory.mem, memory.mem + memory.size);
    WebPMemoryWriterClear(&memory);
    if (!encoded)
        throw std::runtime_error("cannot encode a frame: libwebp error " + std::to_string(picture.error_code));
    return bytes;
}

}  // namespace raster::detail
