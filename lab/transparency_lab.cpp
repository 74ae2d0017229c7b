// Exact transparency against the cheap methods (doc/conventions.md#transparency): its error
// against per-object sorting and weighted blended OIT on crossing layers, and its cost on a
// frame of eight layers over every pixel against the same layers opaque. Prints two CSV tables.
#include <raster/image/colour.hpp>
#include <raster/render/scene.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <utility>
#include <vector>
#include <glm/ext/matrix_transform.hpp>

namespace {

// A square of side 2 split into n x n quads, facing the camera (which looks along +z).
std::shared_ptr<const raster::Mesh> grid(int n) {
    auto mesh = std::make_shared<raster::Mesh>();
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            mesh->positions.emplace_back(-1.0F + 2.0F * static_cast<float>(i) / static_cast<float>(n),
                                         -1.0F + 2.0F * static_cast<float>(j) / static_cast<float>(n), 0.0F);
        }
    }
    mesh->normals.assign(mesh->positions.size(), {0.0F, 0.0F, -1.0F});
    const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
    const glm::vec3 behind(0.0F, 0.0F, 1.0F);
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            mesh->facets.push_back(
                raster::facet_facing_away(mesh->positions, at(i, j), at(i + 1, j), at(i + 1, j + 1), behind));
            mesh->facets.push_back(
                raster::facet_facing_away(mesh->positions, at(i, j), at(i + 1, j + 1), at(i, j + 1), behind));
        }
    }
    return mesh;
}

raster::Scene layers(int width, int height, bool blended) {
    raster::Scene scene{raster::OrthoCamera(width, height), {20, 20, 28}, {{{0.3F, 0.5F, -1.0F}}}, {}, {}};
    const auto mesh = grid(32);
    for (int k = 0; k < 8; ++k) {
        glm::mat4 model(2.0F);  // wider than the view: every pixel sees all eight
        model[3] =
            glm::vec4(0.02F * static_cast<float>(k), 0.01F * static_cast<float>(k), 0.1F * static_cast<float>(k), 1.0F);
        const float t = static_cast<float>(k) / 7.0F;
        raster::SceneObject object{mesh, model,
                                   raster::LinearMaterial{{0, 0, 0}, {t, 1.0F - t, 0.5F}, {0.2F, 0.2F, 0.2F}, 32.0F}};
        if (blended) object.opacity = {raster::AlphaMode::blend, 0.5F, 0.5F};
        scene.objects.push_back(object);
    }
    return scene;
}

double best_seconds(raster::Renderer& renderer, raster::Framebuffer& image, const raster::Scene& scene) {
    double best = 1e30;
    for (int run = 0; run < 5; ++run) {
        const auto start = std::chrono::steady_clock::now();
        renderer.render(image, scene);
        best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    return best;
}

// Three unlit squares turned about y so that each crosses the others, half transparent, over grey.
raster::Scene crossing(int size) {
    raster::Scene scene{raster::OrthoCamera(size, size), {128, 128, 128}, {}, {}, {}};
    const auto mesh = grid(4);
    const raster::LinearRgb colours[3] = {{0.9F, 0.1F, 0.1F}, {0.1F, 0.8F, 0.1F}, {0.1F, 0.2F, 0.9F}};
    for (int k = 0; k < 3; ++k) {
        const float turn = -0.8F + 0.8F * static_cast<float>(k);
        const glm::mat4 model =
            glm::scale(glm::rotate(glm::translate(glm::mat4(1.0F), glm::vec3(0.15F * static_cast<float>(k - 1),
                                                                             0.1F * static_cast<float>(k - 1),
                                                                             0.05F * static_cast<float>(k - 1))),
                                   turn, glm::vec3(0, 1, 0)),
                       glm::vec3(0.6F));
        raster::SceneObject object{mesh, model, raster::LinearMaterial{{0, 0, 0}, colours[k], {0, 0, 0}, {}},
                                   raster::ShadingMethod::unlit};
        object.opacity = {raster::AlphaMode::blend, 0.6F, 0.5F};
        scene.objects.push_back(object);
    }
    return scene;
}

struct Layer {
    std::vector<float> colour;  // straight, linear, three a pixel
    std::vector<float> alpha;
    std::vector<float> depth;  // infinite where the layer is absent
    double centre_depth;       // the object's centre, for sorting per object
};

// Each object alone over nothing at one sample: its colour, alpha and depth at every pixel.
std::vector<Layer> layers_of(const raster::Scene& scene, int w, int h) {
    std::vector<Layer> out;
    const std::array<float, 256>& linear = raster::linear_from_srgb_bytes();
    for (const raster::SceneObject& object : scene.objects) {
        raster::Scene alone = scene;
        alone.objects = {object};
        alone.keep_depth = true;
        raster::Renderer renderer;
        raster::Framebuffer image(w, h);
        renderer.render(image, alone);
        const std::vector<std::uint8_t> alpha = renderer.coverage();
        Layer layer;
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const raster::Rgb c = image.pixel(x, y);
                layer.colour.insert(layer.colour.end(), {linear[c.r], linear[c.g], linear[c.b]});
                const auto i = static_cast<std::size_t>(y * w + x);
                layer.alpha.push_back(static_cast<float>(alpha[i]) / 255.0F);
                layer.depth.push_back(renderer.depth().at(x, y));
            }
        }
        layer.centre_depth = static_cast<double>(object.model[3][2]);
        out.push_back(std::move(layer));
    }
    return out;
}

// The mean and largest difference of two linear images, three floats a pixel.
std::pair<double, double> error_of(const std::vector<float>& a, const std::vector<float>& b) {
    double sum = 0.0, most = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const double d = std::abs(static_cast<double>(a[i]) - static_cast<double>(b[i]));
        sum += d, most = std::max(most, d);
    }
    return {sum / static_cast<double>(a.size()), most};
}

void compare_methods() {
    constexpr int kSize = 256;
    const raster::Scene scene = crossing(kSize);
    raster::Framebuffer exact_image(kSize, kSize);
    raster::Renderer renderer;
    renderer.render(exact_image, scene);
    const std::array<float, 256>& linear = raster::linear_from_srgb_bytes();
    const auto pixels = static_cast<std::size_t>(kSize) * static_cast<std::size_t>(kSize);
    std::vector<float> exact(pixels * 3);
    for (std::size_t i = 0; i < pixels * 3; ++i) exact[i] = linear[exact_image.bytes()[i]];
    std::vector<Layer> layers = layers_of(scene, kSize, kSize);
    const float grey = linear[128];
    // Per-object sorting: whole objects far to near by their centres, each over the result so far.
    std::vector<std::size_t> order(layers.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(),
              [&](std::size_t a, std::size_t b) { return layers[a].centre_depth > layers[b].centre_depth; });
    std::vector<float> sorted(pixels * 3, grey), weighted(pixels * 3);
    for (const std::size_t k : order) {
        for (std::size_t i = 0; i < pixels; ++i) {
            const float a = layers[k].alpha[i];
            for (std::size_t c = 0; c < 3; ++c)
                sorted[i * 3 + c] = a * layers[k].colour[i * 3 + c] + (1.0F - a) * sorted[i * 3 + c];
        }
    }
    // Weighted blended OIT (McGuire and Bavoil 2013, their depth weight for view depths near 1).
    for (std::size_t i = 0; i < pixels; ++i) {
        double accum[4] = {0, 0, 0, 0}, revealage = 1.0;
        for (const Layer& layer : layers) {
            const double a = layer.alpha[i];
            if (a <= 0.0) continue;
            const double z = layer.depth[i];
            const double w =
                a * std::clamp(10.0 / (1e-5 + std::pow(z / 5.0, 2.0) + std::pow(z / 200.0, 6.0)), 1e-2, 3e3);
            for (std::size_t c = 0; c < 3; ++c) accum[c] += layer.colour[i * 3 + c] * a * w;
            accum[3] += a * w;
            revealage *= 1.0 - a;
        }
        for (std::size_t c = 0; c < 3; ++c) {
            const double mean = accum[3] > 0.0 ? accum[c] / accum[3] : 0.0;
            weighted[i * 3 + c] = static_cast<float>(mean * (1.0 - revealage) + grey * revealage);
        }
    }
    std::printf("method,mean_error,max_error\n");
    const auto row = [&](const char* name, const std::vector<float>& image) {
        const auto [mean, most] = error_of(image, exact);
        std::printf("%s,%.5f,%.5f\n", name, mean, most);
    };
    row("exact", exact);
    row("per_object_sorted", sorted);
    row("weighted_blended", weighted);
}

}  // namespace

int main() {
    compare_methods();
    constexpr int kWidth = 800, kHeight = 600;
    // Opaque as drawn (depth first: only the nearest layer shaded) and without the depth pass (the
    // layers come near to far, so the depth test rejects the farther ones before shading too).
    std::printf("samples,threads,opaque_ms,opaque_no_depth_pass_ms,blended_ms,ratio\n");
    for (const int samples : {1, 4}) {
        for (const int threads : {1, 2}) {
            raster::Renderer renderer({.threads = threads, .samples = samples});
            raster::Renderer no_depth_pass(
                {.threads = threads, .samples = samples, .depth_first = raster::RenderOptions::DepthFirst::never});
            raster::Framebuffer image(kWidth, kHeight);
            const double opaque = best_seconds(renderer, image, layers(kWidth, kHeight, false));
            const double shaded = best_seconds(no_depth_pass, image, layers(kWidth, kHeight, false));
            const double blended = best_seconds(renderer, image, layers(kWidth, kHeight, true));
            std::printf("%d,%d,%.2f,%.2f,%.2f,%.2f\n", samples, threads, opaque * 1e3, shaded * 1e3, blended * 1e3,
                        blended / opaque);
        }
    }
    return 0;
}
