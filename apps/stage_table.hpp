#pragma once

#include <raster/render/stage_times.hpp>

#include <string>

// render --timings: a job's stage times as a small table, for standard error.
std::string stage_table(const raster::StageTimes& times);
