// The preview's frame pacing (preview/FramePacer.h) on a GL context, with a clock the draws
// advance by a cost a pixel the test sets: a frame that fits is whole in one step; a dear one is
// drawn over several steps, none over its budget, a stand-in shown meanwhile, every row once; one
// the clock cannot see is whole at once; a new scene starts over; a budget of 0 draws nothing; a
// cost that jumps down the view is learnt; the views share a turn's budget and breathe after it.

#include "preview/FramePacer.h"

#include "StudioTestSupport.h"
#include "preview/GlSupport.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QtTest>
#include <cmath>
#include <functional>
#include <optional>
#include <vector>

using namespace px;
using namespace px::studio;

namespace {

constexpr glm::ivec2 kSize{160, 120};

// A scene whose draw costs `perPixel(row)` fake ms a pixel: the whole view red, a stand-in blue.
struct FakeScene {
    double clock = 0.0;
    std::function<double(int row)> perPixel;
    std::vector<int> rowDraws = std::vector<int>(kSize.y, 0); // full-size draws of each row
    int standIns = 0;

    Status draw(glm::ivec2 size, QRect rows) {
        QOpenGLFunctions* f = QOpenGLContext::currentContext()->functions();
        const bool full = size == kSize;
        const QRect r = rows.isEmpty() ? QRect(0, 0, size.x, size.y) : rows;
        f->glEnable(GL_SCISSOR_TEST);
        f->glScissor(r.x(), size.y - r.y() - r.height(), r.width(), r.height());
        f->glClearColor(full ? 1.0f : 0.0f, 0.0f, full ? 0.0f : 1.0f, 1.0f);
        f->glClear(GL_COLOR_BUFFER_BIT);
        f->glDisable(GL_SCISSOR_TEST);
        for (int y = r.top(); y <= r.bottom(); ++y) {
            // A stand-in's row y covers the view's rows around y * kSize.y / size.y.
            clock += perPixel(y * kSize.y / size.y) * r.width();
            if (full)
                ++rowDraws[y];
        }
        standIns += full ? 0 : 1;
        return success();
    }
    FramePacer::DrawFn fn() {
        return [this](glm::ivec2 size, QRect rows) { return draw(size, rows); };
    }
};

// The colour every pixel of `target` shows, or nothing when they differ.
std::optional<QColor> uniformColour(const RenderTarget& target) {
    const Image image = target.read();
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            for (int c = 0; c < 3; ++c)
                if (std::abs(image.at(x, y, c) - image.at(0, 0, c)) > 0.02f)
                    return std::nullopt;
    return QColor::fromRgbF(image.at(0, 0, 0), image.at(0, 0, 1), image.at(0, 0, 2));
}

} // namespace

class FramePacerTest : public QObject {
    Q_OBJECT
    QOffscreenSurface m_surface;
    QOpenGLContext m_context;
    std::optional<RenderTarget> m_shown; // the view's framebuffer
    FakeScene* m_scene = nullptr;

    // One step of the frame of `serial`, timed on the fake clock.
    FramePacer::Step step(FramePacer& pacer, FakeScene& scene, std::uint64_t serial,
                          double budgetMs, double* ms = nullptr) {
        const double before = scene.clock;
        Result<FramePacer::Step> s =
            pacer.step(serial, 1, kSize, m_shown->framebuffer(), budgetMs, scene.fn());
        if (ms)
            *ms = scene.clock - before;
        return s ? *s : FramePacer::Step{};
    }

public:
    static void initMain() { setUpOpenGl(); }

private slots:
    void initTestCase() {
        m_surface.create();
        QVERIFY(m_context.create());
        QVERIFY(m_context.makeCurrent(&m_surface));
        Result<RenderTarget> target = RenderTarget::create(kSize, TargetFormat::Rgba8);
        QVERIFY(target);
        m_shown = std::move(*target);
        FramePacer::setClock([this] { return m_scene ? m_scene->clock : 0.0; });
    }
    void cleanupTestCase() { FramePacer::setClock({}); }

    // Two views' steps in one window update share the turn's budget; the turn ends after the
    // event (composing included), and nothing is left for a breath after that, however long
    // the event took beyond its drawing.
    void viewsShareATurnAndBreatheAfterIt() {
        FakeScene scene;
        m_scene = &scene;
        FramePacer::endTurn(); // whatever an earlier test left open
        scene.clock += 100.0;
        QCOMPARE(FramePacer::budgetLeftInTurn(10.0), 30.0);
        FramePacer::spentInTurn(18.0); // the first view's step
        scene.clock += 18.0;
        QCOMPARE(FramePacer::budgetLeftInTurn(10.0), 12.0); // the second view's
        FramePacer::spentInTurn(12.0);
        scene.clock += 12.0;
        QCOMPARE(FramePacer::budgetLeftInTurn(10.0), 0.0);
        scene.clock += 40.0; // composing the window, a bake's result: not drawing, same event
        QCOMPARE(FramePacer::budgetLeftInTurn(10.0), 0.0); // a measure slice waits
        FramePacer::endTurn();
        scene.clock += 9.0;
        QCOMPARE(FramePacer::budgetLeftInTurn(10.0), 0.0); // within the breath
        FramePacer::spentInTurn(5.0);                      // a copy while breathing counts nowhere
        FramePacer::endTurn();                             // nor does it end a turn again
        scene.clock += 1.0;
        QCOMPARE(FramePacer::budgetLeftInTurn(10.0), 30.0); // a new turn
        FramePacer::endTurn();
        m_scene = nullptr;
    }

    void aFrameThatFitsIsWholeInOneStep() {
        FakeScene scene;
        m_scene = &scene;
        scene.perPixel = [](int) { return 1e-4; }; // 1.92 ms the frame
        FramePacer pacer;
        const FramePacer::Step s = step(pacer, scene, 1, 30.0);
        QVERIFY(s.complete);
        QVERIFY(s.bands >= 1);
        QCOMPARE(scene.rowDraws, std::vector<int>(kSize.y, 1));
        QVERIFY(qAbs(s.frameMs - 1e-4 * kSize.x * kSize.y) < 1e-9);
        QCOMPARE(uniformColour(*m_shown), std::optional<QColor>(QColor(Qt::red)));
    }

    // A draw the clock does not see (a coarse clock, a fast GPU) costs nothing: the frame is whole
    // in one step, in doubling bands, every row once (it took a row a step, 120 steps here).
    void aFrameTheClockCannotSeeIsWholeInOneStep() {
        FakeScene scene;
        m_scene = &scene;
        scene.perPixel = [](int) { return 0.0; };
        FramePacer pacer;
        const FramePacer::Step s = step(pacer, scene, 1, 30.0);
        QVERIFY(s.complete);
        QVERIFY2(s.bands <= 12, qPrintable(QString::number(s.bands)));
        QCOMPARE(scene.rowDraws, std::vector<int>(kSize.y, 1));
        QCOMPARE(uniformColour(*m_shown), std::optional<QColor>(QColor(Qt::red)));
    }

    void aDearFrameIsDrawnOverSeveralStepsWithinBudget() {
        FakeScene scene;
        m_scene = &scene;
        const double perPixel = 150.0 / (kSize.x * kSize.y); // 150 ms the frame
        scene.perPixel = [&](int) { return perPixel; };
        FramePacer pacer;
        int steps = 0;
        for (;;) {
            double ms = 0.0;
            const FramePacer::Step s = step(pacer, scene, 1, 30.0, &ms);
            ++steps;
            QVERIFY2(ms <= 30.0 + 1e-9,
                     qPrintable(QStringLiteral("step %1: %2 ms").arg(steps).arg(ms)));
            if (s.complete) {
                QVERIFY(qAbs(s.frameMs - 150.0) < 1e-6);
                break;
            }
            // Meanwhile the stand-in, the whole view.
            QCOMPARE(uniformColour(*m_shown), std::optional<QColor>(QColor(Qt::blue)));
            QVERIFY(steps < 100);
        }
        QVERIFY2(steps >= 5, qPrintable(QString::number(steps)));
        QCOMPARE(scene.standIns, 2); // the probe, then one as large as fitted
        QCOMPARE(scene.rowDraws, std::vector<int>(kSize.y, 1));
        QCOMPARE(uniformColour(*m_shown), std::optional<QColor>(QColor(Qt::red)));
    }

    void aNewSceneStartsOverAndNoBudgetDrawsNothing() {
        FakeScene scene;
        m_scene = &scene;
        scene.perPixel = [](int) { return 150.0 / (kSize.x * kSize.y); };
        FramePacer pacer;
        QVERIFY(!step(pacer, scene, 1, 30.0).complete);
        double ms = -1.0;
        FramePacer::Step s = step(pacer, scene, 1, 0.0, &ms);
        QCOMPARE(ms, 0.0);
        QVERIFY(!s.complete && s.bands == 0 && !s.standIn);
        // Scene 2: rows from the top again, a stand-in first (the cost is known: no probe).
        std::fill(scene.rowDraws.begin(), scene.rowDraws.end(), 0);
        s = step(pacer, scene, 2, 30.0);
        QVERIFY(s.standIn && !s.complete);
        QVERIFY(scene.rowDraws.front() == 1);
        while (!s.complete)
            s = step(pacer, scene, 2, 30.0);
        QCOMPARE(scene.rowDraws, std::vector<int>(kSize.y, 1));
        // Whole: the next step shows it again without drawing.
        const double frameMs = s.frameMs;
        s = step(pacer, scene, 2, 30.0, &ms);
        QVERIFY(s.complete && s.bands == 0 && !s.standIn);
        QCOMPARE(ms, 0.0);
        QCOMPARE(s.frameMs, frameMs);
        QCOMPARE(uniformColour(*m_shown), std::optional<QColor>(QColor(Qt::red)));
    }

    void aCostThatJumpsDownTheViewIsLearnt() {
        // The sky above (cheap), the mesh below at ten times the cost: a band over the sky must
        // not make the first band over the mesh ten times too long.
        FakeScene scene;
        m_scene = &scene;
        const double sky = 20.0 / (kSize.x * kSize.y);
        scene.perPixel = [&](int row) { return row < kSize.y / 2 ? sky : 10.0 * sky; };
        FramePacer pacer;
        double worst[4] = {};
        for (std::uint64_t serial = 1; serial <= 3; ++serial) { // the cost known from frame 2 on
            FramePacer::Step s;
            do {
                double ms = 0.0;
                s = step(pacer, scene, serial, 30.0, &ms);
                worst[serial] = std::max(worst[serial], ms);
            } while (!s.complete);
        }
        // The first frame knows the scene's mean cost (the probe) and keeps within twice the
        // budget; the next ones know each row's cost from the frame before, and keep to it.
        QVERIFY2(worst[1] <= 2.0 * 30.0, qPrintable(QString::number(worst[1])));
        for (int frame : {2, 3})
            QVERIFY2(worst[frame] <= 30.0 + 1e-9,
                     qPrintable(QStringLiteral("frame %1: %2 ms").arg(frame).arg(worst[frame])));
    }
};

QTEST_MAIN(FramePacerTest)
#include "FramePacerTest.moc"
