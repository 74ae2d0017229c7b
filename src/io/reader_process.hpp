#pragma once

#include <raster/io/model.hpp>
#include <raster/io/reader_limits.hpp>

#include "io/shared_bytes.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

// A model read in a child process under limits, so that a reader we do not own (assimp,
// tinyobjloader, stb_image) can crash, loop or allocate without end and take only itself down.
namespace raster::detail {

// Runs `read` in a forked child with its address space, processor time and file writes
// limited, and takes its model back through shared memory; in this process when the limits say so.
// Throws std::runtime_error with one line naming `name` when the child crashed ("the
// `reader` reader crashed"), ran out of memory or time, or `read` threw.
// What a reader child left: its message (length first stripped), how it ended, and whether
// the waiting side stopped it for time or for the size of what it sent.
struct ChildOutcome {
    std::vector<std::uint8_t> message;  // a model's says how many bytes of `shared` hold it
    SharedBytes shared;
    int status = 0;  // as waitpid gives it
    double processor_seconds = 0.0;
    bool timed_out = false;
    bool too_large = false;
    std::string start_error;  // why no child could be started, or ""
};

// How the model comes back: in shared memory where the system makes one, else in the pipe's message
// (doc/conventions.md#reader-process); `pipe` acts out a system that refuses memfd_create.
enum class ModelPassage : std::uint8_t { shared_memory, pipe };

// Forks a child that runs `read` under `limits` and collects what it sends.
[[nodiscard]] ChildOutcome run_reader_child(const std::function<Model()>& read, const ReaderLimits& limits,
                                            ModelPassage passage = ModelPassage::shared_memory);

// The model a child sent, or the one line that says why there is none.
[[nodiscard]] Model model_from_outcome(const ChildOutcome& outcome, const std::string& name, const std::string& reader,
                                       const ReaderLimits& limits);

// The memory a reader may take under `limits`: its own, or the default.
[[nodiscard]] std::uint64_t memory_in_force(const ReaderLimits& limits);

// The one line for a reader that needs more memory than `limits` allow.
[[nodiscard]] std::string memory_refusal(const std::string& name, const std::string& reader,
                                         const ReaderLimits& limits);

// `processor_seconds`, when given, receives the child's processor time.
[[nodiscard]] Model read_in_child(const std::function<Model()>& read, const std::string& name,
                                  const std::string& reader, const ReaderLimits& limits,
                                  double* processor_seconds = nullptr);

}  // namespace raster::detail
