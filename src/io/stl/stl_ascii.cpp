#include "io/stl/stl_ascii.hpp"

#include "io/stl/stl_mesh.hpp"
#include "io/stl/stl_words.hpp"

#include <raster/io/input_file.hpp>

#include <array>
#include <string>
#include <string_view>

namespace raster::detail {
namespace {

glm::vec3 three_numbers(StlWords& words, const std::string& inside) {
    const float x = words.number(inside);
    const float y = words.number(inside);
    return {x, y, words.number(inside)};
}

}  // namespace

Model read_ascii_stl(PlyBytes& bytes, const std::string& name, const ObjOptions& options, Model model) {
    StlWords words(bytes, name);
    StlMesh mesh(options.crease_degrees);
    std::string_view word;
    if (!words.next(word)) words.fail("an ASCII STL begins with 'solid'");
    if (word.starts_with("\xEF\xBB\xBF")) word.remove_prefix(3);  // a UTF-8 byte order mark
    if (!is_keyword(word.substr(0, 5), "solid")) words.fail("an ASCII STL begins with 'solid'");
    words.skip_line();  // the solid's name
    std::uint64_t facets = 0;
    bool ended = false;
    while (words.next(word)) {
        if (is_keyword(word.substr(0, 8), "endsolid")) {
            words.skip_line();
            if (!words.next(word)) {
                ended = true;
                break;
            }
            if (!is_keyword(word.substr(0, 5), "solid")) {  // assimp stops here too
                model.warnings.push_back(name + ":" + std::to_string(words.line()) +
                                         ": text after 'endsolid' that begins no solid; not read");
                ended = true;
                break;
            }
            words.skip_line();
            continue;
        }
        if (!is_keyword(word, "facet")) words.fail("'facet' or 'endsolid' expected, not '" + printable(word, 40) + "'");
        const std::string facet = "facet " + std::to_string(++facets);
        words.expect("normal", facet);
        const glm::vec3 normal = three_numbers(words, facet);
        words.expect("outer", facet);
        words.expect("loop", facet);
        std::array<glm::vec3, 3> corners{};
        for (glm::vec3& corner : corners) {
            words.expect("vertex", facet);
            corner = three_numbers(words, facet);
        }
        words.expect("endloop", facet);
        words.expect("endfacet", facet);
        if (!mesh.add(corners, normal, nullptr)) words.fail(facet + " has a corner that is not a finite point");
    }
    mesh.add_part_to(model, LinearRgb{1.0F, 1.0F, 1.0F});
    if (model.parts.empty()) {
        throw std::runtime_error(name + ": " + kNothingToDraw +
                                 (facets == 0 ? " (its solids hold no facets)" : " (every facet has no area)"));
    }
    if (!ended) model.warnings.push_back(name + ": the file ends without 'endsolid'; drawing the facets it holds");
    return model;
}

}  // namespace raster::detail
