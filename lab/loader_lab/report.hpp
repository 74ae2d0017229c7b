#pragma once

#include "loader_lab/cases.hpp"

#include <vector>

// What the lab found, as loaders.csv (for lab/loader_chart.gp) and loaders-summary.md.
namespace loader_lab {

// Every (file, loader): status, load times in ms, what it read and whether it agrees.
void write_csv(const std::vector<Case>& all, const fs::path& models, const fs::path& out);
// Tables of load times, of what each read, and of how each met the malformed files.
void write_summary(const std::vector<Case>& all, const fs::path& models, int rounds, const fs::path& out);

}  // namespace loader_lab
