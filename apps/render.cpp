#include "command_line.hpp"
#include "delivery.hpp"
#include "model_render.hpp"
#include "render_batch.hpp"
#include "render_options.hpp"
#include "render_outputs.hpp"
#include "stage_table.hpp"

#include <raster/io/reader_service.hpp>

#include <chrono>
#include <iostream>

int main(int argc, char** argv) {
    CLI::App app(render_description(), "render");
    RenderArguments arguments;
    add_render_options(app, arguments);
    raster::StageTimes times;  // --timings: printed after the report

    const int status = run_exporter(app, arguments.options, argc, argv, [&] {
        const auto start = std::chrono::steady_clock::now();
        // Forked now, while the process is small: each model's reader is forked from it.
        const raster::ReaderService readers;
        settle_arguments(app, arguments, readers);
        raster::Renderer renderer(arguments.options.render_options());
        const ImageFormat format = picture_format(app, arguments);
        if (!arguments.output_dir.empty()) return render_batch(app, arguments, format, renderer, start);
        name_the_picture(app, arguments, format);
        LoadedModel loaded = load_model(arguments.model_path, arguments.plan);
        times = loaded.times;
        times.threads = renderer.threads();
        const auto finish = render_model(app, arguments.options, loaded, arguments.plan, renderer,
                                         arguments.plan.timings ? &times : nullptr);
        raster::Stopwatch encoding;  // a still's encoding and writing; an animation's is timed as it is made
        const FinishedPicture done = finish();
        if (!done.written) {
            arguments.options.inputs = loaded.inputs;
            deliver(arguments.options, done.bytes);
        }
        if (arguments.plan.frames == 0) times.encode.spent += encoding.lap();
        return done.report;
    });
    if (status == 0 && arguments.plan.timings) std::cerr << stage_table(times) << std::flush;
    return status;
}
