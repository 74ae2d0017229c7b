#pragma once

#include <raster/render/auto_detail.hpp>
#include <raster/render/render_style.hpp>
#include <raster/scenes/diary_scenes.hpp>
#include <raster/scenes/seed_scenes.hpp>

#include <string>
#include <CLI/CLI.hpp>

// --scene NAME, any of the diary's scenes (the original's final one by default) or the other
// seeds'; the help lists them all.
void add_scene_option(CLI::App& app, std::string& scene);
// The scene list for a footer: one line each, "  torus           0.0.17  a Phong-shaded torus ...".
std::string scene_list();

// --detail diary|auto: the release's own meshes and shading, or the cheapest that the image's
// pixels cannot tell from the true surface.
void add_detail_option(CLI::App& app, bool& automatic);
// Plans automatic detail from every 30th frame of a clip (or the one still).
raster::DetailPlan plan_for(const raster::DiaryScene& scene, int width, int height, int frames);
// ", detail torus level 6 (Phong)" for the report line; empty when nothing was chosen.
std::string describe(const raster::DetailPlan& plan);

// The seeds' scenes have their own meshes and cameras: --detail auto and --perspective are
// errors with them (std::invalid_argument).
void check_seed_options(const std::string& scene, bool automatic, int fov_degrees);

// --perspective DEGREES: 0 keeps the diary's orthographic camera; 1..179 looks through a pinhole
// of that vertical field of view, the eye moved back so the scene keeps its framing.
void add_perspective_option(CLI::App& app, int& fov_degrees);
// --style textured|flat|wireframe: raster-engine's render modes, on every scene.
void add_render_style_option(CLI::App& app, raster::RenderStyle& style);
// Renders the scene through the camera the option chose, in the style chosen.
void render_scene(raster::Framebuffer& frame, const raster::Scene& scene, int fov_degrees, raster::RenderStyle style,
                  raster::Renderer& renderer);
void render_scene(raster::Framebuffer& frame, const raster::PerspectiveScene& scene, raster::RenderStyle style,
                  raster::Renderer& renderer);

// --view NAME: a still framed on one element of the islands (raster::island_elements()).
void add_view_option(CLI::App& app, std::string& element);
