#include "io/obj/obj_pieces.hpp"

#include "geometry/polygon_triangles.hpp"
#include "io/for_each_index.hpp"

#include <algorithm>
#include <exception>
#include <stdexcept>

namespace raster::detail {

namespace {

// Byte ranges of about equal length, each ending just after a '\n' (or at the text's end).
std::vector<std::string_view> ranges_of(std::string_view text, std::size_t threads, std::size_t least_bytes) {
    const std::size_t count = std::clamp<std::size_t>(text.size() / std::max<std::size_t>(least_bytes, 1), 1,
                                                      std::max<std::size_t>(threads, 1));
    std::vector<std::string_view> ranges;
    std::size_t start = 0;
    for (std::size_t k = 1; k <= count && start < text.size(); ++k) {
        std::size_t end = text.size();
        if (k < count) {
            const std::size_t newline = text.find('\n', std::max(start, text.size() / count * k));
            end = newline == std::string_view::npos ? text.size() : newline + 1;
        }
        ranges.push_back(text.substr(start, end - start));
        start = end;
    }
    if (ranges.empty()) ranges.emplace_back();
    return ranges;
}

bool any(const BadNumbers& bad) {
    return std::ranges::any_of(bad, [](const auto& list) { return !list.empty(); });
}

}  // namespace

std::vector<ObjPiece> read_obj_pieces(std::string_view text, const std::string& name, std::size_t max_corners,
                                      std::size_t max_line_bytes, std::size_t threads, std::size_t range_bytes) {
    std::vector<ObjRange> ranges;
    const std::vector<std::string_view> texts = ranges_of(text, threads, range_bytes);
    std::vector<ObjCounts> counts(texts.size());
    for_each_index(texts.size(), threads, [&](std::size_t i) { counts[i] = count_obj_range(texts[i], i == 0); });
    ObjCounts before;
    for (std::size_t i = 0; i < texts.size(); ++i) {
        ranges.push_back({texts[i], before, i == 0});
        before.lines += counts[i].lines;
        for (std::size_t k = 0; k < 3; ++k) before.defined[k] += counts[i].defined[k];
    }
    std::vector<ObjPiece> pieces(texts.size());
    std::vector<std::exception_ptr> failures(texts.size());
    for_each_index(texts.size(), threads, [&](std::size_t i) {
        try {
            pieces[i] = read_obj_range(ranges[i], name, max_corners, max_line_bytes);
        } catch (...) {
            failures[i] = std::current_exception();
        }
    });
    // A range that may use a bad number of an earlier one is checked again knowing them all (a range
    // looks up only indices before its own), every such range at once.
    BadNumbers bad;
    std::vector<bool> bad_before(texts.size());
    for (std::size_t i = 0; i < texts.size(); ++i) {
        bad_before[i] = any(bad);
        for (std::size_t k = 0; k < 3; ++k)
            bad[k].insert(bad[k].end(), pieces[i].bad[k].begin(), pieces[i].bad[k].end());
    }
    std::vector<std::exception_ptr> checked(texts.size());
    for_each_index(texts.size(), threads, [&](std::size_t i) {
        if (!bad_before[i] || !(failures[i] || pieces[i].names_earlier)) return;
        try {
            (void)read_obj_range(ranges[i], name, max_corners, max_line_bytes, &bad);
        } catch (...) {
            checked[i] = std::current_exception();
        }
    });
    for (std::size_t i = 0; i < texts.size(); ++i) {
        if (checked[i]) std::rethrow_exception(checked[i]);
        if (failures[i]) std::rethrow_exception(failures[i]);
        const ObjPiece& piece = pieces[i];
        if (piece.counts.lines != counts[i].lines || piece.counts.defined != counts[i].defined)
            throw std::runtime_error("its lines were counted two ways; please report this file");
    }
    return pieces;
}

PolygonSoup join_obj_pieces(std::vector<ObjPiece>& pieces, const std::vector<PieceMaterials>& materials,
                            std::size_t threads) {
    PolygonSoup soup;
    std::size_t coloured = 0, triangles = 0;
    std::vector<std::size_t> first_triangle;
    for (const ObjPiece& piece : pieces) {
        coloured += piece.coloured_vertices;
        first_triangle.push_back(triangles);
        triangles += piece.triangles.size();
    }
    const auto append = [](auto& to, auto& from) {
        to.insert(to.end(), from.begin(), from.end());
        from = {};
    };
    for (ObjPiece& piece : pieces) {
        append(soup.positions, piece.positions);
        append(soup.uvs, piece.uvs);
        append(soup.normals, piece.normals);
    }
    // OBJ's colours are all or none (doc/conventions.md#vertex-colours).
    const bool all_coloured = coloured == soup.positions.size() && coloured > 0;
    for (ObjPiece& piece : pieces) {
        if (all_coloured) append(soup.colours, piece.colours);
        piece.colours = {};
    }
    const auto finished = [&](const ObjCorner& read) {
        return SoupCorner{read.position, read.normal, read.uv, all_coloured ? read.position : kNoIndex};
    };
    soup.triangles.resize(triangles);
    for_each_index(pieces.size(), threads, [&](std::size_t i) {
        ObjPiece& piece = pieces[i];
        const PieceMaterials& in_force = materials[i];
        SoupTriangle* const out = soup.triangles.data() + first_triangle[i];
        for (std::size_t t = 0; t < piece.triangles.size(); ++t) {
            const ObjTriangle& read = piece.triangles[t];
            const int material =
                read.material < 0 ? in_force.entering : in_force.by_statement[static_cast<std::size_t>(read.material)];
            out[t] = {{finished(read.corners[0]), finished(read.corners[1]), finished(read.corners[2])}, material};
        }
        std::vector<glm::dvec3> outline;
        for (const HeldPolygon& polygon : piece.polygons) {
            const ObjCorner* const corners = piece.polygon_corners.data() + polygon.first_corner;
            outline.clear();
            for (std::size_t c = 0; c < polygon.corners; ++c)
                outline.emplace_back(soup.positions[static_cast<std::size_t>(corners[c].position)]);
            std::size_t t = polygon.first_triangle;
            // Each piece turned from OBJ's counter-clockwise order to raster's clockwise one.
            for (const auto& [a, b, c] : triangles_of_polygon(outline))
                out[t++].corners = {finished(corners[a]), finished(corners[c]), finished(corners[b])};
        }
        piece.triangles = {};
        piece.polygon_corners = {};
    });
    for (ObjPiece& piece : pieces) {
        // OBJ gives points and lines no material: they take the default (doc/conventions.md#points-and-lines).
        for (const ObjCorner& point : piece.points) soup.points.push_back({finished(point), -1});
        for (const auto& [from, to] : piece.segments) soup.segments.push_back({{finished(from), finished(to)}, -1});
        piece.points = {};
        piece.segments = {};
    }
    return soup;
}

}  // namespace raster::detail
