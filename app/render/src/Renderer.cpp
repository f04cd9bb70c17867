#include "parallax/render/Renderer.h"

#include "parallax/material/SurfaceFactors.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <glm/gtc/matrix_inverse.hpp>

namespace px {

Result<std::unique_ptr<Renderer>> Renderer::create(std::shared_ptr<ShaderCache> shaders) {
    std::unique_ptr<Renderer> r(new Renderer);
    r->m_shaders = shaders ? std::move(shaders) : std::make_shared<ShaderCache>();
    r->m_info = currentGlInfo();
    if (Status s = requireGl43(r->m_info); !s)
        return s.error();
    return r;
}

const GpuMesh& Renderer::mesh(const DrawOptions& o) {
    if (o.customMesh) {
        // Holding the source keeps its address from being reused by another mesh.
        if (m_customSource != o.customMesh) {
            m_custom = GpuMesh::upload(*o.customMesh);
            m_customSource = o.customMesh;
        }
        return m_custom;
    }
    auto it = m_meshes.find(o.mesh);
    if (it == m_meshes.end())
        it = m_meshes.emplace(o.mesh, GpuMesh::upload(makeMesh(o.mesh))).first;
    return it->second;
}

VariantKey Renderer::variantFor(const GpuMaterial& gpu, const Material& m,
                                const DrawOptions& o) const {
    VariantKey k;
    k.technique = m.technique;
    k.shadow = m.selfShadow;
    k.normalSource = m.normalSource;
    if (k.normalSource == NormalSource::Map && !gpu.hasNormalMap())
        k.normalSource = NormalSource::HeightCentral;
    if (k.normalSource != NormalSource::Map && !gpu.hasHeight())
        k.normalSource = gpu.hasNormalMap() ? NormalSource::Map : NormalSource::None;
    if (k.technique == Technique::Normal && k.normalSource == NormalSource::None)
        k.technique = Technique::None; // nothing to map normals from
    k.albedoMap = gpu.hasAlbedo();
    k.surfaceMap = gpu.hasSurfaceMap();
    k.wrap = gpu.wrap();
    k.lighting = m.lighting;
    k.tbn = o.tbn;
    k.output = o.output == ShaderOutput::Trace ? ShaderOutput::Color : o.output;
    k.flavour = o.kernels;
    k.environment = o.environment != nullptr;
    return canonical(k);
}

Status Renderer::draw(GpuMaterial& gpu, const Material& m, const OrbitCamera& camera,
                      const DirectionalLight& light, const DrawOptions& o, glm::ivec2 size) {
    if (gpu.wrap() != m.wrap)
        gpu.setWrap(m.wrap);
    const VariantKey key = variantFor(gpu, m, o);
    if (Status s = gpu.prepare(key.technique); !s)
        return s;
    Result<const ShaderProgram*> program = m_shaders->program(key);
    if (!program)
        return program.error();
    const ShaderProgram& p = **program;

    const float aspect =
        size.y > 0 ? static_cast<float>(size.x) / static_cast<float>(size.y) : 1.0f;
    p.set("pxModel", o.model);
    p.set("pxNormalMatrix", glm::inverseTranspose(glm::mat3(o.model)));
    p.set("pxViewProjection", camera.projection(aspect) * camera.view());
    p.set("pxTiling", glm::vec2(m.tiling));
    p.set("pxCameraPos", camera.position());
    p.set("pxLightDir", light.direction());
    p.set("pxLightColor", light.color);
    p.set("pxAmbient", light.ambient);
    p.set("pxScale", m.heightScale);
    p.set("pxMinLayers", m.params.minLayers);
    p.set("pxMaxLayers", m.params.maxLayers);
    p.set("pxRefineSteps", refineSteps(key.technique, m.params));
    p.set("pxMaxSteps", m.params.maxSteps);
    p.set("pxBaseColor", o.baseColor);
    p.set("pxSpecular", m.specular);
    p.set("pxShininess", m.shininess);
    const SurfaceFactors surface = surfaceFactors(m, gpu.hasRoughnessMap(), gpu.hasMetallicMap());
    p.set("pxRoughness", surface.roughness);
    p.set("pxMetallic", surface.metallic);
    p.set("pxShadowSoftness", m.shadowSoftness);
    p.set("pxNormalGreenSign", m.normalGreen == NormalGreen::DirectX ? -1.0f : 1.0f);
    p.set("pxExposure", o.exposure);
    gpu.bind(p);
    if (key.environment)
        o.environment->bind(p);

    glViewport(0, 0, size.x, size.y);
    if (o.clear) {
        const glm::vec4 c = key.output != ShaderOutput::Color ? glm::vec4(-1.0f) : o.background;
        glClearColor(c.r, c.g, c.b, c.a);
        glClearDepth(1.0);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
    if (o.environment && o.showEnvironment && key.output == ShaderOutput::Color) {
        if (Status s = drawBackground(*o.environment, camera, o.exposure, aspect); !s)
            return s;
    }
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glDisable(GL_BLEND);
    p.use();
    mesh(o).draw();
    glUseProgram(0);
    return checkGlError("drawing " + key.name());
}

Status Renderer::drawBackground(const GpuEnvironment& environment, const OrbitCamera& camera,
                                float exposure, float aspect) {
    if (!m_background) {
        Result<GeneratedProgram> generated = generateBackgroundProgram();
        if (!generated)
            return generated.error();
        Result<ShaderProgram> built = ShaderProgram::build(*generated);
        if (!built)
            return built.error();
        m_background = std::move(*built);
        m_emptyVertexArray = gl::Object(gl::ObjectKind::VertexArray);
    }
    const ShaderProgram& p = *m_background;
    p.set("pxInverseViewProjection", glm::inverse(camera.projection(aspect) * camera.view()));
    p.set("pxCameraPos", camera.position());
    p.set("pxExposure", exposure);
    environment.bind(p);
    // Behind everything: no depth written, the mesh draws over it.
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    p.use();
    glBindVertexArray(m_emptyVertexArray.id());
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
    return checkGlError("drawing the environment");
}

Result<Image> Renderer::renderImage(GpuMaterial& gpu, const Material& m, const OrbitCamera& camera,
                                    const DirectionalLight& light, const DrawOptions& o,
                                    glm::ivec2 size) {
    Result<RenderTarget> target = RenderTarget::create(
        size, o.output != ShaderOutput::Color ? TargetFormat::Rgba32F : TargetFormat::Rgba8);
    if (!target)
        return target.error();
    target->bind();
    Status s = draw(gpu, m, camera, light, o, size);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (!s)
        return s.error();
    return target->read();
}

} // namespace px
