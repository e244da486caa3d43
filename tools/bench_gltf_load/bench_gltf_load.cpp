// bench_gltf_load FILE [REPEATS]: times loadGltfScene (parse, checks, flattening into world space,
// tangent generation, image decoding; no GL) and prints each run and the median. A benchmark, not
// a test: `make bench-gltf` runs it on a generated scene of about one million triangles.
#include "t10/error.hpp"
#include "t10/gltf_scene.hpp"
#include "t10/stats.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    if (argc < 2 || argc > 3) {
        std::cerr << "usage: bench_gltf_load FILE.gltf|FILE.glb [REPEATS]\n";
        return 2;
    }
    const int repeats = argc == 3 ? std::max(1, std::stoi(argv[2])) : 3;
    std::vector<double> times;
    try {
        for (int i = 0; i < repeats; ++i) {
            const auto start = std::chrono::steady_clock::now();
            const t10::SceneDescription scene = t10::loadGltfScene(argv[1]);
            const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
            times.push_back(ms);
            std::cout << "load " << i + 1 << ": " << ms << " ms, " << scene.triangleCount << " triangles, "
                      << scene.vertexCount << " vertices\n";
        }
    } catch (const t10::Error& error) {
        std::cerr << "bench_gltf_load: " << error.what() << "\n";
        return 1;
    }
    std::cout << "median load time: " << t10::median(times) << " ms (" << argv[1] << ")\n";
    return 0;
}
