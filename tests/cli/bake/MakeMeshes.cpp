// Writes the mesh bake's command-line inputs into the folder named (tests/cli/bake): one sculpted
// tile (a periodic ground with a dome across its right edge) as OBJ, binary PLY, a Y-up glTF and
// ASCII STL; broken files (a truncated PLY, an OBJ whose material library lies outside its folder);
// and keep.png with a twin in two folders of their own (what failed bakes must leave alone).

#include "BakeTiles.h"
#include "parallax/image/ImageFile.h"

#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace px;

namespace {

bool writeStl(const std::string& path, const test::TestMesh& m) {
    std::ofstream out(path);
    out << "solid tile\n";
    for (std::size_t i = 0; i + 2 < m.indices.size(); i += 3) {
        out << "facet normal 0 0 1\nouter loop\n";
        for (int k = 0; k < 3; ++k) {
            const glm::vec3& p = m.positions[m.indices[i + k]];
            out << "vertex " << p.x << " " << p.y << " " << p.z << "\n";
        }
        out << "endloop\nendfacet\n";
    }
    out << "endsolid tile\n";
    return static_cast<bool>(out);
}

bool writeText(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
    return static_cast<bool>(out);
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: px-make-bake-meshes FOLDER\n");
        return 2;
    }
    namespace fs = std::filesystem;
    const fs::path dir = argv[1];
    fs::create_directories(dir);
    const test::TileRect t{0, 0, 2, 1};
    test::TestMesh m = test::periodicGround(t, 64, 0.15, 0.7);
    test::append(m, test::dome({1.9, 0.5, 0.0}, 0.3, 48, 16));
    bool ok = test::writeObj((dir / "tile.obj").string(), m) &&
              test::writePlyBinary((dir / "tile.ply").string(), m) &&
              test::writeGltf((dir / "tile-yup.gltf").string(), test::toYUp(m)) &&
              writeStl((dir / "tile.stl").string(), test::flatGround(t, 4, 0.1));
    // A binary PLY cut short: its header promises more faces than it holds.
    test::writePlyBinary((dir / "truncated.ply").string(), m);
    fs::resize_file(dir / "truncated.ply", fs::file_size(dir / "truncated.ply") - 100);
    // An OBJ that names a material library outside its folder.
    fs::create_directories(dir / "inner");
    ok = ok && writeText((dir / "outside.mtl").string(), "newmtl m\nKd 1 1 1\n") &&
         writeText((dir / "inner" / "escape.obj").string(),
                   "mtllib ../outside.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n") &&
         writeText((dir / "empty.obj").string(), "# nothing\n");
    Image keep(4, 4, 1);
    for (int i = 0; i < 16; ++i)
        keep.pixels[static_cast<std::size_t>(i)] = static_cast<float>(i) / 15.0f;
    ImageWriteOptions png;
    png.format = PixelFormat::UInt16;
    for (const char* folder : {"fail", "interrupt"}) {
        fs::create_directories(dir / folder);
        ok = ok && writeImage((dir / folder / "keep.png").string(), keep, png) &&
             writeImage((dir / folder / "keep-twin.png").string(), keep, png);
    }
    if (!ok) {
        std::fprintf(stderr, "px-make-bake-meshes: could not write into %s\n", argv[1]);
        return 1;
    }
    return 0;
}
