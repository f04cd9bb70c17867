// The view's error readout against the bench (parallax-cli bench, Compare): on a plane seen at
// one angle (a long lens: every pixel's ray at nearly that angle) the technique's figures are the
// bench's for that setting and angle; seen from afar, the technique's figure follows its layers
// while the filtering's (the mip level against level 0), which no layer count changes, stays put.
// Drives the view's measurement (PreviewRenderer) on a GL context of its own; a seeded, tileable
// random height map (the seed printed on failure).

#include "parallax/eval/Bench.h"
#include "preview/ErrorStats.h"
#include "preview/GlSupport.h"
#include "preview/PreviewRenderer.h"

#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QTest>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

using namespace px;
using namespace px::studio;

namespace {

constexpr int kMapSide = 64;
constexpr float kScale = 0.1f;
constexpr float kTiling = 4.0f;

// A sum of tileable waves and bumps: slopes of every direction, some steep.
HeightField randomField(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> frequency(1, 6);
    std::uniform_real_distribution<double> phase(0.0, 2.0 * std::numbers::pi), amplitude(0.03, 0.1);
    struct Wave {
        int fx, fy;
        double phase, amplitude;
    };
    std::vector<Wave> waves;
    waves.reserve(7);
    for (int k = 0; k < 7; ++k)
        waves.push_back({frequency(rng), frequency(rng) - 3, phase(rng), amplitude(rng)});
    HeightField field(kMapSide, kMapSide);
    for (int y = 0; y < kMapSide; ++y)
        for (int x = 0; x < kMapSide; ++x) {
            double h = 0.5;
            for (const Wave& w : waves)
                h += w.amplitude *
                     std::sin(2.0 * std::numbers::pi * (w.fx * x + w.fy * y) / double(kMapSide) +
                              w.phase);
            field.at(x, y) = static_cast<float>(std::clamp(h, 0.0, 1.0));
        }
    return field;
}

TraceParams layers(int minLayers, int maxLayers) {
    TraceParams p = info(Technique::Pom).defaults;
    p.minLayers = minLayers;
    p.maxLayers = maxLayers;
    return p;
}

// The plane seen `polar` degrees from its normal through a long lens from `distance`.
PreviewScene planeScene(const std::shared_ptr<const MaterialAssets>& assets, TraceParams params,
                        float polar, float distance) {
    PreviewScene scene;
    scene.material.heightScale = kScale;
    scene.material.tiling = kTiling;
    scene.material.technique = Technique::Pom;
    scene.material.params = params;
    scene.quality = {Technique::Pom, params};
    scene.assets = assets;
    scene.view.camera.elevationDeg = 90.0f - polar;
    scene.view.camera.azimuthDeg = 20.0f;
    scene.view.camera.fovYDeg = 2.0f;
    scene.view.camera.distance = distance;
    scene.view.camera.target = glm::vec3(0.0f);
    scene.overlays.heatMap = true; // every pixel
    return scene;
}

// The view's direction over its pixels, from each ray's entry and exact hit (hit = entry + P t):
// mean polar and azimuth in degrees, as the bench takes them (docs/conventions.md §5).
struct ViewAngle {
    double polar = 0.0, azimuth = 0.0, spread = 0.0; // spread: max polar - min polar
};

ViewAngle angleOf(const PreviewRenderer::Surfaces& s) {
    double px = 0.0, py = 0.0, lo = 90.0, hi = 0.0;
    int n = 0;
    double polarSum = 0.0;
    for (int y = 0; y < s.exact.height; ++y)
        for (int x = 0; x < s.exact.width; ++x) {
            const double t = s.exact.at(x, y, 2);
            if (!(t > 0.2) || !(s.entry.at(x, y, 2) >= 0.0f))
                continue;
            const double dx = (double(s.exact.at(x, y, 0)) - s.entry.at(x, y, 0)) / t;
            const double dy = (double(s.exact.at(x, y, 1)) - s.entry.at(x, y, 1)) / t;
            const double polar = std::atan(std::hypot(dx, dy) / kScale) * 180.0 / std::numbers::pi;
            lo = std::min(lo, polar);
            hi = std::max(hi, polar);
            polarSum += polar;
            px += dx;
            py += dy;
            ++n;
        }
    ViewAngle a;
    if (n == 0)
        return a;
    a.polar = polarSum / n;
    a.azimuth = std::atan2(py, px) * 180.0 / std::numbers::pi;
    if (a.azimuth < 0.0)
        a.azimuth += 360.0;
    a.spread = hi - lo;
    return a;
}

HitErrorStats benchAt(const HeightField& field, TraceParams params, double polar, double azimuth) {
    BenchConfig config;
    config.maps = {{"random", std::make_shared<HeightField>(field)}};
    BenchSetting setting;
    setting.technique = Technique::Pom;
    setting.params = params;
    config.settings = {setting};
    config.polarDeg = {polar};
    config.azimuthDeg = azimuth;
    config.scales = {kScale};
    config.rays = 256;
    config.timingRepeats = 0;
    Result<BenchReport> report = runBench(config);
    if (!report || report->rows.size() != 1)
        return {};
    return report->rows.front().stats;
}

bool near(double a, double b, double relative, double absolute) {
    return std::abs(a - b) <= relative * std::max(std::abs(a), std::abs(b)) + absolute;
}

} // namespace

class ReadoutBenchTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { setUpOpenGl(); }

private slots:
    void initTestCase() {
        QVERIFY2(probeOpenGl().usable, qPrintable(probeOpenGl().reason));
        m_surface.setFormat(QSurfaceFormat::defaultFormat());
        m_surface.create();
        m_context.setFormat(QSurfaceFormat::defaultFormat());
        QVERIFY(m_context.create());
        QVERIFY(m_context.makeCurrent(&m_surface));
        Result<std::unique_ptr<PreviewRenderer>> renderer = PreviewRenderer::create();
        QVERIFY2(renderer, renderer ? "" : renderer.error().message.c_str());
        m_renderer = std::move(*renderer);
        m_renderer->keepSurfaces(true);
        m_seed = std::random_device{}();
    }
    void cleanupTestCase() {
        m_renderer.reset();
        m_context.doneCurrent();
    }

    // Close enough that every pixel reads level 0: the filtering's error is nothing, and the
    // technique's figures are the bench's at the view's angle, for two settings and two angles;
    // the bench at another angle is told apart, so the comparison can fail.
    void techniqueFiguresAreTheBenchs_data() {
        QTest::addColumn<int>("minLayers");
        QTest::addColumn<int>("maxLayers");
        QTest::addColumn<float>("polar");
        QTest::addRow("pom 4-8 at 60") << 4 << 8 << 60.0f;
        QTest::addRow("pom 8-32 at 70") << 8 << 32 << 70.0f;
    }
    void techniqueFiguresAreTheBenchs() {
        QFETCH(int, minLayers);
        QFETCH(int, maxLayers);
        QFETCH(float, polar);
        const HeightField field = randomField(m_seed);
        auto assets = std::make_shared<MaterialAssets>();
        assets->height = field;
        const TraceParams params = layers(minLayers, maxLayers);
        const PreviewStats view = measure(planeScene(assets, params, polar, 30.0f));
        QVERIFY2(view.valid && view.pixels > 20000, qPrintable(seedText()));
        QCOMPARE(view.filteringMaxError, 0.0); // level 0 everywhere: both exact passes agree
        const ViewAngle angle = angleOf(m_renderer->surfaces());
        QVERIFY2(
            std::abs(angle.polar - polar) < 1.0 && angle.spread < 3.0,
            qPrintable(QString("view at %1 deg, spread %2").arg(angle.polar).arg(angle.spread)));
        const HitErrorStats bench = benchAt(field, params, angle.polar, angle.azimuth);
        QVERIFY(bench.rays > 0);
        const QString figures =
            QString("%1: view p99 %2 mean %3, bench p99 %4 mean %5 at %6/%7 deg")
                .arg(seedText())
                .arg(view.p99Error)
                .arg(view.meanError)
                .arg(bench.p99Error)
                .arg(bench.meanError)
                .arg(angle.polar)
                .arg(angle.azimuth);
        qInfo("%s", qPrintable(figures));
        QVERIFY2(bench.p99Error > 0.01, qPrintable(figures)); // a setting with an error to see
        QVERIFY2(near(view.p99Error, bench.p99Error, 0.15, 0.01), qPrintable(figures));
        QVERIFY2(near(view.meanError, bench.meanError, 0.15, 0.005), qPrintable(figures));
        // The same figure 15 degrees steeper is another: the agreement above means something.
        const HitErrorStats steeper = benchAt(field, params, angle.polar + 15.0, angle.azimuth);
        QVERIFY2(!near(view.p99Error, steeper.p99Error, 0.15, 0.01),
                 qPrintable(figures + QString(", bench p99 %1 steeper").arg(steeper.p99Error)));
    }

    // From afar the pixels read a coarser level: its exact hit is off level 0's (the filtering's
    // error), the same whatever the layers; the technique's own error falls with more layers,
    // while the error against level 0 alone (the readout before) hardly moves.
    void techniqueFigureFollowsTheLayersFilteringDoesNot() {
        const HeightField field = randomField(m_seed);
        auto assets = std::make_shared<MaterialAssets>();
        assets->height = field;
        const PreviewStats coarse = measure(planeScene(assets, layers(4, 8), 70.0f, 200.0f));
        const SurfaceErrors coarseTotal = totalAgainstLevel0();
        const PreviewStats fine = measure(planeScene(assets, layers(128, 256), 70.0f, 200.0f));
        const SurfaceErrors fineTotal = totalAgainstLevel0();
        const QString figures =
            QString("%1: technique p99 %2 -> %3, filtering p99 %4 -> %5, total p99 %6 -> %7")
                .arg(seedText())
                .arg(coarse.p99Error)
                .arg(fine.p99Error)
                .arg(coarse.filteringP99Error)
                .arg(fine.filteringP99Error)
                .arg(coarseTotal.techniqueError.p99)
                .arg(fineTotal.techniqueError.p99);
        qInfo("%s", qPrintable(figures));
        QVERIFY2(coarse.valid && fine.valid && coarse.pixels == fine.pixels, qPrintable(figures));
        QVERIFY2(coarse.filteringP99Error > 0.1, qPrintable(figures)); // a coarser level is read
        QCOMPARE(fine.filteringP99Error, coarse.filteringP99Error);
        QCOMPARE(fine.filteringMeanError, coarse.filteringMeanError);
        QVERIFY2(fine.p99Error < 0.25 * coarse.p99Error, qPrintable(figures));
        // Against level 0 alone the layers hide behind the filtering: the total falls far less.
        QVERIFY2(fineTotal.techniqueError.p99 > 0.5 * fine.filteringP99Error, qPrintable(figures));
    }

private:
    PreviewStats measure(const PreviewScene& scene) {
        if (!m_renderer->beginMeasure(scene, QSize(320, 320), 0.0))
            return {};
        for (int step = 0; step < 100000; ++step)
            if (std::optional<Result<PreviewStats>> done = m_renderer->measureStep(1.0e6))
                return *done ? **done : PreviewStats{};
        return {};
    }
    // The last measurement's technique hits against level 0's exact hits alone.
    SurfaceErrors totalAgainstLevel0() const {
        const PreviewRenderer::Surfaces& s = m_renderer->surfaces();
        ReferenceSurfaces references;
        references.exact = &s.exact;
        references.entry = &s.entry;
        return compareSurfaces(s.hits, references, kMapSide, kMapSide);
    }
    QString seedText() const { return QString("seed %1").arg(m_seed); }

    QOffscreenSurface m_surface;
    QOpenGLContext m_context;
    std::unique_ptr<PreviewRenderer> m_renderer;
    unsigned m_seed = 0;
};

QTEST_MAIN(ReadoutBenchTest)
#include "ReadoutBenchTest.moc"
