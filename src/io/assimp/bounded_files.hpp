#pragma once

#include <raster/io/input_file.hpp>
#include <raster/io/obj_file.hpp>

#include "io/gltf/gltf_facts.hpp"
#include "io/ply_header.hpp"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <unordered_set>
#include <vector>
#include <assimp/IOSystem.hpp>

// Every file assimp opens (the model, glTF buffers and images) goes through InputFile: regular
// files only, sizes capped, confinement kept, each one remembered as an input of the run.
namespace raster::detail {

class TrackedStream;

class BoundedFiles final : public Assimp::IOSystem {
public:
    // `model`: the file whose structure is checked whenever it is opened; `extension` its format.
    BoundedFiles(const ObjOptions& options, std::vector<InputRecord>& sources, std::filesystem::path model = {},
                 std::string extension = {});
    ~BoundedFiles() override;
    BoundedFiles(const BoundedFiles&) = delete;
    BoundedFiles& operator=(const BoundedFiles&) = delete;

    bool Exists(const char* file) const override;
    char getOsSeparator() const override { return '/'; }
    Assimp::IOStream* Open(const char* file, const char* mode) override;
    void Close(Assimp::IOStream* stream) override;

    // Why the first file that could not be opened was refused, or "".
    [[nodiscard]] const std::string& first_failure() const noexcept { return first_failure_; }
    // The same without the file's name: "does not exist".
    [[nodiscard]] const std::string& first_reason() const noexcept { return first_reason_; }
    // What the model's body holds, when it is a PLY that passed its checks.
    [[nodiscard]] const PlyShape& ply_shape() const noexcept { return ply_shape_; }
    // What a glTF model's JSON says beyond what assimp reads: its extensions, materials' extensions, cameras.
    [[nodiscard]] const GltfFacts& gltf_facts() const noexcept { return gltf_facts_; }

private:
    static constexpr std::uint8_t kNoByte = 0;
    const ObjOptions& options_;
    std::vector<InputRecord>& sources_;
    std::filesystem::path model_;
    std::string extension_;
    FileIdentity model_identity_;
    bool has_model_ = false;
    bool model_recorded_ = false;
    std::vector<std::unique_ptr<std::vector<std::uint8_t>>> buffers_;
    std::unordered_set<TrackedStream*> open_;
    std::string first_failure_;
    std::string first_reason_;
    PlyShape ply_shape_;
    GltfFacts gltf_facts_;
};

// The checks a model file passes before assimp parses it, on every open: assimp opens some
// files twice, and a check made only the first time is no check. "" when it passes.
// A PLY's shape goes to `ply` and what a glTF says beyond assimp to `gltf` when given.
[[nodiscard]] std::string structure_problem(std::span<const std::uint8_t> bytes, const std::string& extension,
                                            const std::filesystem::path& directory, const ObjOptions& options,
                                            PlyShape* ply = nullptr, GltfFacts* gltf = nullptr);

}  // namespace raster::detail
