// Writes the mesh bake's benchmark input: a sculpted tile as a binary little-endian PLY of about
// N triangles (default 2M): a periodic ground of waves with domes on it, an (n + 1)² vertex grid
// with normals, so the file is what a sculpting tool exports. Used by mesh-bake-report.sh.
//
//   parallax-bench-make-mesh-tile OUT.ply [TRIANGLES]

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The relief over the unit tile, periodic in x and y, and its gradient.
double relief(double x, double y, double& dx, double& dy) {
    double z = 0.04 * std::sin(kTwoPi * 3 * x) * std::cos(kTwoPi * 2 * y);
    dx = 0.04 * kTwoPi * 3 * std::cos(kTwoPi * 3 * x) * std::cos(kTwoPi * 2 * y);
    dy = -0.04 * kTwoPi * 2 * std::sin(kTwoPi * 3 * x) * std::sin(kTwoPi * 2 * y);
    // Domes, two of them across the tile's edges (the wrap's distance).
    const double domes[4][3] = {
        {0.3, 0.4, 0.15}, {0.95, 0.7, 0.12}, {0.6, 0.02, 0.1}, {0.7, 0.6, 0.08}};
    for (const auto& d : domes) {
        double ox = x - d[0], oy = y - d[1];
        ox -= std::round(ox);
        oy -= std::round(oy);
        const double q = d[2] * d[2] - ox * ox - oy * oy;
        if (q > 0) {
            const double h = std::sqrt(q) * 0.6;
            if (h > 0) {
                z += h;
                dx += -0.6 * ox / std::sqrt(q);
                dy += -0.6 * oy / std::sqrt(q);
            }
        }
    }
    return z;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fprintf(stderr, "usage: parallax-bench-make-mesh-tile OUT.ply [TRIANGLES]\n");
        return 2;
    }
    const double triangles = argc > 2 ? std::atof(argv[2]) : 2e6;
    const int n = static_cast<int>(std::lround(std::sqrt(triangles / 2)));
    std::FILE* out = std::fopen(argv[1], "wb");
    if (out == nullptr) {
        std::perror(argv[1]);
        return 1;
    }
    const std::size_t vertices = static_cast<std::size_t>(n + 1) * (n + 1);
    const std::size_t faces = 2 * static_cast<std::size_t>(n) * n;
    std::fprintf(out,
                 "ply\nformat binary_little_endian 1.0\nelement vertex %zu\nproperty float x\n"
                 "property float y\nproperty float z\nproperty float nx\nproperty float ny\n"
                 "property float nz\nelement face %zu\nproperty list uchar int vertex_indices\n"
                 "end_header\n",
                 vertices, faces);
    std::vector<float> row(static_cast<std::size_t>(n + 1) * 6);
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            const double x = static_cast<double>(i) / n, y = static_cast<double>(j) / n;
            double dx = 0, dy = 0;
            const double z = relief(x, y, dx, dy);
            const double len = std::sqrt(dx * dx + dy * dy + 1);
            float* v = &row[static_cast<std::size_t>(i) * 6];
            v[0] = static_cast<float>(x);
            v[1] = static_cast<float>(y);
            v[2] = static_cast<float>(z);
            v[3] = static_cast<float>(-dx / len);
            v[4] = static_cast<float>(-dy / len);
            v[5] = static_cast<float>(1 / len);
        }
        std::fwrite(row.data(), sizeof(float), row.size(), out);
    }
    std::vector<unsigned char> face(13 * 2 * static_cast<std::size_t>(n));
    for (int j = 0; j < n; ++j) {
        unsigned char* f = face.data();
        for (int i = 0; i < n; ++i) {
            const auto v = static_cast<std::int32_t>(j * (n + 1) + i), r = n + 1;
            const std::int32_t tris[2][3] = {{v, v + 1, v + r + 1}, {v, v + r + 1, v + r}};
            for (const auto& t : tris) {
                *f++ = 3;
                for (std::int32_t k : t) {
                    std::memcpy(f, &k, 4);
                    f += 4;
                }
            }
        }
        std::fwrite(face.data(), 1, face.size(), out);
    }
    if (std::fclose(out) != 0) {
        std::perror(argv[1]);
        return 1;
    }
    std::printf("%s: %zu triangles, %zu vertices\n", argv[1], faces, vertices);
    return 0;
}
