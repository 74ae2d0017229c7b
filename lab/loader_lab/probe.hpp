#pragma once

#include "loader_lab/loaders.hpp"

#include <string>

// Each (file, loader) loaded once in a forked child: a loader that crashes or loops takes only the child down.
namespace loader_lab {

// How a load in a child process ended: "accepted", "refused", "loaded, unsafe" (the library took it
// but our walk found it unusable), "crashed (...)", "hung (...)" or "died (...)".
struct Outcome {
    std::string status;
    Reading reading;
    std::string message;  // why it refused, or its first warning
};

// Loads the file once in a forked child, killed after kProbeSeconds.
Outcome probe(Loader loader, const fs::path& path);

}  // namespace loader_lab
