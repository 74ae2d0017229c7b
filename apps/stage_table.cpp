#include "stage_table.hpp"

#include <cstdio>
#include <utility>

std::string stage_table(const raster::StageTimes& times) {
    const std::pair<const char*, const raster::StageTime*> rows[] = {{"read", &times.read},
                                                                     {"prepare", &times.prepare},
                                                                     {"draw", &times.draw},
                                                                     {"resolve", &times.resolve},
                                                                     {"encode", &times.encode}};
    std::string table = "stage      wall s    cpu s  one core\n";
    char line[160];
    for (const auto& [name, stage] : rows) {
        if (stage == &times.resolve && times.resolve_in_draw && !(stage->spent.wall > 0.0)) {
            std::snprintf(line, sizeof line, "%-8s  in draw: transparent surfaces are resolved strip by strip\n", name);
        } else if (!(stage->spent.wall > 0.0)) {  // no time: no share to give
            std::snprintf(line, sizeof line, "%-8s %7.2f  %7.2f         -\n", name, 0.0, stage->spent.processor);
        } else {
            const double share = raster::one_core_share(*stage, times.threads);
            std::snprintf(line, sizeof line, "%-8s %7.2f  %7.2f  %7.0f%%%s\n", name, stage->spent.wall,
                          stage->spent.processor, 100.0 * share, stage->counted ? "" : " ~");
        }
        table += line;
    }
    if (times.threads <= 1) return table + "one core: all of every stage, on one thread (--threads 1)\n";
    const std::string threads = std::to_string(times.threads);
    return table + "one core: share of the wall time with at most one of the " + threads +
           " threads busy; ~ estimated as (T*W - C)/((T-1)*W), T = " + threads +
           ", as if the stage ran on one thread or on all\n";
}
