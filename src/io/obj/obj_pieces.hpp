#pragma once

#include "io/model_builder.hpp"
#include "io/obj/obj_piece.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

// An OBJ text split into byte ranges at line ends, each range read on a core of its own, and the
// pieces joined in file order into one soup.
namespace raster::detail {

// Reads the text in up to `threads` ranges split at line ends, of about equal length and no more than one per
// `range_bytes`; throws
// std::runtime_error "NAME:LINE: ..." for the first problem in file order, as one reading from the start would.
[[nodiscard]] std::vector<ObjPiece> read_obj_pieces(std::string_view text, const std::string& name,
                                                    std::size_t max_corners, std::size_t max_line_bytes,
                                                    std::size_t threads, std::size_t range_bytes);

// The material each piece's statements put in force (-1 for mtllib and the default), and the one in force where it
// starts.
struct PieceMaterials {
    std::vector<int> by_statement;
    int entering = -1;
};

// The pieces in file order as one soup (emptied as they are joined): polygons split into exactly
// their own area, materials resolved, colours kept only when every vertex gives one.
[[nodiscard]] PolygonSoup join_obj_pieces(std::vector<ObjPiece>& pieces, const std::vector<PieceMaterials>& materials,
                                          std::size_t threads);

}  // namespace raster::detail
