#pragma once

#include <raster/image/framebuffer.hpp>
#include <raster/image/subpixel.hpp>

#include <cstdint>
#include <span>
#include <type_traits>
#include <glm/vec2.hpp>

namespace raster {

// A run of covered pixels on row y: x_begin included, x_end excluded.
struct Span {
    int y;
    int x_begin;
    int x_end;
};

// A non-owning reference to a callable taking a Span, cheaper than std::function; valid only
// while the callable lives, which for a visitor is the call it is passed to.
class SpanVisitor {
public:
    template <typename Callable>
    requires(!std::is_same_v<std::remove_cvref_t<Callable>, SpanVisitor>) SpanVisitor(Callable&& callable)
    noexcept  // NOLINT: implicit on purpose, like std::function
        : object_(const_cast<void*>(static_cast<const void*>(&callable))),
          call_([](void* object, Span span) { (*static_cast<std::remove_reference_t<Callable>*>(object))(span); }) {}
    void operator()(Span span) const { call_(object_, span); }

private:
    void* object_;
    void (*call_)(void*, Span);
};

// A rectangle of pixels: the part of the plane a target can receive.
struct PixelRect {
    int x;
    int y;
    int width;
    int height;
};

// Twice the signed area of a polygon in subpixel units squared (shoelace formula). Positive
// means the corners run clockwise on screen, which is how front faces arrive
// (doc/conventions.md#facing).
[[nodiscard]] std::int64_t twice_signed_area(std::span<const SubpixelPoint> corners) noexcept;

// Visits, row by row, the pixels of `clip` whose centres a convex polygon covers: inside every
// edge, or on an edge that is a top or left edge (doc/conventions.md#fill). Either winding works;
// zero area covers nothing, nor do polygons with more than 8 corners or corners beyond
// kMaxSubpixelCoordinate. Each row's span comes from exact 64-bit edge functions solved for x,
// so the work is one step per row of the clipped bounding box. Returns the rows examined.
std::int64_t rasterize_convex(std::span<const SubpixelPoint> corners, PixelRect clip, SpanVisitor visit);

// Paints the covered pixels; the framebuffer's top-left pixel sits at `origin`.
std::int64_t fill_convex(Framebuffer& framebuffer, std::span<const SubpixelPoint> corners, Rgb colour,
                         glm::ivec2 origin = {0, 0});

}  // namespace raster
