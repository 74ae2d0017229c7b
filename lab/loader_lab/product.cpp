// The product's reader, raster::read_model, as `render` calls it.
#include "loader_lab/loaders.hpp"

#include <raster/io/model.hpp>
#include <raster/io/model_file.hpp>

#include <set>

namespace loader_lab {

Reading by_product(const fs::path& path, bool maps, bool apart) {
    raster::ObjOptions options;  // what `render` passes, maps included unless asked not to
    options.load_textures = maps;
    options.limits.separate_process = apart;
    const raster::Model model = raster::read_model(path, options);
    Reading r;
    r.triangles = raster::triangle_count(model);  // flat ones were dropped while building it
    std::set<const raster::Texture*> textures;
    for (const raster::ModelPart& part : model.parts) {
        r.vertices += part.mesh.positions.size();
        if (part.texture != nullptr) textures.insert(part.texture.get());
    }
    r.materials = model.parts.size();  // one part per material the triangles use
    r.textures = textures.size();
    const raster::Bounds bounds = raster::bounds_of(model);
    // raster mirrors z into its left-handed world; mirrored back to compare with the others.
    r.box.add({bounds.low.x, bounds.low.y, -bounds.high.z});
    r.box.add({bounds.high.x, bounds.high.y, -bounds.low.z});
    if (!model.warnings.empty()) r.note = model.warnings.front();
    return r;
}

}  // namespace loader_lab
