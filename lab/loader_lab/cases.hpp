#pragma once

#include "loader_lab/probe.hpp"

#include <map>
#include <string>
#include <vector>

// The files the lab reads: assimp-testmodels' well-formed models, and its malformed ones of the formats raster reads.
namespace loader_lab {

struct Case {
    std::string label;  // as the chart and tables name it
    fs::path path;
    bool malformed;
    std::map<Loader, Outcome> outcomes{};
    std::map<Loader, std::vector<double>> seconds{};  // one per round: the mean load of a batch
    std::map<Loader, int> batch{};
    std::map<Loader, std::string> disagreements{};
};

// The cases found under `models`, well-formed first; a missing file is skipped with a line on stderr.
std::vector<Case> cases(const fs::path& models);

}  // namespace loader_lab
