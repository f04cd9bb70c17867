#pragma once
// A view's frame drawn within a time budget per turn of the event loop. On llvmpipe a frame over
// 8192² maps costs 120-160 ms, longer than the event loop may stall: the pacer draws the frame
// into its own target in bands of rows, as many as the budget allows, and shows it once every
// band is there; meanwhile a picture of the same scene at fewer pixels, drawn first to fit the
// budget. The cost per pixel is learnt from the bands drawn, and each row's from the last whole
// frame; an unknown cost (another technique, other maps, another size) is first probed on the
// whole scene at a 64th of the pixels. Where a frame fits (a GPU, small maps) the pacer adds a
// probe per new cost and a copy a frame. Needs the view's GL context current.

#include "parallax/Result.h"
#include "parallax/render/RenderTarget.h" // parallax-render

#include <QRect>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

namespace px::studio {

class FramePacer {
public:
    // Draws the scene at `size` into the bound framebuffer, clipped to `rows` (view pixels, row 0
    // at the top; the whole view when empty).
    using DrawFn = std::function<Status(glm::ivec2 size, QRect rows)>;

    struct Step {
        bool complete = false; // the whole frame is shown, not the smaller stand-in
        double frameMs = 0.0;  // what the whole frame cost, its bands added up (when complete)
        int bands = 0;         // bands drawn in this step
        bool standIn = false;  // the smaller picture was drawn in this step
    };

    // Draws the next part of the frame of scene `serial` (a new serial starts a new frame) and
    // shows what there is in framebuffer `fbo` of `size`. `costKey` names what the cost per pixel
    // depends on beyond the camera (technique, maps, size): a new key starts a new frame too and
    // probes the cost again. Steps of a frame already whole only show it again; a budget of 0
    // draws nothing and shows what there is.
    Result<Step> step(std::uint64_t serial, std::uint64_t costKey, glm::ivec2 size, unsigned fbo,
                      double budgetMs, const DrawFn& draw);
    void forget(); // the next step starts a frame and probes the cost

    // The drawing one turn of the event loop may take (default 30 ms: with composing the window, a
    // turn stays well under 0.1 s; tests change it).
    static void setBudgetMs(double ms);
    static double budgetMs();
    // One window update paints every view, so the views' frames and measurements share a turn's
    // budget: what this turn has left, and what a step spent. A turn ends with the event that
    // drew, its composing included (endTurn, from a call queued after it); the next opens
    // `breathMs` later, so input and timers run between, and until then nothing is left.
    static double budgetLeftInTurn(double breathMs);
    static void spentInTurn(double ms);
    static void endTurn();
    // The user's input (a press, a key, the wheel) and whether some came within the last
    // kInputQuietMs. While it does, a view puts off what would hold the event loop for long: a
    // shader variant's first draw in its context (llvmpipe compiles it then, 0.3-0.9 s on the
    // GUI thread), so the window answers the click first and the variant is drawn once the user
    // pauses.
    static constexpr double kInputQuietMs = 300.0;
    static void noteInput();
    static bool inputRecently();

    // The clock steps and bands are timed with, in ms (tests: a clock the draws advance). Empty:
    // the steady clock.
    static void setClock(std::function<double()> nowMs);

private:
    Status ensureTarget(std::optional<RenderTarget>& target, glm::ivec2 size);

    std::optional<RenderTarget> m_frame, m_standIn;
    std::uint64_t m_serial = 0, m_costKey = 0;
    bool m_started = false;
    std::optional<double> m_msPerPixel;
    int m_bandRows = 1;     // the last band's rows: the next is at most twice as many
    int m_rowsDone = 0;     // rows of m_frame drawn for m_serial, from the top
    double m_frameMs = 0.0; // their cost
    bool m_standInShown = false, m_standInDecided = false;
    double m_standInShare = 0.0;      // of the view's pixels
    double m_meanPerPixel = 0.0;      // the last stand-in's cost a pixel
    std::vector<double> m_rowMs;      // each row's cost in the last whole frame of this cost
    std::vector<double> m_rowMsDrawn; // ... in the frame being drawn
};

} // namespace px::studio
