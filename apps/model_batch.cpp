#include "model_batch.hpp"

#include <raster/io/input_file.hpp>

#include <map>
#include <stdexcept>

std::vector<BatchJob> plan_batch(const std::vector<std::string>& models, const std::filesystem::path& dir,
                                 const std::string& extension) {
    std::vector<BatchJob> jobs;
    std::map<std::filesystem::path, std::string> claimed;  // output -> the model that writes it
    std::vector<raster::FileIdentity> identities(models.size());
    std::vector<bool> known(models.size());
    for (std::size_t i = 0; i < models.size(); ++i) known[i] = raster::identity_of(models[i], identities[i]);
    for (const std::string& model : models) {
        std::filesystem::path output = dir / std::filesystem::path(model).stem();
        output += extension;
        if (const auto [at, fresh] = claimed.emplace(output, model); !fresh) {
            throw std::runtime_error("'" + raster::printable(at->second) + "' and '" + raster::printable(model) +
                                     "' would both write '" + raster::printable(output.string()) +
                                     "'; render them into different --output-dir");
        }
        raster::FileIdentity identity;
        if (raster::identity_of(output, identity)) {
            for (std::size_t i = 0; i < models.size(); ++i) {
                if (known[i] && identities[i] == identity) {
                    throw std::runtime_error("'" + raster::printable(output.string()) + "' is the model '" +
                                             raster::printable(models[i]) + "'; a picture never replaces its input");
                }
            }
        }
        jobs.push_back({model, std::move(output)});
    }
    return jobs;
}
