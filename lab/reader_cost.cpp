// reader-cost: what reading a model in a child process costs against reading it in this one.
// Writes a 700 x 700 grid (977,202 triangles) as binary PLY and as OBJ in a temporary
// directory, then loads each file in a fresh process, in the child and in the process in turn,
// as `render` does once per run; prints the medians and spreads.
#include <raster/io/model.hpp>
#include <raster/io/model_file.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>
#include <sys/wait.h>
#include <unistd.h>

namespace {

constexpr int kSide = 700;

float height(int i, int j) {
    return 0.1F * std::sin(static_cast<float>(i) * 0.05F) * std::cos(static_cast<float>(j) * 0.05F);
}

void write_grid(const std::filesystem::path& dir) {
    const int faces = 2 * (kSide - 1) * (kSide - 1);
    std::ofstream ply(dir / "grid.ply", std::ios::binary);
    ply << "ply\nformat binary_little_endian 1.0\nelement vertex " << kSide * kSide
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face " << faces
        << "\nproperty list uchar int vertex_indices\nend_header\n";
    std::ofstream obj(dir / "grid.obj");
    for (int j = 0; j < kSide; ++j) {
        for (int i = 0; i < kSide; ++i) {
            const float p[3] = {static_cast<float>(i) / kSide, static_cast<float>(j) / kSide, height(i, j)};
            ply.write(reinterpret_cast<const char*>(p), sizeof p);
            obj << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
        }
    }
    for (int j = 0; j + 1 < kSide; ++j) {
        for (int i = 0; i + 1 < kSide; ++i) {
            const int a = j * kSide + i;
            for (const std::array<int, 3>& t :
                 {std::array<int, 3>{a, a + 1, a + kSide}, std::array<int, 3>{a + 1, a + kSide + 1, a + kSide}}) {
                ply.put(3);
                ply.write(reinterpret_cast<const char*>(t.data()), sizeof t);
                obj << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
            }
        }
    }
}

// Seconds one load takes in a fresh process of this program (`--once child|here FILE`).
double fresh_load(const std::string& how, const std::filesystem::path& file) {
    std::FILE* out = ::popen(("exec " + std::filesystem::read_symlink("/proc/self/exe").string() + " --once " + how +
                              " '" + file.string() + "'")
                                 .c_str(),
                             "r");
    double seconds = -1.0;
    if (out == nullptr || std::fscanf(out, "%lf", &seconds) != 1) seconds = -1.0;
    if (out != nullptr) ::pclose(out);
    if (seconds < 0.0) throw std::runtime_error("reader-cost: the load of " + file.string() + " failed");
    return seconds;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc == 4 && std::strcmp(argv[1], "--once") == 0) {
        raster::ObjOptions options;
        options.limits.separate_process = std::strcmp(argv[2], "child") == 0;
        const auto start = std::chrono::steady_clock::now();
        const raster::Model model = raster::read_model(argv[3], options);
        std::printf("%.4f %zu\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                    raster::triangle_count(model));
        return 0;
    }
    const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("raster-reader-cost-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    write_grid(dir);
    std::printf("| file | in the child, s | in the process, s | cost |\n|---|---:|---:|---:|\n");
    for (const char* name : {"grid.ply", "grid.obj"}) {
        std::vector<double> child, here;
        for (int r = 0; r < rounds; ++r) {  // interleaved, so that a noisy moment hits both
            child.push_back(fresh_load("child", dir / name));
            here.push_back(fresh_load("here", dir / name));
        }
        std::sort(child.begin(), child.end());
        std::sort(here.begin(), here.end());
        const double c = child[child.size() / 2], h = here[here.size() / 2];
        std::printf("| `%s` | %.3f (%.3f-%.3f) | %.3f (%.3f-%.3f) | %+.0f %% |\n", name, c, child.front(), child.back(),
                    h, here.front(), here.back(), 100.0 * (c / h - 1.0));
    }
    std::filesystem::remove_all(dir);
}
