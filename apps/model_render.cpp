#include "model_render.hpp"

#include "animation_export.hpp"

#include <raster/io/model_file.hpp>
#include <raster/io/texture_file.hpp>
#include <raster/platform/stopwatch.hpp>

#include <cstdio>
#include <iostream>
#include <numbers>
#include <stdexcept>
#include <utility>

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string seconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f s", seconds);
    return text;
}

LoadedModel load_model(const std::string& path, const RenderPlan& plan) {
    const auto start = std::chrono::steady_clock::now();
    LoadedModel loaded;
    raster::Model model = raster::read_model(path, plan.obj, &loaded.times.read.spent);
    raster::Stopwatch preparing;
    loaded.inputs = model.sources;
    loaded.inputs.insert(loaded.inputs.end(), plan.texture_inputs.begin(), plan.texture_inputs.end());
    loaded.warnings = model.warnings;
    if (plan.texture) {
        for (std::string& warning : raster::replace_diffuse_maps(model, plan.texture, plan.texture_path))
            loaded.warnings.push_back(warning);
    }
    for (raster::ModelPart& part : model.parts) part.sampler.filter = plan.filter;
    if (plan.camera < 0 && !model.cameras.empty()) {  // carried, not drawn from: said once
        const std::size_t count = model.cameras.size();
        loaded.warnings.push_back(path + ": it carries " + std::to_string(count) +
                                  (count == 1 ? " camera" : " cameras") +
                                  " (raster frames the model itself; --camera N draws from one)");
    }
    const std::size_t triangles = raster::triangle_count(model), points = raster::point_count(model),
                      lines = raster::segment_count(model);
    if (triangles > 0 || (points == 0 && lines == 0)) loaded.contents = std::to_string(triangles) + " triangles";
    if (points > 0) loaded.contents += (loaded.contents.empty() ? "" : ", ") + std::to_string(points) + " points";
    if (lines > 0) loaded.contents += (loaded.contents.empty() ? "" : ", ") + std::to_string(lines) + " lines";
    loaded.model = std::move(model);
    loaded.times.prepare.spent = preparing.lap();
    loaded.seconds = seconds_since(start);
    return loaded;
}

std::function<FinishedPicture()> render_model(const CLI::App& app, ExportOptions options, LoadedModel& loaded,
                                              const RenderPlan& plan, raster::Renderer& renderer,
                                              raster::StageTimes* times) {
    const auto start = std::chrono::steady_clock::now();
    raster::Stopwatch preparing;
    options.inputs = loaded.inputs;
    if (!options.quiet) {
        for (const std::string& warning : loaded.warnings)
            std::cerr << app.get_name() << ": warning: " << warning << '\n';
    }
    raster::ModelView view = plan.view;
    if (plan.camera >= 0) {
        const auto index = static_cast<std::size_t>(plan.camera);
        if (index >= loaded.model.cameras.size())
            throw std::invalid_argument(raster::camera_refusal(loaded.model, index));
        view = raster::through_camera(view, loaded.model.cameras[index], loaded.model);
    }
    const raster::ModelStage stage(std::move(loaded.model), view, options.width, options.height);
    if (times != nullptr) times->prepare.spent += preparing.lap();
    const auto draw = [&](raster::Framebuffer& frame, double turn, std::vector<std::uint8_t>& alpha) {
        stage.render(frame, renderer, turn, times);
        if (plan.view.transparent) alpha = renderer.coverage();
    };
    const std::string tail = ", " + loaded.contents + ", ";
    const double loading = loaded.seconds;
    if (plan.frames == 0) {
        auto finish = render_still(app, options, [&](raster::Framebuffer& frame, std::vector<std::uint8_t>& alpha) {
            draw(frame, 0.0, alpha);
        });
        return [finish = std::move(finish), tail, loading, start] {
            FinishedPicture done = finish();
            done.report += tail + seconds_text(loading + seconds_since(start));
            return done;
        };
    }
    // The frames are encoded while the next are drawn: encode is what the export spends besides drawing.
    const raster::StageTimes before = times != nullptr ? *times : raster::StageTimes{};
    raster::Stopwatch exporting;
    std::string report = export_animation(app, options, plan.frames, plan.fps,
                                          [&](raster::Framebuffer& frame, int index, std::vector<std::uint8_t>& alpha) {
                                              draw(frame, 2.0 * std::numbers::pi * index / plan.frames, alpha);
                                          });
    if (times != nullptr) {
        raster::Spent rest = exporting.lap();
        for (const auto stage_of :
             {&raster::StageTimes::prepare, &raster::StageTimes::draw, &raster::StageTimes::resolve}) {
            rest.wall -= (times->*stage_of).spent.wall - (before.*stage_of).spent.wall;
            rest.processor -= (times->*stage_of).spent.processor - (before.*stage_of).spent.processor;
        }
        times->encode.spent += rest;
    }
    report += tail + seconds_text(loading + seconds_since(start));
    return [report] { return FinishedPicture{{}, report, true}; };
}
