#pragma once
// Generates the GLSL 4.30 core program of a variant from shaders/ (embedded at build time).
// The variant's defines (PX_HAS_<FEATURE>, PX_TECHNIQUE_<NAME>, only for what is on) resolve the
// #if blocks; then only the functions, structs and globals reachable from main() are kept, and
// only the uniforms and samplers that kept code reads are declared. So each variant carries
// exactly the code, samplers and uniforms it uses. Every kept snippet is preceded by
// `#line L S`, S indexing GeneratedShader::sources and L = S * 10000 + the line in that file (Mesa
// reports no source numbers, so the line carries the file too): compiler errors point at the file
// in shaders/, and mapCompilerLog() rewrites them to "shaders/FILE:LINE".

#include "parallax/Result.h"
#include "parallax/shader/VariantKey.h"

#include <string>
#include <string_view>
#include <vector>

namespace px {

// Texture units, fixed per sampler (layout(binding = N) in the generated code).
namespace TextureUnit {
inline constexpr int Height = 0;      // R16 or R32F height map, mipmapped
inline constexpr int Cone = 1;        // RG32F or RG16: height, sqrt(cone ratio)
inline constexpr int MaxMip = 2;      // R32F max-mip pyramid atlas
inline constexpr int Albedo = 3;      // linear RGBA (sRGB decoded on upload)
inline constexpr int Normal = 4;      // tangent-space normal map, +Y up
inline constexpr int Orm = 5;         // occlusion, roughness, metallic
inline constexpr int RayOrigins = 6;  // RG32F uv0 per ray (trace output)
inline constexpr int EnvSpecular = 7; // RGB float equirectangular, GGX-prefiltered per mip level
inline constexpr int SplitSum = 8;    // RG32F split-sum table (N.V, roughness)
} // namespace TextureUnit

// Levels the max-mip atlas row table holds (a 2^31 texel side would need 32).
inline constexpr int kMaxMipAtlasLevels = 32;

struct ShaderUniform {
    std::string name;
    std::string type; // GLSL type: "sampler2D", "float", "int[32]", ...
    int unit = -1;    // samplers: the texture unit
};

struct GeneratedShader {
    std::string text;
    std::vector<std::string> sources;    // #line source numbers: 0 is the generated header
    std::vector<ShaderUniform> uniforms; // declared, each read by the kept code
    std::vector<std::string> defines;    // the PX_ defines that are on
};

// What the vertex stage depends on: the trace pass or a mesh, and which of its outputs the
// fragment stage reads (sorted names, "vNormal", "vUv", ...). Programs with equal vertex keys have
// byte-identical vertex shaders.
struct VertexKey {
    bool trace = false;
    std::vector<std::string> outputs;
    // "mesh+vNormal+vPosition+vUv", "trace": the vertex shader's name.
    std::string name() const;
    friend bool operator==(const VertexKey&, const VertexKey&) = default;
    // NOLINTNEXTLINE(modernize-use-nullptr): clang-tidy 15 misreads the defaulted comparison's 0.
    friend auto operator<=>(const VertexKey&, const VertexKey&) = default;
};

struct GeneratedProgram {
    VariantKey key;
    VertexKey vertexKey;
    GeneratedShader vertex;
    GeneratedShader fragment;
};

// Fails for an invalid key (with isValid()'s sentence) or a malformed shader file (naming it and
// the line). The key is canonicalised first.
Result<GeneratedProgram> generateProgram(const VariantKey& key);

// The environment drawn behind the mesh (shaders/render/background.*.glsl), from the same files
// and bindings; its key is the default one (only named in errors).
Result<GeneratedProgram> generateBackgroundProgram();

// The compute program of a cone bake: the kernels of shaders/bake/ (the ones the CPU bakers
// compile as C++), the GPU's bindings (shaders/bake/gpu/bindings.glsl) and the kind's main(), only
// what main() reaches, `precise` kept (the GPU rounds as the CPU does). kBakeLocalSize invocations
// a work group (or `localSize`): one per 4 x 4 tile (relaxed) or per texel (quick).
enum class BakeShaderKind { Quick, Relaxed };
inline constexpr int kBakeLocalSize = 64;
Result<GeneratedShader> generateBakeShader(BakeShaderKind kind, WrapMode wrap,
                                           int localSize = kBakeLocalSize);

// Rewrites the "SOURCE:LINE" / "SOURCE(LINE)" positions of a GLSL compiler log (Mesa, glslang,
// NVIDIA) into "shaders/FILE:LINE".
std::string mapCompilerLog(std::string_view log, const std::vector<std::string>& sources);

} // namespace px
