#pragma once

// The OpenGL side of raster-vs-gl: an OSMesa context (llvmpipe on Debian 12) drawing into memory,
// with an optional multisample framebuffer, and GL's matrices for raster's two cameras.
#include <raster/camera/ortho_camera.hpp>
#include <raster/camera/perspective_camera.hpp>
#include <raster/image/framebuffer.hpp>

#define GL_GLEXT_PROTOTYPES 1  // OSMesa exports the GL entry points the GLSL and multisample paths call
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <cstdint>
#include <vector>
#include <glm/mat4x4.hpp>

namespace bench {

class GlContext {
public:
    // With samples > 1, frames are drawn into a multisample framebuffer and resolved by finish().
    GlContext(int width, int height, int samples = 1);
    ~GlContext();
    GlContext(const GlContext&) = delete;
    GlContext& operator=(const GlContext&) = delete;

    // Binds the framebuffer a frame is drawn into.
    void begin() const;
    // Resolves the samples, if any, and waits until the pixels are in memory.
    void finish() const;
    [[nodiscard]] raster::Framebuffer image() const;
    [[nodiscard]] raster::Rgb pixel(int x, int y) const {
        const std::size_t i =
            (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)) * 4;
        return {pixels_[i], pixels_[i + 1], pixels_[i + 2]};
    }

private:
    int width_;
    int height_;
    std::vector<std::uint8_t> pixels_;
    OSMesaContext context_ = nullptr;
    GLuint framebuffer_ = 0;  // the multisample one, or 0
    GLuint colour_ = 0;
    GLuint depth_ = 0;
};

// GL's clip-from-world matrix for raster's camera: the same pixels, raster's depth range mapped
// to GL's -1..1 (doc/conventions.md#perspective); an orthographic view's depths +-100 likewise.
[[nodiscard]] glm::dmat4 gl_clip_from_world(const raster::PerspectiveCamera& camera);
[[nodiscard]] glm::dmat4 gl_clip_from_world(const raster::OrthoCamera& camera);

}  // namespace bench
