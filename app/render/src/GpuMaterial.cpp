#include "parallax/render/GpuMaterial.h"

#include "parallax/bake/ConeMapBaker.h"
#include "parallax/bake/ConeMapFinish.h"
#include "parallax/render/TextureUpload.h"
#include "parallax/shader/ShaderGenerator.h"

#include <GL/gl.h>
#include <GL/glext.h>

namespace px {

namespace {

// The same map, not an equal one: the same size and the very same texels in memory.
bool same(const Image& a, const Image& b) {
    if (a.empty() || b.empty())
        return a.empty() && b.empty();
    return a.width == b.width && a.height == b.height && a.channels == b.channels &&
           a.pixels.sharesWith(b.pixels);
}

bool same(const HeightField& a, const HeightField& b) {
    return !a.empty() && a.width == b.width && a.height == b.height &&
           a.texels.sharesWith(b.texels);
}

bool same(const ConeMap& a, const std::optional<ConeMap>& b) {
    return b && !a.sqrtRatio.empty() && a.kind == b->kind && a.width == b->width &&
           a.height == b->height && a.sqrtRatio.sharesWith(b->sqrtRatio);
}

} // namespace

Result<std::unique_ptr<GpuMaterial>>
GpuMaterial::create(const MaterialAssets& assets, WrapMode wrap, const GpuMaterial* previous) {
    std::unique_ptr<GpuMaterial> m(new GpuMaterial);
    m->m_wrap = wrap;
    if (previous && previous->m_wrap != wrap)
        previous = nullptr; // its textures sample with another wrap
    if (Status s = m->uploadMaps(assets, previous); !s)
        return s.error();
    m->setWrap(wrap); // sampler state (the wrap is already m_wrap: nothing is invalidated)
    return m;
}

GpuMaterial::Kept GpuMaterial::kept(const MaterialAssets& assets, const GpuMaterial* previous) {
    Kept k;
    if (!previous)
        return k;
    const GpuMaterial& p = *previous;
    k.height = same(assets.height, p.m_field);
    k.albedo = same(assets.albedo, p.m_albedoMap);
    k.normal = same(assets.normal, p.m_normalMap);
    k.orm = same(assets.ao, p.m_aoMap) && same(assets.roughness, p.m_roughnessMap) &&
            same(assets.metallic, p.m_metallicMap);
    k.cone = k.height && same(assets.cone, p.m_coneCpu);
    k.relaxedCone = k.height && same(assets.relaxedCone, p.m_relaxedCpu);
    k.pyramid = k.height && p.m_pyramidCpu;
    return k;
}

std::size_t GpuMaterial::texelsToUpload(const MaterialAssets& assets, WrapMode wrap,
                                        const GpuMaterial* previous,
                                        std::span<const Technique> techniques) {
    if (previous && previous->m_wrap != wrap)
        previous = nullptr;
    const Kept k = kept(assets, previous);
    auto texels = [](const auto& map) { return std::size_t(map.width) * std::size_t(map.height); };
    std::size_t n = 0;
    n += k.height ? 0 : texels(assets.height);
    n += k.albedo || assets.albedo.empty() ? 0 : texels(assets.albedo);
    n += k.normal || assets.normal.empty() ? 0 : texels(assets.normal);
    if (!k.orm) // packed at the size of the largest of the three
        n += std::max({texels(assets.ao), texels(assets.roughness), texels(assets.metallic)});
    // The derived maps the techniques read, where `previous` has no texture of the same ones.
    for (Technique t : techniques) {
        const TechniqueInfo& ti = info(t);
        if ((ti.needsConeMap && !(k.cone && previous->m_cone)) ||
            (ti.needsRelaxedConeMap && !(k.relaxedCone && previous->m_relaxed)) ||
            (ti.needsPyramid && !(k.pyramid && previous->m_atlas)))
            n += texels(assets.height);
    }
    return n;
}

Status GpuMaterial::uploadMaps(const MaterialAssets& assets, const GpuMaterial* previous) {
    const Kept k = kept(assets, previous);
    // Takes `from` (previous's texture of the same map) if there is one, else uploads.
    auto take = [this](Texture& to, const Texture& from, const auto& upload) -> Status {
        if (from) {
            to = from;
            return success();
        }
        Result<gl::Object> t = upload();
        if (!t)
            return t.error();
        to = std::make_shared<const gl::Object>(std::move(*t));
        ++m_uploads;
        return success();
    };
    const Texture none;
    if (!assets.height.empty()) {
        m_field = assets.height;
        m_heightMax = k.height ? previous->m_heightMax : assets.height.maxHeight();
        m_height16 = k.height ? previous->m_height16 : gl::fitsR16(assets.height);
        const gl::HeightFormat format = m_height16 ? gl::HeightFormat::R16 : gl::HeightFormat::R32F;
        if (Status s = take(m_height, k.height ? previous->m_height : none,
                            [&] { return gl::uploadHeight(assets.height, format); });
            !s)
            return s;
    }
    // A colour map: kept (for the next material to compare) and on the GPU.
    auto image = [&](Texture& to, Image& source, const Image& map, bool same, const Texture& from,
                     const auto& upload) -> Status {
        if (map.empty())
            return success();
        source = map;
        return take(to, same ? from : none, upload);
    };
    if (Status s = image(m_albedo, m_albedoMap, assets.albedo, k.albedo,
                         previous ? previous->m_albedo : none,
                         [&] { return gl::uploadAlbedo(assets.albedo); });
        !s)
        return s;
    if (Status s = image(m_normal, m_normalMap, assets.normal, k.normal,
                         previous ? previous->m_normal : none,
                         [&] { return gl::uploadNormalMap(assets.normal); });
        !s)
        return s;
    if (!assets.ao.empty() || !assets.roughness.empty() || !assets.metallic.empty()) {
        m_aoMap = assets.ao;
        m_roughnessMap = assets.roughness;
        m_metallicMap = assets.metallic;
        auto present = [](const Image& i) { return i.empty() ? nullptr : &i; };
        if (Status s = take(m_orm, k.orm ? previous->m_orm : none,
                            [&] {
                                return gl::uploadOrm(present(assets.ao), present(assets.roughness),
                                                     present(assets.metallic));
                            });
            !s)
            return s;
    }
    // Derived maps upload when a technique asks (prepare); ones `previous` holds for the same
    // height come along, so a bake adds one texture and an undo none.
    if (!assets.cone.sqrtRatio.empty()) {
        m_coneCpu = assets.cone;
        if (k.cone) {
            m_cone = previous->m_cone;
            m_cone16 = previous->m_cone16;
        }
    }
    if (!assets.relaxedCone.sqrtRatio.empty()) {
        m_relaxedCpu = assets.relaxedCone;
        if (k.relaxedCone) {
            m_relaxed = previous->m_relaxed;
            m_relaxed16 = previous->m_relaxed16;
        }
    }
    if (k.pyramid) {
        m_pyramidCpu = previous->m_pyramidCpu;
        m_atlas = previous->m_atlas;
        m_atlasRows = previous->m_atlasRows;
        m_atlasTop = previous->m_atlasTop;
    }
    return success();
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
        gl::setWrap(*m_height, wrap);
    for (const Texture* t : {&m_albedo, &m_normal, &m_orm}) {
        if (*t)
            gl::setFilteredSampling(**t, wrap);
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
    auto cone = [&](ConeKind kind, std::optional<ConeMap>& cpu, Texture& gpu,
                    bool& sixteen) -> Status {
        if (gpu)
            return success();
        if (!cpu) {
            cpu = bakeConeMap(m_field, m_wrap, kind);
            quantiseDown(*cpu, 65535); // as the editor's bakes: RG16 holds it
            ++m_bakes;
        }
        sixteen = m_height16 && gl::fitsRG16(*cpu);
        Result<gl::Object> t = gl::uploadConeMap(
            m_field, *cpu, sixteen ? gl::ConeFormat::RG16 : gl::ConeFormat::RG32F);
        if (!t)
            return t.error();
        gl::setWrap(*t, m_wrap);
        gpu = std::make_shared<const gl::Object>(std::move(*t));
        ++m_uploads;
        return success();
    };
    if (ti.needsConeMap) {
        if (Status s = cone(ConeKind::Conservative, m_coneCpu, m_cone, m_cone16); !s)
            return s;
    }
    if (ti.needsRelaxedConeMap) {
        if (Status s = cone(ConeKind::Relaxed, m_relaxedCpu, m_relaxed, m_relaxed16); !s)
            return s;
    }
    if (ti.needsPyramid && !m_atlas) {
        if (!m_pyramidCpu) {
            m_pyramidCpu =
                std::make_shared<const MaxMipPyramid>(MaxMipPyramid::build(m_field, m_wrap));
            ++m_bakes;
        }
        if (m_pyramidCpu->levels() > kMaxMipAtlasLevels)
            return Error{"the max-mip pyramid has more levels than the shader's table holds"};
        Result<gl::Object> t = gl::uploadMaxMipAtlas(*m_pyramidCpu, m_atlasRows);
        if (!t)
            return t.error();
        m_atlas = std::make_shared<const gl::Object>(std::move(*t));
        ++m_uploads;
        m_atlasTop = m_pyramidCpu->top();
    }
    return success();
}

void GpuMaterial::bind(const ShaderProgram& program) const {
    auto unit = [](int u, const Texture& t) {
        if (!t)
            return;
        glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(u));
        glBindTexture(GL_TEXTURE_2D, t->id());
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
