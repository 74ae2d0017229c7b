#pragma once

#include <cstddef>
#include <exception>
#include <filesystem>
#include <functional>
#include <future>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

// Several models rendered in one run: where each picture goes, and a loop that reads the next
// model while the current one is drawn.

struct BatchJob {
    std::string model;
    std::filesystem::path output;
};

// DIR/NAME.EXTENSION for each model, NAME being its file name without the extension. Throws
// std::runtime_error, before any work, for two models that would write one file or an output
// that is one of the models.
std::vector<BatchJob> plan_batch(const std::vector<std::string>& models, const std::filesystem::path& dir,
                                 const std::string& extension);

// Runs `load` one job ahead of `use`, on a thread of its own, so that reading a model overlaps
// drawing the one before. `between` runs after each load ends (with the model read, or null)
// and before the next begins, the one moment no model is being read: files are written then,
// so none is read half-replaced. A
// job whose load or use throws goes to `fail` with the reason, and the loop goes on. Returns how
// many jobs `use` finished.
template <typename Loaded>
std::size_t run_prefetched(const std::vector<BatchJob>& jobs, const std::function<Loaded(const BatchJob&)>& load,
                           const std::function<void(const BatchJob&, Loaded&)>& use,
                           const std::function<void(Loaded*)>& between,
                           const std::function<void(const BatchJob&, const std::string&)>& fail) {
    const auto start = [&](std::size_t i) {
        try {
            return std::async(std::launch::async, load, std::cref(jobs[i]));
        } catch (const std::system_error&) {  // no thread to spare: read it here instead
            std::promise<Loaded> now;
            try {
                now.set_value(load(jobs[i]));
            } catch (...) {
                now.set_exception(std::current_exception());
            }
            return now.get_future();
        }
    };
    std::size_t succeeded = 0;
    std::future<Loaded> next = jobs.empty() ? std::future<Loaded>() : start(0);
    for (std::size_t i = 0; i < jobs.size(); ++i) {
        std::future<Loaded> current = std::move(next);
        std::optional<Loaded> loaded;
        std::string failure;
        try {
            loaded.emplace(current.get());
        } catch (const std::exception& error) {
            failure = error.what();
        }
        between(loaded ? &*loaded : nullptr);
        if (i + 1 < jobs.size()) next = start(i + 1);
        if (!loaded) {
            fail(jobs[i], failure);
            continue;
        }
        try {
            use(jobs[i], *loaded);
            ++succeeded;
        } catch (const std::exception& error) {
            fail(jobs[i], error.what());
        }
    }
    between(nullptr);
    return succeeded;
}
