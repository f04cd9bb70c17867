#include "parallax/render/GpuConeBaker.h"

#include "parallax/bake/ConeBakeInputs.h"
#include "parallax/bake/ConeMapFinish.h"
#include "parallax/render/GlInfo.h"
#include "parallax/render/HeadlessContext.h"
#include "parallax/render/ShaderProgram.h"
#include "parallax/shader/ShaderGenerator.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <algorithm>
#include <chrono>

namespace px {

namespace {

using Clock = std::chrono::steady_clock;

// A storage buffer holding `bytes` of `data` (or uninitialised), bound at `binding`.
Result<gl::Object> storage(int binding, const void* data, std::size_t bytes) {
    GLint64 largest = 0;
    glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &largest);
    if (static_cast<GLint64>(bytes) > largest)
        return Error{"the map needs a " + std::to_string(bytes >> 20) +
                     " MiB storage buffer, more than this GPU's " + std::to_string(largest >> 20) +
                     " MiB"};
    gl::Object buffer(gl::ObjectKind::Buffer);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, buffer.id());
    // An empty buffer is still bound (a program's unused block must have one).
    glBufferData(GL_SHADER_STORAGE_BUFFER, static_cast<GLsizeiptr>(std::max<std::size_t>(bytes, 4)),
                 data, data ? GL_STATIC_DRAW : GL_STREAM_READ);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, static_cast<GLuint>(binding), buffer.id());
    if (Status s = checkGlError("uploading the bake's buffers"); !s)
        return s.error();
    return buffer;
}

void setInt(GLuint p, const char* name, int v) {
    glUniform1i(glGetUniformLocation(p, name), v);
}

template <typename T> void setInts(GLuint p, const char* name, const T* v, int count) {
    if (count > 0)
        glUniform1iv(glGetUniformLocation(p, name), count, v);
}

void setSizes(GLuint p, const char* name, const std::vector<glm::ivec2>& sizes) {
    if (!sizes.empty())
        glUniform2iv(glGetUniformLocation(p, name), static_cast<GLsizei>(sizes.size()),
                     &sizes[0].x);
}

} // namespace

Result<unsigned> GpuConeBaker::program(ConeKind kind, WrapMode wrap) {
    const int key = static_cast<int>(kind) * 2 + static_cast<int>(wrap);
    auto found = m_programs.find(key);
    if (found != m_programs.end())
        return found->second.id();
    if (Status s = requireGl43(currentGlInfo()); !s)
        return s.error();
    // llvmpipe runs a work group's invocations as one SIMD program, and there the relaxed
    // kernel's divergent search missed cells that narrow cones (issue 41: cones wider than the
    // CPU's on noise 256², in whole tiles); one invocation a group gives the CPU's cones.
    if (m_localSize == 0)
        m_localSize =
            currentGlInfo().renderer.find("llvmpipe") != std::string::npos ? 1 : kBakeLocalSize;
    Result<GeneratedShader> source = generateBakeShader(
        kind == ConeKind::Relaxed ? BakeShaderKind::Relaxed : BakeShaderKind::Quick, wrap,
        m_localSize);
    if (!source)
        return source.error();
    Result<gl::Object> shader =
        compileShaderStage(GL_COMPUTE_SHADER, *source, "the cone bake's compute shader");
    if (!shader)
        return shader.error();
    gl::Object p(gl::ObjectKind::Program);
    glAttachShader(p.id(), shader->id());
    glLinkProgram(p.id());
    glDetachShader(p.id(), shader->id());
    GLint ok = GL_FALSE;
    glGetProgramiv(p.id(), GL_LINK_STATUS, &ok);
    if (!ok)
        return Error{"the cone bake's compute program does not link"};
    const unsigned id = p.id();
    m_programs.emplace(key, std::move(p));
    return id;
}

Result<ConeMap> GpuConeBaker::bakeRaw(const HeightField& field, WrapMode wrap, ConeKind kind,
                                      const BakeControl& control, GpuBakeInfo* info) {
    if (field.empty())
        return Error{"the height map is empty"};
    // The pyramids on the CPU: about 2 % of the work on a CPU bake, a share of the bar here too.
    BakeControl prepare = control;
    if (control.progress)
        prepare.progress = [&control](float f) { control.progress(0.05f * f); };
    Result<ConeBakeInputs> in = prepareConeBake(field, wrap, kind, prepare);
    if (!in)
        return in.error();
    Result<unsigned> p = program(kind, wrap);
    if (!p)
        return p.error();
    const auto start = Clock::now();
    const std::size_t texels = static_cast<std::size_t>(field.width) * field.height;
    Result<gl::Object> heights = storage(0, &field.texels[0], texels * sizeof(float));
    if (!heights)
        return heights.error();
    Result<gl::Object> fall =
        storage(1, in->fallWords.data(), in->fallWords.size() * sizeof(std::uint32_t));
    if (!fall)
        return fall.error();
    Result<gl::Object> levels =
        storage(2, in->levelValues.data(), in->levelValues.size() * sizeof(float));
    if (!levels)
        return levels.error();
    Result<gl::Object> cones = storage(3, nullptr, texels * sizeof(float));
    if (!cones)
        return cones.error();

    const GLuint id = *p;
    glUseProgram(id);
    glUniform2i(glGetUniformLocation(id, "pxBakeSize"), field.width, field.height);
    glUniform2f(glGetUniformLocation(id, "pxBakeInv"), 1.0f / static_cast<float>(field.width),
                1.0f / static_cast<float>(field.height));
    glUniform1f(glGetUniformLocation(id, "pxBakeMax"), field.maxHeight());
    setInt(id, "pxFallTop", in->fallTop);
    glUniform1f(glGetUniformLocation(id, "pxFallUnit"), in->fallUnit);
    setSizes(id, "pxFallSizes", in->fallSizes);
    setInts(id, "pxFallOffsets", in->fallOffsets.data(), static_cast<int>(in->fallOffsets.size()));
    setInt(id, "pxCellLevels", in->cellLevels);
    setSizes(id, "pxCellSizes", in->cellSizes);
    setInts(id, "pxCellOffsets", in->cellOffsets.data(), static_cast<int>(in->cellOffsets.size()));
    setInts(id, "pxStripLevelCounts", in->stripLevels.data(), 4);
    setInts(id, "pxStripCounts", in->stripCounts.data(), 128);
    setInts(id, "pxStripOffsets", in->stripOffsets.data(), 128);

    // Work items: 4 x 4 tiles (relaxed) or texels (quick), dispatched in slices that grow or
    // shrink towards sliceMilliseconds.
    const bool relaxed = kind == ConeKind::Relaxed;
    const int items =
        relaxed ? ((field.width + 3) / 4) * ((field.height + 3) / 4) : static_cast<int>(texels);
    const GLint first = glGetUniformLocation(id, "pxBakeFirst");
    const GLint end = glGetUniformLocation(id, "pxBakeEnd");
    int slice = m_localSize; // one work group first, then as many as the time allows
    int dispatches = 0;
    for (int done = 0; done < items;) {
        if (control.cancelled())
            return cancelledError();
        const int count = std::min(slice, items - done);
        glUniform1i(first, done);
        glUniform1i(end, done + count);
        const auto sliceStart = Clock::now();
        glDispatchCompute(static_cast<GLuint>((count + m_localSize - 1) / m_localSize), 1, 1);
        glFinish();
        ++dispatches;
        done += count;
        if (control.progress)
            control.progress(0.05f + 0.95f * static_cast<float>(done) / static_cast<float>(items));
        const double ms =
            std::chrono::duration<double, std::milli>(Clock::now() - sliceStart).count();
        if (ms < 0.5 * sliceMilliseconds)
            slice = std::min(slice * 2, 1 << 24);
        else if (ms > 2.0 * sliceMilliseconds)
            slice = std::max(slice / 2, m_localSize);
    }
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    ConeMap out(kind, field.width, field.height);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, cones->id());
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, static_cast<GLsizeiptr>(texels * sizeof(float)),
                       &out.sqrtRatio[0]);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    glUseProgram(0);
    if (Status s = checkGlError("baking cone maps on the GPU"); !s)
        return s.error();
    if (info) {
        info->renderer = currentGlInfo().renderer;
        info->milliseconds =
            std::chrono::duration<double, std::milli>(Clock::now() - start).count();
        info->dispatches = dispatches;
    }
    return out;
}

Result<ConeMap> GpuConeBaker::bake(const HeightField& field, WrapMode wrap, ConeKind kind,
                                   const BakeControl& control, GpuBakeInfo* info) {
    Result<ConeMap> cones = bakeRaw(field, wrap, kind, control, info);
    if (cones) {
        applyNeighbourhoodMinimum(*cones, wrap);
        if (control.progress)
            control.progress(1.0f);
    }
    return cones;
}

Result<ConeMap> bakeConeMapHeadless(const HeightField& field, WrapMode wrap, ConeKind kind,
                                    const BakeControl& control, GpuBakeInfo* info) {
    Result<std::unique_ptr<HeadlessContext>> context = HeadlessContext::create();
    if (!context)
        return context.error();
    GpuConeBaker baker;
    return baker.bake(field, wrap, kind, control, info);
}

} // namespace px
