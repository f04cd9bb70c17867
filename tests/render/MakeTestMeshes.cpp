// Writes the meshes the render command's tests read (tests/support/TestMeshes.h) into a folder,
// with an equirectangular environment (the built-in sky as an EXR) and a square EXR that is not
// one: make-test-meshes DIR.

#include "TestMeshes.h"
#include "parallax/image/ImageFile.h"
#include "parallax/light/Environment.h"

#include <cstdio>
#include <limits>
#include <string>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: make-test-meshes DIR\n");
        return 2;
    }
    using namespace px::test;
    const std::string dir = std::string(argv[1]) + "/";
    TestMesh noUv = torus(16, 8, false);
    noUv.uvs.clear();
    TestMesh nan = torus(16, 8, false);
    nan.positions[3].x = std::numeric_limits<float>::quiet_NaN();
    TestMesh twoSets = torus(16, 8, false);
    for (const glm::vec2& uv : twoSets.uvs)
        twoSets.uvs2.push_back(2.0f * uv);
    const bool ok = writeObj(dir + "torus.obj", torus(32, 16, false)) &&
                    writeObj(dir + "torus-fine.obj", torus(128, 64, false)) && // README picture
                    writeGltf(dir + "torus-tangents.gltf", torus(32, 16, true)) &&
                    writeGltf(dir + "two-sets.glb", twoSets) &&
                    writeGltf(dir + "sphere-seamed.glb", seamedSphere(32, 16)) &&
                    writeObj(dir + "no-uv.obj", noUv) && writeObj(dir + "nan.obj", nan) &&
                    writeObj(dir + "degenerate.obj", withDegenerateTriangles(torus(16, 8, false)));
    px::ImageWriteOptions exr;
    exr.format = px::PixelFormat::Half;
    const bool images =
        px::writeImage(dir + "sky.exr", px::makeSkyEnvironment({0.6f, 0.5f, 0.6f}, 64), exr).ok() &&
        px::writeImage(dir + "square.exr", px::Image(32, 32, 3), exr).ok();
    if (!ok || !images) {
        std::fprintf(stderr, "cannot write the meshes into %s\n", argv[1]);
        return 1;
    }
    return 0;
}
