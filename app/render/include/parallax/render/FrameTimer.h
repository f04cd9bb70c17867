#pragma once
// Timing GL work. On llvmpipe (and other CPU rasterisers) GL timer queries are meaningless
// (docs/platform.md): there a steady clock brackets the work with glFinish before and
// after. On real GPUs a GL_TIME_ELAPSED query measures the GPU time of the work itself.

#include "parallax/render/GlInfo.h"

#include <functional>
#include <string>

namespace px {

struct FrameTiming {
    double medianMs = 0.0;
    double minMs = 0.0;
    double maxMs = 0.0;
    int frames = 0;
    bool gpuTimer = false; // GL_TIME_ELAPSED, else steady clock around glFinish
    std::string method() const {
        return gpuTimer ? "GL timer query" : "steady clock around glFinish";
    }
};

// Runs `frame` `warmup` times untimed (first-use compiles, uploads, bakes), then `frames` times,
// each timed alone. `frame` issues GL commands on the current context.
FrameTiming timeFrames(const std::function<void()>& frame, int frames, int warmup,
                       const GlInfo& info);

} // namespace px
