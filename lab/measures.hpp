#pragma once

#include "corpus.hpp"
#include "fill_methods.hpp"
#include "line_methods.hpp"

#include <cstdint>
#include <string>

// Accuracy yardsticks (shared/guides/accuracy.md): each method against the exact reference.
namespace lab {

struct FillAccuracy {
    std::int64_t reference_pixels = 0;  // covered by the reference
    std::int64_t mismatches = 0;        // pixels where the method's count differs from the reference's
    std::int64_t cracks = 0;            // mesh pixels well inside the mesh that the method left empty
    std::int64_t double_hits = 0;       // mesh pixels the method hit more than once
};

struct LineAccuracy {
    std::int64_t reference_pixels = 0;
    std::int64_t mismatches = 0;
    double max_distance = 0.0;               // farthest drawn pixel centre from the ideal segment
    std::int64_t outside_neighbourhood = 0;  // drawn pixels not within one pixel of the reference set
    std::int64_t count_difference = 0;       // sum over segments of |drawn - reference|
    std::int64_t max_count_difference = 0;
    std::int64_t steps = 0;  // samples the method stepped through
};

[[nodiscard]] FillAccuracy measure_polygons(const FillMethod& method, const PolygonCorpus& corpus);
[[nodiscard]] FillAccuracy measure_mesh(const FillMethod& method, const MeshCase& mesh);
// Largest distance, in pixels, between the centroid of the covered pixels and the true centroid
// of a triangle moving 1/16 px per frame for 64 frames, `offset` pixels from the origin.
[[nodiscard]] double measure_motion(const FillMethod& method, std::int64_t offset);
[[nodiscard]] LineAccuracy measure_segments(const LineMethod& method, const SegmentCorpus& corpus);

}  // namespace lab
