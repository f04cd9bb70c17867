#include "parallax/render/GpuMaterial.h"

#include "parallax/bake/ConeMapBaker.h"
#include "parallax/render/TextureUpload.h"
#include "parallax/shader/ShaderGenerator.h"

#include <GL/gl.h>
#include <GL/glext.h>

namespace px {

Result<std::unique_ptr<GpuMaterial>> GpuMaterial::create(const MaterialAssets& assets,
                                                         WrapMode wrap) {
    std::unique_ptr<GpuMaterial> m(new GpuMaterial);
    m->m_wrap = wrap;
    if (!assets.height.empty()) {
        m->m_field = assets.height;
        m->m_heightMax = assets.height.maxHeight();
        m->m_height16 = gl::fitsR16(assets.height);
        Result<gl::Object> t = gl::uploadHeight(
            assets.height, m->m_height16 ? gl::HeightFormat::R16 : gl::HeightFormat::R32F);
        if (!t)
            return t.error();
        m->m_height = std::move(*t);
    }
    if (!assets.albedo.empty()) {
        Result<gl::Object> t = gl::uploadAlbedo(assets.albedo);
        if (!t)
            return t.error();
        m->m_albedo = std::move(*t);
    }
    if (!assets.normal.empty()) {
        Result<gl::Object> t = gl::uploadNormalMap(assets.normal);
        if (!t)
            return t.error();
        m->m_normal = std::move(*t);
    }
    if (!assets.ao.empty() || !assets.roughness.empty() || !assets.metallic.empty()) {
        auto present = [](const Image& i) { return i.empty() ? nullptr : &i; };
        Result<gl::Object> t =
            gl::uploadOrm(present(assets.ao), present(assets.roughness), present(assets.metallic));
        if (!t)
            return t.error();
        m->m_orm = std::move(*t);
    }
    if (!assets.cone.sqrtRatio.empty())
        m->m_coneCpu = assets.cone;
    if (!assets.relaxedCone.sqrtRatio.empty())
        m->m_relaxedCpu = assets.relaxedCone;
    m->setWrap(wrap); // sampler state (the wrap is already m_wrap: nothing is invalidated)
    return m;
}

void GpuMaterial::setWrap(WrapMode wrap) {
    if (wrap != m_wrap) {
        m_coneCpu.reset();
        m_relaxedCpu.reset();
        m_pyramidCpu.reset();
        m_cone.reset();
        m_relaxed.reset();
        m_atlas.reset();
    }
    m_wrap = wrap;
    if (m_height)
        gl::setWrap(m_height, wrap);
    for (const gl::Object* t : {&m_albedo, &m_normal, &m_orm}) {
        if (*t)
            gl::setFilteredSampling(*t, wrap);
    }
}

bool GpuMaterial::ready(Technique technique) const {
    const TechniqueInfo& ti = info(technique);
    if (ti.parallax && !m_height)
        return false;
    return (!ti.needsConeMap || m_cone) && (!ti.needsRelaxedConeMap || m_relaxed) &&
           (!ti.needsPyramid || m_atlas);
}

Status GpuMaterial::prepare(Technique technique) {
    const TechniqueInfo& ti = info(technique);
    if ((ti.parallax || ti.needsConeMap || ti.needsPyramid) && !m_height)
        return Error{"the " + std::string(ti.name) + " technique needs a height map"};
    auto cone = [&](ConeKind kind, std::optional<ConeMap>& cpu, gl::Object& gpu) -> Status {
        if (gpu)
            return success();
        if (!cpu) {
            cpu = bakeConeMap(m_field, m_wrap, kind);
            ++m_bakes;
        }
        Result<gl::Object> t = gl::uploadConeMap(m_field, *cpu);
        if (!t)
            return t.error();
        gl::setWrap(*t, m_wrap);
        gpu = std::move(*t);
        return success();
    };
    if (ti.needsConeMap) {
        if (Status s = cone(ConeKind::Conservative, m_coneCpu, m_cone); !s)
            return s;
    }
    if (ti.needsRelaxedConeMap) {
        if (Status s = cone(ConeKind::Relaxed, m_relaxedCpu, m_relaxed); !s)
            return s;
    }
    if (ti.needsPyramid && !m_atlas) {
        if (!m_pyramidCpu) {
            m_pyramidCpu = MaxMipPyramid::build(m_field, m_wrap);
            ++m_bakes;
        }
        if (m_pyramidCpu->levels() > kMaxMipAtlasLevels)
            return Error{"the max-mip pyramid has more levels than the shader's table holds"};
        Result<gl::Object> t = gl::uploadMaxMipAtlas(*m_pyramidCpu, m_atlasRows);
        if (!t)
            return t.error();
        m_atlas = std::move(*t);
        m_atlasTop = m_pyramidCpu->top();
    }
    return success();
}

void GpuMaterial::setConeMap(const ConeMap& cones) {
    if (cones.kind == ConeKind::Conservative) {
        m_coneCpu = cones;
        m_cone.reset();
    } else {
        m_relaxedCpu = cones;
        m_relaxed.reset();
    }
}

void GpuMaterial::setPyramid(const MaxMipPyramid& pyramid) {
    m_pyramidCpu = pyramid;
    m_atlas.reset();
}

void GpuMaterial::bind(const ShaderProgram& program) const {
    auto unit = [](int u, const gl::Object& t) {
        if (!t)
            return;
        glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(u));
        glBindTexture(GL_TEXTURE_2D, t.id());
    };
    unit(TextureUnit::Height, m_height);
    const Technique t = program.key().technique;
    unit(TextureUnit::Cone, t == Technique::RelaxedCone ? m_relaxed : m_cone);
    unit(TextureUnit::MaxMip, m_atlas);
    unit(TextureUnit::Albedo, m_albedo);
    unit(TextureUnit::Normal, m_normal);
    unit(TextureUnit::Orm, m_orm);
    glActiveTexture(GL_TEXTURE0);
    program.set("pxHeightMax", m_heightMax);
    program.set("pxMaxMipTop", m_atlasTop);
    if (!m_atlasRows.empty())
        program.set("pxMaxMipRows", std::span<const int>(m_atlasRows));
}

} // namespace px
