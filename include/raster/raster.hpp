#pragma once

// One include for all of raster, stage by stage (doc/architecture.md); scenes/ is raster::scenes,
// linked on its own. umbrella_header_test.sh keeps it whole.

#include <raster/version.hpp>

#include <raster/platform/cores.hpp>
#include <raster/platform/stopwatch.hpp>

#include <raster/image/colour.hpp>
#include <raster/image/framebuffer.hpp>
#include <raster/image/lanes.hpp>
#include <raster/image/subpixel.hpp>

#include <raster/geometry/analytic_shape.hpp>
#include <raster/geometry/cube.hpp>
#include <raster/geometry/mesh.hpp>
#include <raster/geometry/primitives.hpp>
#include <raster/geometry/shapes.hpp>
#include <raster/geometry/tangents.hpp>

#include <raster/camera/ortho_camera.hpp>
#include <raster/camera/perspective_camera.hpp>

#include <raster/rasterize/depth_buffer.hpp>
#include <raster/rasterize/draw_cube.hpp>
#include <raster/rasterize/draw_mesh.hpp>
#include <raster/rasterize/fill.hpp>
#include <raster/rasterize/line.hpp>
#include <raster/rasterize/shader.hpp>

#include <raster/shade/gltf_brdf.hpp>
#include <raster/shade/intensity_lighting.hpp>
#include <raster/shade/linear_lighting.hpp>
#include <raster/shade/mapped_phong_shader.hpp>
#include <raster/shade/metallic_roughness.hpp>
#include <raster/shade/metallic_roughness_lighting.hpp>
#include <raster/shade/metallic_roughness_shaders.hpp>
#include <raster/shade/normal_map.hpp>
#include <raster/shade/opacity.hpp>
#include <raster/shade/phong_maps.hpp>
#include <raster/shade/shaders.hpp>
#include <raster/shade/split_sum_table.hpp>
#include <raster/shade/surroundings.hpp>
#include <raster/shade/texture.hpp>
#include <raster/shade/texture_transform.hpp>
#include <raster/shade/textured_shaders.hpp>

#include <raster/io/frame_files.hpp>
#include <raster/io/frame_range.hpp>
#include <raster/io/frame_timing.hpp>
#include <raster/io/held_signals.hpp>
#include <raster/io/input_file.hpp>
#include <raster/io/kitty_graphics.hpp>
#include <raster/io/model.hpp>
#include <raster/io/model_camera.hpp>
#include <raster/io/model_file.hpp>
#include <raster/io/obj_file.hpp>
#include <raster/io/output_file.hpp>
#include <raster/io/ply_file.hpp>
#include <raster/io/png.hpp>
#include <raster/io/reader_limits.hpp>
#include <raster/io/reader_service.hpp>
#include <raster/io/stl_file.hpp>
#include <raster/io/texture_file.hpp>
#include <raster/io/webp.hpp>
#include <raster/io/webp_parts.hpp>

#include <raster/render/auto_detail.hpp>
#include <raster/render/model_scene.hpp>
#include <raster/render/render_style.hpp>
#include <raster/render/samples.hpp>
#include <raster/render/scene.hpp>
#include <raster/render/stage_times.hpp>

#include <raster/scenes/diary_scenes.hpp>
#include <raster/scenes/island_world.hpp>
#include <raster/scenes/palette.hpp>
#include <raster/scenes/scenes.hpp>
#include <raster/scenes/seed_scenes.hpp>
