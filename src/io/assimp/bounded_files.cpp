#include "io/assimp/bounded_files.hpp"

#include "io/gltf/gltf_structure.hpp"
#include "io/named_path.hpp"
#include "io/ply_header.hpp"

#include <optional>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <assimp/MemoryIOWrapper.h>

namespace raster::detail {

std::string structure_problem(std::span<const std::uint8_t> bytes, const std::string& extension,
                              const std::filesystem::path& directory, const ObjOptions& options, PlyShape* ply,
                              GltfFacts* gltf) {
    if (extension == ".ply") {
        if (std::string problem = ply_header_problem(bytes); !problem.empty()) return problem;
        return ply_counts_problem(bytes, ply);
    }
    if (extension != ".gltf" && extension != ".glb") return "";
    return gltf_structure_problem(
        bytes, extension == ".glb",
        [&](std::string_view uri) -> std::optional<std::uint64_t> {
            try {
                std::error_code error;
                const std::filesystem::path file = resolve_named_path(directory, std::string(uri), options.confine);
                // Outside the confinement a size would tell an uploader something: its reader refuses it instead.
                if (!options.confine.empty() && std::filesystem::weakly_canonical(file, error)
                                                    .lexically_relative(options.confine)
                                                    .string()
                                                    .starts_with(".."))
                    return std::nullopt;
                const std::uintmax_t size = std::filesystem::file_size(file, error);
                return error ? std::nullopt : std::optional<std::uint64_t>(size);
            } catch (const std::runtime_error&) {
                return std::nullopt;
            }
        },
        gltf);
}

// A stream over bytes in memory that leaves `open` when deleted, whoever deletes it.
class TrackedStream final : public Assimp::MemoryIOStream {
public:
    TrackedStream(const std::uint8_t* data, std::size_t size, std::unordered_set<TrackedStream*>& open)
        : Assimp::MemoryIOStream(data, size, false), open_(open) {}
    ~TrackedStream() override { open_.erase(this); }
    TrackedStream(const TrackedStream&) = delete;
    TrackedStream& operator=(const TrackedStream&) = delete;

private:
    std::unordered_set<TrackedStream*>& open_;
};

BoundedFiles::BoundedFiles(const ObjOptions& options, std::vector<InputRecord>& sources, std::filesystem::path model,
                           std::string extension)
    : options_(options), sources_(sources), model_(std::move(model)), extension_(std::move(extension)) {
    has_model_ = !model_.empty() && identity_of(model_, model_identity_);
}

BoundedFiles::~BoundedFiles() {
    // assimp deletes most streams itself, but not one it was reading when it threw.
    for (TrackedStream* stream : std::unordered_set<TrackedStream*>(open_)) delete stream;
}

bool BoundedFiles::Exists(const char* file) const {
    FileIdentity identity;
    return identity_of(file, identity);
}

Assimp::IOStream* BoundedFiles::Open(const char* file, const char* mode) {
    if (std::string(mode).find_first_of("wa+") != std::string::npos) return nullptr;  // reading only
    InputRules rules;
    FileIdentity identity;
    const bool exists = identity_of(file, identity);
    const bool is_model = has_model_ && exists && identity == model_identity_;
    rules.role = is_model || sources_.empty() ? "model" : "model buffer";
    rules.max_bytes = kMaxModelFileBytes;
    rules.confine = options_.confine;
    try {
        if (exists && !is_model) sources_.push_back({file, identity, rules.role});
        if (is_model && !model_recorded_) {
            sources_.push_back({file, identity, rules.role});
            model_recorded_ = true;
        }
        auto bytes = std::make_unique<std::vector<std::uint8_t>>(read_input_file(file, rules));
        if (is_model) {
            if (std::string problem =
                    structure_problem(*bytes, extension_, model_.parent_path(), options_, &ply_shape_, &gltf_facts_);
                !problem.empty()) {
                throw std::runtime_error(problem);
            }
        }
        // An empty file still gets a real address: assimp copies from it.
        const std::uint8_t* data = bytes->empty() ? &kNoByte : bytes->data();
        const std::size_t size = bytes->size();
        buffers_.push_back(std::move(bytes));
        auto* stream = new TrackedStream(data, size, open_);
        open_.insert(stream);
        return stream;
    } catch (const std::runtime_error& problem) {
        if (first_failure_.empty()) {
            first_failure_ = "'" + printable(file) + "' " + problem.what();
            first_reason_ = problem.what();
        }
        return nullptr;
    }
}

void BoundedFiles::Close(Assimp::IOStream* stream) { delete stream; }

}  // namespace raster::detail
