#pragma once

#include <raster/image/framebuffer.hpp>

#include <glm/mat4x4.hpp>

// The scenes of the diary, shared by the exporters and the tests so they cannot disagree.
namespace raster {

inline constexpr int kSceneWidth = 800;
inline constexpr int kSceneHeight = 600;
inline constexpr int kAnimationFrameCount = 360;
inline constexpr int kFrameSpacingMs = 20;  // 50 frames per second

enum class CubeStyle { filled, wireframe, culled_wireframe, lit };

// The still pose: pi/4 about Y, then pi/4 about X, at half size.
[[nodiscard]] glm::mat4 still_cube_pose();
// Rz(t) Ry(t) Rx(t): the tumble's rotation by angle t.
[[nodiscard]] glm::mat4 tumble_rotation(float t);
// The tumble's angle at a frame, 2 pi frame / frame_count, computed in float.
[[nodiscard]] float tumble_angle(int frame, int frame_count);
// The tumble: M(t) = Rz(t) Ry(t) Rx(t) S(0.5) with t = 2 pi frame / frame_count.
[[nodiscard]] glm::mat4 tumble_pose(int frame, int frame_count);

// 0.0.1: one white pixel at the centre of a black frame.
void render_white_pixel(Framebuffer& framebuffer);
// 0.0.2: white spokes from the centre every 5 degrees, the lines' visual check.
void render_spokes(Framebuffer& framebuffer);
// The cube at `pose` on black: palette faces when filled, the 0.0.8 light when lit, otherwise
// lines in `line_colour`.
void render_cube(Framebuffer& framebuffer, const glm::mat4& pose, CubeStyle style, Rgb line_colour);
// 0.0.3 / 0.0.5 / 0.0.6: the still pose, white lines for the wireframe styles.
void render_still_cube(Framebuffer& framebuffer, CubeStyle style);
// 0.0.7: the unit cube at the identity pose: only the blue near face shows.
void render_unit_cube(Framebuffer& framebuffer);
// 0.0.4 to 0.0.7: one tumble frame, cornflower-blue lines for the wireframe styles.
void render_tumble_frame(Framebuffer& framebuffer, int frame, int frame_count, CubeStyle style);

}  // namespace raster
