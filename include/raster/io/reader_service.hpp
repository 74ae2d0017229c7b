#pragma once

#include <raster/io/model.hpp>
#include <raster/io/obj_file.hpp>

#include <filesystem>
#include <mutex>
#include <sys/types.h>

// A small process that forks the reader of each model. Forking a program that is drawing and
// encoding copies its page tables and makes every page it writes meanwhile a copy: about 4 ms a
// model in a batch. Started before the program grows threads and buffers, this process forks
// cheaply (doc/conventions.md#reader-process).
namespace raster {

class ReaderService {
public:
    // Forks the service now; throws std::runtime_error when it cannot.
    ReaderService();
    // Ends the service and waits for it.
    ~ReaderService();
    ReaderService(const ReaderService&) = delete;
    ReaderService& operator=(const ReaderService&) = delete;

    // What read_model(path, options) gives, the reading forked from the service. Calls from
    // several threads take turns. `processor_seconds`, when given, receives the reader's processor time.
    [[nodiscard]] Model read(const std::filesystem::path& path, const ObjOptions& options,
                             double* processor_seconds = nullptr) const;

private:
    int socket_ = -1;
    ::pid_t pid_ = -1;
    mutable std::mutex turn_;
};

}  // namespace raster
