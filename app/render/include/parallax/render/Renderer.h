#pragma once
// The renderer the editor and the command line share. It owns the per-context GL state (meshes,
// compiled variants) and draws one material on one mesh into the bound framebuffer.
//
// Editor use: one Renderer per QOpenGLWidget context, created in initializeGL(); several views
// share one OrbitCamera and DirectionalLight and each passes its own Material copy (technique,
// quality, shadow, normal source, lighting: the per-view settings) to draw() in paintGL(). Every
// parameter is a uniform, set on each draw: moving a slider never recompiles; only a new feature
// set compiles a new variant, once (ShaderCache). renderImage() draws offscreen and reads the
// frame back.

#include "parallax/material/Material.h"
#include "parallax/render/Camera.h"
#include "parallax/render/GlInfo.h"
#include "parallax/render/GpuEnvironment.h"
#include "parallax/render/GpuMaterial.h"
#include "parallax/render/Mesh.h"
#include "parallax/render/RenderTarget.h"
#include "parallax/render/ShaderCache.h"

#include <glm/vec4.hpp>
#include <map>
#include <memory>
#include <optional>

namespace px {

struct DrawOptions {
    MeshKind mesh = MeshKind::Plane;
    // A loaded mesh (parallax/mesh/MeshLoader.h) drawn instead of `mesh` when set; uploaded on
    // first use and kept while this pointer is the one drawn.
    std::shared_ptr<const MeshData> customMesh;
    TbnSource tbn = TbnSource::VertexTangents;
    ShaderOutput output = ShaderOutput::Color; // Color, Surface or FootprintSurface (hit data)
    // Production: the texture units filter, as an engine's shader would; Verify: the kernels
    // that match the CPU to the bit.
    KernelFlavour kernels = KernelFlavour::Production;
    // Cleared to before drawing, as stored (the colour output is sRGB-encoded); alpha 0 leaves the
    // background transparent. The Surface output always clears to -1 (t = -1: no surface); a
    // surface seen more than 89 degrees from its normal has t = -2 (surface.frag.glsl).
    glm::vec4 background{0.0f};
    bool clear = true;
    glm::vec3 baseColor{1.0f}; // multiplies the albedo map (the colour when there is none)
    glm::mat4 model{1.0f};
    // Image-based light (docs/lighting.md): with an environment the colour output is lit by it
    // instead of the constant ambient, the light stays as the sun, and the result is exposed by
    // `exposure` stops and tone-mapped; `showEnvironment` draws it behind the mesh instead of
    // `background`.
    const GpuEnvironment* environment = nullptr;
    float exposure = 0.0f;
    bool showEnvironment = false;
};

class Renderer {
public:
    // Needs a current OpenGL 4.3 context; the error names what the context offers otherwise.
    // `shaders`: a cache shared with the renderers of contexts sharing this one's objects (an
    // editor's views), so each variant compiles once for all of them; null: one of its own.
    static Result<std::unique_ptr<Renderer>> create(std::shared_ptr<ShaderCache> shaders = nullptr);

    // The variant this material and these options draw with, given the maps `gpu` has.
    VariantKey variantFor(const GpuMaterial& gpu, const Material& material,
                          const DrawOptions& options) const;

    // Draws into the bound draw framebuffer over the viewport (0, 0, size). Prepares the derived
    // maps the technique reads (baking them if missing) and compiles the variant on first use.
    Status draw(GpuMaterial& gpu, const Material& material, const OrbitCamera& camera,
                const DirectionalLight& light, const DrawOptions& options, glm::ivec2 size);

    // Renders offscreen and reads the result back (top row first): sRGB-encoded RGBA for Color,
    // (u, v, t, fetches) floats for Surface.
    Result<Image> renderImage(GpuMaterial& gpu, const Material& material, const OrbitCamera& camera,
                              const DirectionalLight& light, const DrawOptions& options,
                              glm::ivec2 size);

    ShaderCache& shaders() { return *m_shaders; }
    const GlInfo& glInfo() const { return m_info; }

private:
    Renderer() = default;
    const GpuMesh& mesh(const DrawOptions& options);
    Status drawBackground(const GpuEnvironment& environment, const OrbitCamera& camera,
                          float exposure, float aspect);

    GlInfo m_info;
    std::shared_ptr<ShaderCache> m_shaders;
    std::map<MeshKind, GpuMesh> m_meshes;
    std::shared_ptr<const MeshData> m_customSource; // what m_custom holds
    GpuMesh m_custom;
    std::optional<ShaderProgram> m_background;
    gl::Object m_emptyVertexArray; // core profile draws need one bound
};

} // namespace px
