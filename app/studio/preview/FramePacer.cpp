#include "preview/FramePacer.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>

namespace px::studio {

namespace {

double g_budgetMs = 30.0;

// The first band of a new cost: at most an eighth of the view (twice this).
constexpr int kFirstBandFraction = 16;
// The stand-in's share of the view's pixels: at least this, so it is a picture, and at most a
// quarter, so it is cheap.
constexpr double kMinStandIn = 1.0 / 64.0, kMaxStandIn = 0.25;

std::function<double()> g_clock; // ms; the steady clock when empty

double nowMs() {
    if (g_clock)
        return g_clock();
    return std::chrono::duration<double, std::milli>(
               std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

} // namespace

void FramePacer::setBudgetMs(double ms) {
    g_budgetMs = ms;
}

double FramePacer::budgetMs() {
    return g_budgetMs;
}

namespace {
double g_turnSpentMs = 0.0, g_turnEndedMs = 0.0;
bool g_turnOpen = false, g_turnEnded = false;
} // namespace

double FramePacer::budgetLeftInTurn(double breathMs) {
    if (!g_turnOpen) {
        if (g_turnEnded && nowMs() - g_turnEndedMs < breathMs)
            return 0.0;
        g_turnOpen = true;
        g_turnSpentMs = 0.0;
    }
    return std::max(0.0, g_budgetMs - g_turnSpentMs);
}

void FramePacer::spentInTurn(double ms) {
    if (g_turnOpen)
        g_turnSpentMs += ms;
}

void FramePacer::endTurn() {
    if (!g_turnOpen)
        return;
    g_turnOpen = false;
    g_turnEnded = true;
    g_turnEndedMs = nowMs();
}

namespace {
std::optional<double> g_inputMs;
} // namespace

void FramePacer::noteInput() {
    g_inputMs = nowMs();
}

bool FramePacer::inputRecently() {
    return g_inputMs && nowMs() - *g_inputMs < kInputQuietMs;
}

void FramePacer::setClock(std::function<double()> nowMs) {
    g_clock = std::move(nowMs);
}

void FramePacer::forget() {
    m_started = false;
}

Status FramePacer::ensureTarget(std::optional<RenderTarget>& target, glm::ivec2 size) {
    if (target && target->size() == size)
        return success();
    target.reset();
    Result<RenderTarget> made = RenderTarget::create(size, TargetFormat::Rgba8);
    if (!made)
        return made.error();
    target = std::move(*made);
    return success();
}

Result<FramePacer::Step> FramePacer::step(std::uint64_t serial, std::uint64_t costKey,
                                          glm::ivec2 size, unsigned fbo, double budgetMs,
                                          const DrawFn& draw) {
    QOpenGLExtraFunctions* f = QOpenGLContext::currentContext()->extraFunctions();
    const double start = nowMs();
    const int width = std::max(1, size.x), height = std::max(1, size.y);
    size = {width, height};
    if (Status s = ensureTarget(m_frame, size); !s)
        return s.error();
    // Other maps (an upload landed), another technique: another picture, at another cost.
    const bool newCost = !m_started || costKey != m_costKey;
    if (newCost || m_rowMs.size() != std::size_t(height))
        m_rowMs.clear(); // the last frame's costs a row describe another picture
    if (newCost) {
        m_msPerPixel.reset();
        m_meanPerPixel = 0.0;
        m_bandRows = std::max(1, height / kFirstBandFraction);
        m_costKey = costKey;
    }
    const bool firstStep = newCost || serial != m_serial;
    if (firstStep) {
        m_serial = serial;
        m_rowsDone = 0;
        m_frameMs = 0.0;
        m_standInShown = m_standInDecided = false;
        m_started = true;
        m_rowMsDrawn.assign(std::size_t(height), 0.0);
    }
    Step step;
    const bool breathe = budgetMs <= 0.0;

    auto drawBand = [&](int rows) -> Status {
        m_frame->bind();
        const double bandStart = nowMs();
        Status drawn = draw(size, QRect(0, m_rowsDone, width, rows));
        f->glFinish(); // what the band cost
        if (!drawn)
            return drawn;
        const double ms = nowMs() - bandStart;
        // Learnt quickly upwards (a band over the mesh after one over the sky), slowly down.
        const double perPixel = ms / (double(rows) * width);
        m_msPerPixel = m_msPerPixel ? std::max(perPixel, 0.5 * *m_msPerPixel) : perPixel;
        std::fill_n(m_rowMsDrawn.begin() + m_rowsDone, rows, ms / rows);
        m_frameMs += ms;
        m_rowsDone += rows;
        m_bandRows = rows;
        ++step.bands;
        return success();
    };

    // The whole scene at fewer pixels, shown until the frame is whole; returns its cost a pixel.
    auto drawStandIn = [&](double share) -> Result<double> {
        const glm::ivec2 small(std::max(1, int(std::lround(width * std::sqrt(share)))),
                               std::max(1, int(std::lround(height * std::sqrt(share)))));
        if (Status s = ensureTarget(m_standIn, small); !s)
            return s.error();
        m_standIn->bind();
        const double standInStart = nowMs();
        const Status drawn = draw(small, QRect());
        f->glFinish();
        if (!drawn)
            return drawn.error();
        m_standInShown = step.standIn = true;
        m_standInShare = share;
        // The whole scene's mean: a floor for the bands' estimate, which a band over the sky
        // alone would set far too low for the next one over the mesh.
        m_meanPerPixel = (nowMs() - standInStart) / (double(small.x) * small.y);
        return m_meanPerPixel;
    };

    // An unknown cost is probed on the whole scene at a 64th of the pixels (a band of rows would
    // see the sky alone), which is the first picture too. It errs high: a new program's first
    // draw includes its compiling, and few pixels share the fixed costs.
    if (!m_msPerPixel && !breathe) {
        Result<double> perPixel = drawStandIn(kMinStandIn);
        if (!perPixel)
            return perPixel.error();
        m_msPerPixel = *perPixel;
    }
    // The rest will not fit in this turn: first a stand-in as large as fits, once a frame (not
    // in a step the probe has used up).
    const double left = budgetMs - (nowMs() - start);
    if (!m_standInDecided && !breathe && m_rowsDone < height && left > 0.0) {
        m_standInDecided = true;
        const double perPixel = std::max(*m_msPerPixel, m_meanPerPixel);
        const double full = perPixel * double(width) * height;
        const double rest = perPixel * double(width) * (height - m_rowsDone);
        const double share = std::clamp(0.5 * left / full, kMinStandIn, kMaxStandIn);
        if (rest > left && (!m_standInShown || share > 2.0 * m_standInShare))
            if (Result<double> drawn = drawStandIn(share); !drawn)
                return drawn.error();
    }
    // Bands for what is left of the budget; at least one a step that draws, so every frame
    // completes.
    while (m_rowsDone < height && !breathe) {
        const double left = budgetMs - (nowMs() - start);
        const double rowMs = std::max(*m_msPerPixel, m_meanPerPixel) * width;
        int rows = 0;
        if (m_rowMs.empty()) {
            // A cost the clock did not see (a coarse clock, a fast GPU) is no limit: the band
            // doubling is. (left / 0 cast to int was INT_MIN: one row a step, a frame over
            // hundreds of turns.)
            rows = rowMs > 0.0 ? static_cast<int>(std::min(left / rowMs, double(height))) : height;
        } else {
            // The last frame of this cost said what each row costs: a band stops before the
            // rows that were dear (a small mesh under much sky), never grows past the estimate.
            for (double sum = 0.0; m_rowsDone + rows < height; ++rows) {
                sum += std::max(rowMs, m_rowMs[std::size_t(m_rowsDone) + std::size_t(rows)]);
                if (sum > left)
                    break;
            }
        }
        rows = std::min({rows, 2 * m_bandRows, height - m_rowsDone});
        if (rows < 1) {
            if (step.bands > 0 || step.standIn)
                break;
            rows = 1;
        }
        if (Status s = drawBand(rows); !s)
            return s.error();
    }

    step.complete = m_rowsDone >= height;
    if (step.complete && step.bands > 0)
        m_rowMs = m_rowMsDrawn;
    step.frameMs = step.complete ? m_frameMs : 0.0;
    const RenderTarget& shown = step.complete || !m_standInShown ? *m_frame : *m_standIn;
    f->glBindFramebuffer(GL_READ_FRAMEBUFFER, shown.framebuffer());
    f->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, fbo);
    f->glBlitFramebuffer(0, 0, shown.size().x, shown.size().y, 0, 0, width, height,
                         GL_COLOR_BUFFER_BIT, shown.size() == size ? GL_NEAREST : GL_LINEAR);
    f->glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    f->glViewport(0, 0, width, height);
    return step;
}

} // namespace px::studio
