#include "render_batch.hpp"

#include "delivery.hpp"
#include "finished_picture.hpp"
#include "model_batch.hpp"
#include "model_render.hpp"
#include "render_option_values.hpp"

#include <raster/io/input_file.hpp>

#include <algorithm>
#include <cstdio>
#include <deque>
#include <exception>
#include <filesystem>
#include <functional>
#include <future>
#include <iostream>
#include <map>
#include <stdexcept>
#include <system_error>
#include <utility>
#include <vector>

namespace {

// The models and where each picture goes, less those already there with --skip-existing
// (counted in `kept`), with DIR made.
std::vector<BatchJob> planned_jobs(const CLI::App& app, const RenderArguments& arguments, ImageFormat format,
                                   std::size_t& kept) {
    const ExportOptions& options = arguments.options;
    std::vector<std::string> models{arguments.model_path};
    if (app.count("output") > 0) {
        if (!looks_like_a_model(options.output)) {
            throw CLI::ValidationError("'" + raster::printable(options.output) +
                                       "' is not a model (.obj, .gltf, .glb, .stl, .ply, .fbx, .dae, ...); "
                                       "with --output-dir, pictures are named after their models");
        }
        models.push_back(options.output);
    }
    models.insert(models.end(), arguments.more_models.begin(), arguments.more_models.end());
    std::vector<BatchJob> jobs = plan_batch(models, arguments.output_dir, file_extension(format));
    if (options.skip_existing) {  // pictures are written atomically: one that decodes is whole
        kept = std::erase_if(jobs, [&](const BatchJob& job) { return holds_finished_picture(job.output, format); });
    }
    std::error_code error;
    std::filesystem::create_directories(arguments.output_dir, error);
    if (error || !std::filesystem::is_directory(arguments.output_dir)) {
        throw std::runtime_error("cannot make the output directory '" + raster::printable(arguments.output_dir) + "'" +
                                 (error ? ": " + error.message() : ": a file of that name is in the way"));
    }
    return jobs;
}

}  // namespace

std::string render_batch(const CLI::App& app, const RenderArguments& arguments, ImageFormat format,
                         raster::Renderer& renderer, std::chrono::steady_clock::time_point start) {
    const ExportOptions& options = arguments.options;
    std::size_t kept = 0;
    std::vector<BatchJob> jobs = planned_jobs(app, arguments, format, kept);
    const auto report_failure = [&](const BatchJob& job, const std::string& reason) {
        const std::string model = raster::printable(job.model);
        std::cerr << app.get_name() << ": " << (reason.starts_with(model + ":") ? "" : model + ": ") << reason << '\n';
    };
    // Pictures are encoded on one thread per core at most while the next models are drawn
    // (encoding is most of a small model's time), and written between two reads, checked
    // against every file any model has read: no picture replaces another model's input.
    struct Encoding {
        const BatchJob* job;
        ExportOptions options;
        std::future<FinishedPicture> picture;
    };
    std::deque<Encoding> encoding, encoded;
    const auto in_flight = static_cast<std::size_t>(options.threads_in_use());
    std::vector<raster::InputRecord> every_input;
    std::vector<raster::FileIdentity> pictures;  // written so far
    std::size_t failed_writes = 0;
    // A file already at a picture's place may be what a later model reads: such pictures wait
    // until every model has been read (README: Rendering models you did not make).
    std::vector<HeldPicture> held;
    std::map<std::string, std::string> held_reports;  // by output
    std::vector<bool> existed(jobs.size());
    for (std::size_t i = 0; i < jobs.size(); ++i) {
        std::error_code missing;
        existed[i] = std::filesystem::exists(std::filesystem::symlink_status(jobs[i].output, missing));
    }
    const auto hold_if_existed = [&](const BatchJob& job, ExportOptions& one) {
        if (existed[static_cast<std::size_t>(&job - jobs.data())]) one.held = &held;
    };
    const auto write_encoded = [&] {
        for (Encoding& done : encoded) {
            try {
                const FinishedPicture picture = done.picture.get();
                done.options.inputs = every_input;
                if (!picture.written) deliver(done.options, picture.bytes);
                raster::FileIdentity identity;  // a held picture is not written yet: the file there is not ours
                if (done.options.held == nullptr && raster::identity_of(done.options.output, identity))
                    pictures.push_back(identity);
                if (done.options.held != nullptr) {
                    held_reports[done.options.output] = picture.report;  // said once it is written
                } else if (!options.quiet) {
                    std::cout << picture.report << '\n' << std::flush;
                }
            } catch (const std::exception& problem) {
                report_failure(*done.job, problem.what());
                ++failed_writes;
            }
        }
        encoded.clear();
    };
    const std::size_t drawn = run_prefetched<LoadedModel>(
        jobs, [&](const BatchJob& job) { return load_model(job.model, arguments.plan); },
        [&](const BatchJob& job, LoadedModel& loaded) {
            if (!loaded.refusal.empty()) throw std::runtime_error(loaded.refusal);
            ExportOptions one = options;
            one.output = job.output.string();
            one.show_progress = false;
            hold_if_existed(job, one);
            std::function<FinishedPicture()> finish = render_model(app, one, loaded, arguments.plan, renderer);
            while (encoding.size() >= in_flight) {  // wait for the oldest; it is written between reads
                encoding.front().picture.wait();
                encoded.push_back(std::move(encoding.front()));
                encoding.pop_front();
            }
            encoding.push_back({&job, std::move(one), std::async(std::launch::async, std::move(finish))});
        },
        [&](LoadedModel* loaded) {
            if (loaded != nullptr) {  // what it read is known before anything more is written
                for (const raster::InputRecord& input : loaded->inputs) {
                    if (std::find(pictures.begin(), pictures.end(), input.identity) != pictures.end()) {
                        loaded->refusal =
                            "reads '" + raster::printable(input.path.string()) + "', a picture this run wrote";
                    }
                }
                every_input.insert(every_input.end(), loaded->inputs.begin(), loaded->inputs.end());
            }
            write_encoded();
        },
        report_failure);
    for (Encoding& last : encoding) encoded.push_back(std::move(last));
    write_encoded();
    for (HeldPicture& picture : held) {  // every model has been read: what each read is known
        picture.options.inputs = every_input;
        const auto job = std::find_if(jobs.begin(), jobs.end(),
                                      [&](const BatchJob& j) { return j.output.string() == picture.options.output; });
        try {
            deliver(picture.options, picture.bytes);
            if (!options.quiet) std::cout << held_reports[picture.options.output] << '\n' << std::flush;
        } catch (const std::exception& problem) {
            report_failure(*job, problem.what());
            ++failed_writes;
        }
    }
    const std::size_t written = drawn - failed_writes;
    const double seconds = seconds_since(start);
    const std::string summary = std::to_string(written) + " of " + std::to_string(jobs.size()) + " models into " +
                                raster::printable(arguments.output_dir) + " in " + seconds_text(seconds) +
                                (kept > 0 ? ", " + std::to_string(kept) + " already there kept" : "");
    if (written < jobs.size())
        throw std::runtime_error("wrote " + summary + "; " + std::to_string(jobs.size() - written) + " failed");
    char rate[64];
    std::snprintf(rate, sizeof rate, " (%.1f a second)", static_cast<double>(written) / std::max(seconds, 1e-9));
    return "Rendered " + summary + rate;
}
