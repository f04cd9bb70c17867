#include "parallax/render/FrameTimer.h"

#include "parallax/render/GlObjects.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <algorithm>
#include <chrono>
#include <vector>

namespace px {

FrameTiming timeFrames(const std::function<void()>& frame, int frames, int warmup,
                       const GlInfo& info) {
    for (int i = 0; i < warmup; ++i)
        frame();
    FrameTiming timing;
    timing.gpuTimer = info.timerQueriesMeaningful();
    std::vector<double> ms;
    gl::Object query;
    if (timing.gpuTimer)
        query = gl::Object(gl::ObjectKind::Query);
    for (int i = 0; i < std::max(frames, 1); ++i) {
        if (timing.gpuTimer) {
            glBeginQuery(GL_TIME_ELAPSED, query.id());
            frame();
            glEndQuery(GL_TIME_ELAPSED);
            GLuint64 ns = 0;
            glGetQueryObjectui64v(query.id(), GL_QUERY_RESULT, &ns);
            ms.push_back(static_cast<double>(ns) * 1e-6);
        } else {
            glFinish();
            const auto start = std::chrono::steady_clock::now();
            frame();
            glFinish();
            ms.push_back(
                std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                    .count());
        }
    }
    std::sort(ms.begin(), ms.end());
    timing.frames = static_cast<int>(ms.size());
    timing.medianMs = ms[ms.size() / 2];
    timing.minMs = ms.front();
    timing.maxMs = ms.back();
    return timing;
}

} // namespace px
