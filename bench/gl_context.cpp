#include "gl_context.hpp"

#include <stdexcept>

namespace bench {
namespace {

// raster's view as an affine map, read off the camera by probing it.
template <typename Camera>
glm::dmat4 view_of(const Camera& camera) {
    const glm::dvec3 o = camera.view_from_world(glm::vec3(0.0F));
    const glm::dvec3 x = camera.view_from_world(glm::vec3(1, 0, 0)) - o,
                     y = camera.view_from_world(glm::vec3(0, 1, 0)) - o,
                     z = camera.view_from_world(glm::vec3(0, 0, 1)) - o;
    return {glm::dvec4(x, 0), glm::dvec4(y, 0), glm::dvec4(z, 0), glm::dvec4(o, 1)};
}

}  // namespace

GlContext::GlContext(int width, int height, int samples)
    : width_(width), height_(height), pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4) {
    const int attributes[] = {
        OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 24, OSMESA_PROFILE, OSMESA_COMPAT_PROFILE, 0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (context_ == nullptr || !OSMesaMakeCurrent(context_, pixels_.data(), GL_UNSIGNED_BYTE, width, height)) {
        throw std::runtime_error("cannot create an OSMesa context");
    }
    OSMesaPixelStore(OSMESA_Y_UP, 0);  // row 0 at the top, as raster stores it
    if (samples > 1) {
        glGenFramebuffers(1, &framebuffer_);
        glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
        glGenRenderbuffers(1, &colour_);
        glBindRenderbuffer(GL_RENDERBUFFER, colour_);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_RGBA8, width, height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
        glGenRenderbuffers(1, &depth_);
        glBindRenderbuffer(GL_RENDERBUFFER, depth_);
        glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, width, height);
        glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
        GLint granted = 0;
        glGetIntegerv(GL_SAMPLES, &granted);
        if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE || granted != samples) {
            throw std::runtime_error("this OpenGL cannot draw " + std::to_string(samples) + " samples per pixel");
        }
    }
    glViewport(0, 0, width, height);
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CW);  // raster's front faces run clockwise on screen (doc/conventions.md#facing)
    glDisable(GL_DITHER);
}

GlContext::~GlContext() {
    if (framebuffer_ != 0) {
        glDeleteFramebuffers(1, &framebuffer_);
        glDeleteRenderbuffers(1, &colour_);
        glDeleteRenderbuffers(1, &depth_);
    }
    OSMesaDestroyContext(context_);
}

void GlContext::begin() const { glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_); }

void GlContext::finish() const {
    if (framebuffer_ != 0) {
        // The resolve: GL averages the samples as stored, here sRGB-encoded bytes.
        glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
        glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
    glFinish();  // the pixels are in memory when this returns: OSMesa renders into our buffer
}

raster::Framebuffer GlContext::image() const {
    raster::Framebuffer out(width_, height_);
    for (int y = 0; y < height_; ++y) {
        for (int x = 0; x < width_; ++x) out.set_pixel(x, y, pixel(x, y));
    }
    return out;
}

glm::dmat4 gl_clip_from_world(const raster::PerspectiveCamera& camera) {
    const glm::dvec4 probe = camera.clip_from_view({1.0, 1.0, 1.0});
    const double n = camera.lens().near, f = camera.lens().far;
    glm::dmat4 projection(0.0);
    projection[0][0] = probe.x;  // x_scale
    projection[1][1] = probe.y;  // y_scale
    projection[2][2] = (f + n) / (f - n);
    projection[3][2] = -2.0 * f * n / (f - n);
    projection[2][3] = 1.0;  // w = view depth
    return projection * view_of(camera);
}

glm::dmat4 gl_clip_from_world(const raster::OrthoCamera& camera) {
    // raster's pixel centres sit on whole numbers, GL's on halves; its rows run down, GL's NDC up.
    const glm::dvec2 centre = camera.screen_from_view({0.0, 0.0, 0.0});
    const double scale = camera.screen_from_view({1.0, 0.0, 0.0}).x - centre.x;
    const double width = 2.0 * centre.x + 1.0, height = 2.0 * centre.y + 1.0;
    glm::dmat4 projection(0.0);
    projection[0][0] = 2.0 * scale / width;
    projection[3][0] = 2.0 * (centre.x + 0.5) / width - 1.0;
    projection[1][1] = 2.0 * scale / height;
    projection[3][1] = 1.0 - 2.0 * (centre.y + 0.5) / height;
    projection[2][2] = 1.0 / 100.0;
    projection[3][3] = 1.0;
    return projection * view_of(camera);
}

}  // namespace bench
