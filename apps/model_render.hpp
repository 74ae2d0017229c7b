#pragma once

#include "export_options.hpp"
#include "still_export.hpp"

#include <raster/io/obj_file.hpp>
#include <raster/render/model_scene.hpp>
#include <raster/shade/texture.hpp>

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>
#include <CLI/CLI.hpp>

// render's models: each read with what its reading found, then drawn as a still or a turntable.

// A model read and made ready to draw, with what its reading found.
struct LoadedModel {
    raster::Model model;                      // handed to the stage that draws it
    std::vector<raster::InputRecord> inputs;  // every file read for it, which no output may replace
    std::vector<std::string> warnings;
    std::string contents;      // "N triangles", and points and lines where it has them
    double seconds = 0.0;      // reading it took
    raster::StageTimes times;  // its read and prepare, for --timings
    std::string refusal;       // why a batch will not draw it, though it was read
};

// What every model of a run shares: how to read it and how to look at it.
struct RenderPlan {
    raster::ObjOptions obj;
    std::shared_ptr<const raster::Texture> texture;  // --texture, read once
    std::string texture_path;
    std::vector<raster::InputRecord> texture_inputs;
    raster::TextureFilter filter = raster::TextureFilter::trilinear;
    raster::ModelView view;
    int camera = -1;  // --camera: which of the file's cameras to draw from; -1 for raster's own framing
    int frames = 0;   // 0: a still
    int fps = 30;
    bool timings = false;  // --timings: each stage's time on standard error
};

LoadedModel load_model(const std::string& path, const RenderPlan& plan);

// Draws one loaded model, taking its model, and returns the step that finishes it: a still's
// encoding, which may overlap the next model's drawing (an animation is written at once). `times`, when given,
// receives the prepare and draw times, and an animation's encode: the rest of its export.
std::function<FinishedPicture()> render_model(const CLI::App& app, ExportOptions options, LoadedModel& loaded,
                                              const RenderPlan& plan, raster::Renderer& renderer,
                                              raster::StageTimes* times = nullptr);

double seconds_since(std::chrono::steady_clock::time_point start);
// "1.25 s", for the report lines.
std::string seconds_text(double seconds);
