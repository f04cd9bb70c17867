// The editor driven as a user would, under Xvfb with llvmpipe: sliders reach the preview's pixels
// and the shader's uniforms, viewports trace different techniques, files load by drag and drop,
// baking a cone map enables the cone technique, undo restores, and a corrupt file changes nothing.

#include "StudioTestSupport.h"
#include "jobs/BakeRunner.h"
#include "jobs/MapUpload.h"
#include "panels/ComparePanel.h"
#include "panels/MapRow.h"
#include "panels/MapsPanel.h"
#include "panels/MaterialPanel.h"
#include "panels/TechniquePanel.h"
#include "panels/ViewPanel.h"
#include "panels/WorkPrecisionView.h"
#include "parallax/bake/ConeMapBaker.h"
#include "parallax/bake/ConeMapFinish.h"
#include "parallax/bake/ConeMapReference.h"
#include "parallax/image/ImageFile.h"
#include "parallax/io/AtomicWrite.h"
#include "parallax/material/MaterialFile.h"
#include "parallax/render/GpuMaterial.h"
#include "parallax/render/ShaderCache.h"
#include "preview/FramePacer.h"
#include "preview/PreviewRenderer.h"
#include "widgets/ImageConvert.h"
#include "widgets/SliderField.h"
#include "widgets/TechniqueCombo.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QMenu>
#include <QMessageBox>
#include <QOpenGLContext>
#include <QPainter>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QTimer>
#include <QToolButton>
#include <array>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;

namespace {

std::string writeRamp(const QTemporaryDir& dir, const char* name, int size) {
    Image image(size, size, 1);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x)
            image.at(x, y) = float((x + y) % 8) / 7.0f;
    const std::string path = dir.filePath(name).toStdString();
    return writeImage(path, image, {PixelFormat::UInt16, false}) ? path : std::string();
}

// Correlation of the heat legend's labels in `grab` with the labels drawn upright (or mirrored
// top to bottom) in white on black with the preview's font, where its layout puts them.
double legendLabelMatch(const PreviewWidget* preview, const QImage& grab, bool mirrored) {
    // The stops' labels, in one row under the bar (the unit beside the bar is left out: the
    // rectangle holding both would hold some of the bar).
    HeatLegendLayout legend = preview->heatLegend();
    legend.labels.pop_back();
    QRect labels;
    for (const HeatLegendLayout::Label& label : legend.labels)
        labels = labels.united(label.rect);
    QImage expected(labels.size(), QImage::Format_RGB32);
    expected.fill(Qt::black);
    QPainter p(&expected);
    p.setFont(preview->font());
    p.setPen(Qt::white);
    for (const HeatLegendLayout::Label& label : legend.labels)
        p.drawText(label.rect.translated(-labels.topLeft()), Qt::AlignLeft | Qt::AlignVCenter,
                   label.text);
    p.end();
    if (mirrored)
        expected = expected.mirrored(false, true);
    const QImage actual = grab.copy(labels).convertToFormat(QImage::Format_RGB32);
    double sa = 0, se = 0, saa = 0, see = 0, sae = 0;
    const double n = double(labels.width()) * labels.height();
    for (int y = 0; y < labels.height(); ++y) {
        for (int x = 0; x < labels.width(); ++x) {
            const double a = qGray(actual.pixel(x, y)), e = qGray(expected.pixel(x, y));
            sa += a, se += e, saa += a * a, see += e * e, sae += a * e;
        }
    }
    const double cov = sae / n - sa / n * se / n;
    const double va = saa / n - sa / n * sa / n, ve = see / n - se / n * se / n;
    return va > 0 && ve > 0 ? cov / std::sqrt(va * ve) : 0.0;
}

} // namespace

class StudioWindowTest : public GlWindowTest {
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY(glReady()); }

    void sliderChangesPixelsAndUniforms() {
        auto w = makeWindow();
        QVERIFY(w);
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(preview);
        QVERIFY(waitForFigures(preview));
        QVERIFY2(preview->renderError().isEmpty(), qPrintable(preview->renderError()));
        const QImage before = preview->grabFramebuffer();
        QCOMPARE(preview->uniformValue("pxScale").value_or(-1), 0.06f);

        // Page Up on the height scale slider, as a user would.
        QSlider* slider = w->materialPanel()->heightScale()->slider();
        slider->setFocus();
        QTest::keyClick(slider, Qt::Key_PageUp);
        const float scale = w->document()->material().heightScale;
        QVERIFY(scale > 0.08f);
        QVERIFY(waitForFrame(preview, preview->framesRendered()));
        QCOMPARE(preview->uniformValue("pxScale").value_or(-1), scale);
        const QImage after = preview->grabFramebuffer();
        QVERIFY2(changedPixels(before, after) > before.width() * before.height() / 50,
                 "deeper relief must move the pixels");

        // The layers slider reaches its uniform too.
        QSlider* layers = w->techniquePanel()->maxLayers()->slider();
        layers->setFocus();
        QTest::keyClick(layers, Qt::Key_PageUp);
        const int maxLayers = w->document()->material().params.maxLayers;
        QVERIFY(maxLayers > 32);
        QVERIFY(waitForFrame(preview, preview->framesRendered()));
        QCOMPARE(preview->uniformValue("pxMaxLayers").value_or(-1), float(maxLayers));
    }

    // Two views of one material draw from one copy of its maps on the GPU (an 8192² height map is
    // 171 MB there, and llvmpipe keeps it in the process); a bake uploads its own map and nothing
    // else, and undoing it uploads nothing.
    void viewsShareTheMapsOnTheGpu() {
        auto w = makeWindow(2);
        QVERIFY(w);
        PreviewWidget* left = w->viewports()->viewport(0)->preview();
        PreviewWidget* right = w->viewports()->viewport(1)->preview();
        QVERIFY(left && right);
        QVERIFY(waitForFrame(left, 0) && waitForFrame(right, 0));
        const GpuMaterial* first = left->gpuMaterial();
        QVERIFY(first && first == right->gpuMaterial());
        QCOMPARE(first->uploadCount(), 2); // the sample's height and albedo, once

        w->startBake(BakeKind::Cone);
        QTRY_VERIFY_WITH_TIMEOUT(!w->baker()->isBusy(), 60000);
        QVERIFY(w->document()->state().hasMap(MapKind::Cone));
        w->document()->edit("cone", [](DocumentState& s) {
            s.setView(1, {Technique::Cone, info(Technique::Cone).defaults});
        });
        QVERIFY(waitForFrame(left, left->framesRendered()) &&
                waitForFrame(right, right->framesRendered()));
        QVERIFY2(right->renderError().isEmpty(), qPrintable(right->renderError()));
        const GpuMaterial* baked = left->gpuMaterial();
        QVERIFY(baked && baked == right->gpuMaterial());
        QVERIFY(baked->ready(Technique::Cone));
        QCOMPARE(baked->uploadCount(), 1); // the cone map; the height and albedo came along
        QCOMPARE(baked->bakeCount(), 0);

        w->document()->undoStack()->undo(); // the bake
        QVERIFY(!w->document()->state().hasMap(MapKind::Cone));
        QVERIFY(waitForFrame(left, left->framesRendered()));
        QVERIFY(left->gpuMaterial());
        QCOMPARE(left->gpuMaterial()->uploadCount(), 0);
    }

    // Big maps go up on a worker, on a context sharing the views' (on the GUI thread an 8192² map
    // froze the window for over a second): the views draw what they have meanwhile, then the new
    // maps, and measure them. Here every upload goes to the worker.
    void mapsUploadOnAWorker() {
        PreviewRenderer::setBackgroundUploadTexels(0);
        const auto restore =
            qScopeGuard([] { PreviewRenderer::setBackgroundUploadTexels(4096u * 4096u); });
        const int before = MapUpload::completed();
        auto w = makeWindow(2);
        QVERIFY(w);
        PreviewWidget* left = w->viewports()->viewport(0)->preview();
        PreviewWidget* right = w->viewports()->viewport(1)->preview();
        QVERIFY(left && right);
        QVERIFY(waitForFigures(left) && waitForFigures(right));
        QCOMPARE(MapUpload::completed(), before + 1); // once for both views
        QVERIFY(left->gpuMaterial() && left->gpuMaterial() == right->gpuMaterial());
        const QImage sample = left->grabFramebuffer();

        const std::string ramp = writeRamp(m_dir, "worker_height.png", 256);
        QVERIFY(!ramp.empty());
        QVERIFY(w->loadMap(MapKind::Height, QString::fromStdString(ramp)));
        QVERIFY(waitForFigures(left) && waitForFigures(right));
        QVERIFY2(left->renderError().isEmpty(), qPrintable(left->renderError()));
        QCOMPARE(MapUpload::completed(), before + 2);
        QVERIFY(left->gpuMaterial() == right->gpuMaterial());
        QCOMPARE(left->gpuMaterial()->heightField().width, 256);
        QVERIFY(left->gpuMaterial()->heightField().texels.sharesWith(
            w->document()->state().assets->height.texels));
        // The worker's textures are visible to the views' contexts: the ramp draws (not the
        // background, not the sample) and is measured against its own exact hits.
        QVERIFY(left->stats().valid && left->stats().pixels > 0);
        QVERIFY2(changedPixels(sample, left->grabFramebuffer()) >
                     sample.width() * sample.height() / 10,
                 "the loaded ramp must not look like the sample");

        // A view switched to `cone` after a bake: the cone texture goes up there too, alone.
        w->startBake(BakeKind::Cone);
        QTRY_VERIFY_WITH_TIMEOUT(!w->baker()->isBusy(), 60000);
        QVERIFY(waitForFigures(left) && waitForFigures(right));
        const int bakedUploads = MapUpload::completed();
        w->document()->edit("cone", [](DocumentState& s) {
            s.setView(1, {Technique::Cone, info(Technique::Cone).defaults});
        });
        QVERIFY(waitForFigures(right));
        QVERIFY2(right->renderError().isEmpty(), qPrintable(right->renderError()));
        QCOMPARE(MapUpload::completed(), bakedUploads + 1);
        QVERIFY(right->gpuMaterial()->ready(Technique::Cone));
        QCOMPARE(right->gpuMaterial()->uploadCount(), 1);
        QCOMPARE(right->gpuMaterial()->bakeCount(), 0);
    }

    // The figures take two extra passes (at 8192² 0.2-0.4 s on llvmpipe): drawn a slice per
    // event-loop turn, with the same result as in one go; a scene change mid-way starts over.
    void dearFramesAreDrawnOverSeveralTurns() {
        // A frame over the pacer's budget (FramePacer.h) is drawn a few bands a turn of the event
        // loop and counts once whole; it is the same picture as a frame drawn at once.
        auto w = makeWindow(1);
        QVERIFY(w);
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(preview));

        FramePacer::setBudgetMs(3.0);
        const auto restore = qScopeGuard([] { FramePacer::setBudgetMs(30.0); });
        EventCounter paints(QEvent::Paint);
        preview->installEventFilter(&paints);
        int frames = preview->framesRendered();
        preview->setScene(preview->scene()); // a new frame of the same picture
        QVERIFY(waitForFrame(preview, frames));
        QCOMPARE(preview->framesRendered(), frames + 1);
        QVERIFY2(paints.count >= 4, qPrintable(QString::number(paints.count)));
        preview->removeEventFilter(&paints);
        // The same picture as drawn at once, offscreen at the same size.
        const QImage inBands = preview->grabFramebuffer();
        Result<Image> atOnce = preview->renderImage(preview->scene(), inBands.size());
        QVERIFY(atOnce);
        int differing = 0;
        for (int y = 0; y < inBands.height(); ++y)
            for (int x = 0; x < inBands.width(); ++x) {
                const QRgb c = inBands.pixel(x, y);
                const int rgb[3] = {qRed(c), qGreen(c), qBlue(c)};
                for (int k = 0; k < 3; ++k)
                    differing += std::abs(std::lround(atOnce->at(x, y, k) * 255.0f) - rgb[k]) > 1;
            }
        QCOMPARE(differing, 0);
    }

    // A view's figures come and go (a new frame says "measuring the error…") and their text
    // changes length; the views keep their size, so no frame restarts for a text.
    void figuresDoNotResizeTheViews() {
        auto w = makeWindow(2);
        QVERIFY(w);
        std::array<PreviewWidget*, 2> previews{};
        for (int i = 0; i < 2; ++i) {
            previews[i] = w->viewports()->viewport(i)->preview();
            QVERIFY(waitForFigures(previews[i]));
        }
        QTest::qWait(0); // the layout settles once with the first figures' room reserved
        EventCounter resizes(QEvent::Resize);
        const QSize sizes[2] = {previews[0]->size(), previews[1]->size()};
        for (PreviewWidget* p : previews)
            p->installEventFilter(&resizes);
        // New figures in one view, then in both with a deeper relief.
        PreviewScene heat = previews[0]->scene();
        heat.overlays.heatMap = true;
        previews[0]->setScene(heat);
        QVERIFY(waitForFigures(previews[0]));
        w->document()->edit("deeper", [](DocumentState& s) { s.material.heightScale = 0.2f; });
        for (PreviewWidget* p : previews)
            QVERIFY(waitForFigures(p));
        QCoreApplication::processEvents();
        for (PreviewWidget* p : previews)
            p->removeEventFilter(&resizes);
        QCOMPARE(resizes.count, 0);
        QCOMPARE(previews[0]->size(), sizes[0]);
        QCOMPARE(previews[1]->size(), sizes[1]);
        for (int i = 0; i < 2; ++i) {
            // The figures are not cut off: their room holds their text at the view's width.
            auto* figures = w->viewports()->viewport(i)->findChild<QLabel*>("figures");
            QVERIFY(figures);
            // Cut to the view's width, whole in the figures' text and tooltip.
            const QString whole = w->viewports()->viewport(i)->statsText();
            QVERIFY2(whole.contains(QLatin1String("another surface")), qPrintable(whole));
            QVERIFY(figures->toolTip().contains(QLatin1String("another surface")));
            QVERIFY2(figures->heightForWidth(figures->width()) <= figures->height(),
                     qPrintable(QStringLiteral("%1 px of text in %2 px")
                                    .arg(figures->heightForWidth(figures->width()))
                                    .arg(figures->height())));
            // Nor does their text set how narrow the view may be: the header does.
            Viewport* viewport = w->viewports()->viewport(i);
            const int narrowest = viewport->minimumSizeHint().width();
            const QString text = figures->text();
            figures->setText(QString(400, QLatin1Char('8')));
            QCOMPARE(viewport->minimumSizeHint().width(), narrowest);
            figures->setText(text);
        }
    }

    // A view never waits on input to finish a frame: with the steps it had lined up lost
    // mid-frame (its timers stopped, as a paint request the platform dropped left a view on its
    // stand-in, "measuring the error…", for 55 s until the mouse moved), the frame and its figures
    // still complete, with no input event and nothing asking it to paint.
    void aFrameCompletesWithNoInput() {
        auto w = makeWindow(1, 256);
        QVERIFY(w);
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(preview));
        FramePacer::setBudgetMs(1.0); // a frame over many turns
        const auto restore = qScopeGuard([] { FramePacer::setBudgetMs(30.0); });
        const int frames = preview->framesRendered();
        w->document()->edit("deeper", [](DocumentState& s) { s.material.heightScale = 0.11f; });
        QTRY_VERIFY_WITH_TIMEOUT(!preview->frameComplete(), 30000); // the frame is under way
        for (QTimer* timer : preview->findChildren<QTimer*>())
            timer->stop();
        QVERIFY(!preview->stats().valid);
        QVERIFY2(QTest::qWaitFor(
                     [&] { return preview->framesRendered() > frames && preview->stats().valid; },
                     60000),
                 "the frame stopped where its next step was lost");
        QVERIFY(preview->frameComplete());
    }

    void figuresAreMeasuredInSlices() {
        auto w = makeWindow(1);
        QVERIFY(w);
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(preview));
        auto equal = [](const PreviewStats& a, const PreviewStats& b) {
            return a.valid && b.valid && a.pixels == b.pixels && a.steepPixels == b.steepPixels &&
                   a.fetchesPerPixel == b.fetchesPerPixel && a.meanError == b.meanError &&
                   a.p99Error == b.p99Error && a.maxError == b.maxError &&
                   a.otherSurface == b.otherSurface;
        };
        preview->setScene(preview->scene()); // measured again, the window settled
        QVERIFY(waitForFigures(preview));
        const PreviewStats whole = preview->stats();
        QVERIFY(whole.pixels > 0);

        PreviewWidget::setMeasureSliceMs(0.0); // a box per slice
        const auto restore = qScopeGuard([] { PreviewWidget::setMeasureSliceMs(30.0); });
        const int before = preview->measureSlices();
        preview->setScene(preview->scene());
        QVERIFY(waitForFigures(preview));
        QVERIFY2(preview->measureSlices() - before >= 2 * 24, // 24 sample boxes, two passes
                 qPrintable(QString::number(preview->measureSlices() - before)));
        auto text = [](const PreviewStats& a) {
            return QString("%1 px, %2 steep, %3 fetches, mean %4, p99 %5, max %6, %7 other")
                .arg(a.pixels)
                .arg(a.steepPixels)
                .arg(a.fetchesPerPixel, 0, 'g', 9)
                .arg(a.meanError, 0, 'g', 9)
                .arg(a.p99Error, 0, 'g', 9)
                .arg(a.maxError, 0, 'g', 9)
                .arg(a.otherSurface);
        };
        QVERIFY2(equal(preview->stats(), whole),
                 qPrintable(text(preview->stats()) + " in slices, " + text(whole) + " at once"));

        // Half-way through, the heat map goes on: measured over every pixel, from the start.
        const int started = preview->measureSlices();
        preview->setScene(preview->scene());
        QVERIFY(QTest::qWaitFor([&] { return preview->measureSlices() >= started + 30; }));
        QVERIFY(!preview->stats().valid);
        PreviewScene heat = preview->scene();
        heat.overlays.heatMap = true;
        preview->setScene(heat);
        QVERIFY(waitForFigures(preview));
        const PreviewStats interrupted = preview->stats();
        QVERIFY(interrupted.pixels > whole.pixels);
        PreviewWidget::setMeasureSliceMs(30.0);
        preview->setScene(heat);
        QVERIFY(waitForFigures(preview));
        QVERIFY2(equal(preview->stats(), interrupted),
                 qPrintable(text(preview->stats()) + ", " + text(interrupted) + " interrupted"));
    }

    // The worker does not upload maps nobody wants: maps replaced while their upload waits for
    // it are skipped and the replacing ones go up next (before, the worker uploaded both in
    // turn); a view closed while its maps go up does not wait for the worker (1.1-1.4 s at 8192²
    // on llvmpipe), and the upload it abandoned is skipped too.
    void abandonedUploadsAreNotRun() {
        PreviewRenderer::setBackgroundUploadTexels(0);
        const auto restore = qScopeGuard([] {
            MapUpload::holdWorkers(false);
            PreviewRenderer::setBackgroundUploadTexels(4096u * 4096u);
        });
        auto w = makeWindow(1);
        QVERIFY(w);
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(preview));
        int completed = MapUpload::completed(), skipped = MapUpload::skipped();
        MapUpload::holdWorkers(true);
        const std::string first = writeRamp(m_dir, "first_height.png", 128);
        const std::string second = writeRamp(m_dir, "second_height.png", 96);
        const std::string third = writeRamp(m_dir, "closed_height.png", 256);
        QVERIFY(!first.empty() && !second.empty() && !third.empty());
        QVERIFY(w->loadMap(MapKind::Height, QString::fromStdString(first)));
        QVERIFY(QTest::qWaitFor([&] { return preview->uploading(); }));
        const int frames = preview->framesRendered();
        QVERIFY(w->loadMap(MapKind::Height, QString::fromStdString(second)));
        // A frame of the second maps (the sample's standing in) drops the first upload.
        QVERIFY(waitForFrame(preview, frames));
        QVERIFY(preview->uploading());
        MapUpload::holdWorkers(false);
        QTRY_COMPARE(MapUpload::skipped(), skipped + 1);
        QVERIFY(waitForFigures(preview));
        QCOMPARE(MapUpload::completed(), completed + 1);
        QCOMPARE(preview->gpuMaterial()->heightField().width, 96);

        completed = MapUpload::completed();
        skipped = MapUpload::skipped();
        MapUpload::holdWorkers(true);
        QVERIFY(w->loadMap(MapKind::Height, QString::fromStdString(third)));
        QVERIFY(QTest::qWaitFor([&] { return preview->uploading(); }));
        w.reset(); // the worker is held: this returns at once only if it does not wait for it
        QCOMPARE(MapUpload::completed(), completed);
        MapUpload::holdWorkers(false);
        QTRY_COMPARE(MapUpload::skipped(), skipped + 1);
        QCOMPARE(MapUpload::completed(), completed);
    }

    // A row makes its thumbnail when its map changes, not on every edit of the material (an
    // 8192² map's thumbnail reads 64 M texels).
    void thumbnailsFollowTheirMapsOnly() {
        auto w = makeWindow();
        QVERIFY(w);
        const int start = MapRow::thumbnailsMade();
        w->document()->edit("scale", [](DocumentState& s) { s.material.heightScale *= 1.5f; });
        w->document()->edit("scale", [](DocumentState& s) { s.material.heightScale *= 0.5f; });
        QCOMPARE(MapRow::thumbnailsMade(), start);
        w->startBake(BakeKind::Cone);
        QTRY_VERIFY_WITH_TIMEOUT(!w->baker()->isBusy(), 60000);
        QVERIFY(w->document()->state().hasMap(MapKind::Cone));
        QCOMPARE(MapRow::thumbnailsMade(), start + 1); // the cone map's alone
        const std::string ramp = writeRamp(m_dir, "thumb_height.png", 32);
        QVERIFY(!ramp.empty());
        QVERIFY(w->loadMap(MapKind::Height, QString::fromStdString(ramp)));
        QTRY_VERIFY(MapRow::thumbnailsMade() > start + 1); // the new height map's

        // A map over 1024² texels gets its thumbnail from a worker: not in the edit, after it,
        // the same picture.
        Image albedo(1500, 1000, 3);
        for (int y = 0; y < albedo.height; ++y)
            for (int x = 0; x < albedo.width; ++x)
                for (int c = 0; c < 3; ++c)
                    albedo.at(x, y, c) = float((x / 7 + y / 5 + c) % 4) / 3.0f;
        const int before = MapRow::thumbnailsMade();
        w->document()->edit("albedo", [&](DocumentState& s) {
            auto assets = std::make_shared<MaterialAssets>(*s.assets);
            assets->albedo = albedo;
            s.assets = assets;
        });
        QCOMPARE(MapRow::thumbnailsMade(), before);
        QTRY_COMPARE(MapRow::thumbnailsMade(), before + 1);
        auto* thumbnail = w->mapsPanel()->row(MapKind::Albedo)->findChild<QLabel*>("thumbnail");
        QVERIFY(thumbnail);
        const QImage shown = thumbnail->pixmap().toImage();
        const int side = shown.width();
        const QImage expected =
            toQImage(albedo, side)
                .scaled(side, side, Qt::KeepAspectRatio, Qt::SmoothTransformation);
        QCOMPARE(shown.convertToFormat(QImage::Format_RGB32),
                 expected.convertToFormat(QImage::Format_RGB32));
    }

    // The bake's line says how long the user waited for its map, not only the bake: from Bake
    // to the view drawn with it (a baked normal map needs the view's normal-map shader variant,
    // compiled then: far longer than the bake at this size).
    void bakeTimeSaysTheWait() {
        auto w = makeWindow(1);
        QVERIFY(w);
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(preview));
        QVERIFY(!w->document()->state().hasMap(MapKind::Normal));
        QElapsedTimer clock;
        clock.start();
        w->startBake(BakeKind::Normal);
        const QRegularExpression line("Baked the normal map in ([0-9.]+) s on the CPU, shown "
                                      "([0-9.]+) s after Bake\\.");
        QRegularExpressionMatch m;
        QTRY_VERIFY_WITH_TIMEOUT((m = line.match(w->mapsPanel()->bakeStatus())).hasMatch(), 60000);
        const double elapsed = clock.elapsed() / 1000.0;
        const double bake = m.captured(1).toDouble(), shown = m.captured(2).toDouble();
        qInfo("normal map baked in %.2f s, shown %.2f s after Bake (%.2f s here)", bake, shown,
              elapsed);
        QVERIFY(w->document()->state().hasMap(MapKind::Normal));
        QVERIFY(bake <= shown);
        QVERIFY(shown <= elapsed + 0.01); // the line came after the frame it names
        QVERIFY(preview->framesRendered() > 0 && !preview->uploading());
        QVERIFY(w->statusBar()->currentMessage().contains(m.captured(0).chopped(1)));
    }

    // A variant the view's context never drew waits while the user acts (its first draw holds
    // the event loop while llvmpipe compiles it: after Ctrl+4, clicks waited for three views'
    // variants in turn), and is drawn once input pauses. The pacer's clock stands still here
    // but for the steps the test makes.
    void newVariantsWaitForTheUserToPause() {
        auto w = makeWindow(1);
        QVERIFY(w);
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(preview));
        double now = 1000.0;
        FramePacer::setClock([&now] { return now; });
        const auto restore = qScopeGuard([] { FramePacer::setClock({}); });
        FramePacer::noteInput(); // a click, as the user goes on
        const std::size_t compiled = preview->shaderCache()->size();
        const int frames = preview->framesRendered();
        w->document()->edit("secant", [](DocumentState& s) {
            s.setView(0, {Technique::Secant, info(Technique::Secant).defaults});
        });
        // A turn of the event loop 20 ms on: past the breath after the last (FramePacer).
        auto turn = [&] {
            now += 20.0;
            preview->repaint();
            QCoreApplication::processEvents(); // the turn ends
        };
        for (int i = 0; i < 8; ++i) // 160 ms of turns
            turn();
        QCOMPARE(preview->framesRendered(), frames);
        QCOMPARE(preview->shaderCache()->size(), compiled); // not even compiled
        now += FramePacer::kInputQuietMs;
        // Turns back to back (qWaitFor would sleep 10 ms between them). The test's clock sees no
        // draw cost, which limits no band (FramePacer): the frame is whole within a few turns
        // (it took ~400, a row a turn, before the pacer took a cost of 0 for what it is).
        int turns = 0;
        for (; turns < 20 && preview->framesRendered() <= frames; ++turns)
            turn();
        qInfo("the new variant's first whole frame came %d turns after the pause", turns);
        QVERIFY(preview->framesRendered() > frames);
        QVERIFY(preview->shaderCache()->size() > compiled);
    }

    // Every view draws with one cache of compiled variants (their contexts share programs): a
    // second view on the same technique compiles nothing (each view compiled its own before, on
    // the GUI thread: llvmpipe takes hundreds of ms a variant).
    void viewsShareCompiledVariants() {
        auto w = makeWindow(1);
        QVERIFY(w);
        PreviewWidget* first = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(first));
        const ShaderCache* cache = first->shaderCache();
        QVERIFY(cache && cache->size() > 0);
        const std::size_t compiled = cache->size();
        w->document()->edit("same technique", [](DocumentState& s) { s.setView(1, s.view(0)); });
        w->viewports()->setLayoutCount(2);
        PreviewWidget* second = w->viewports()->viewport(1)->preview();
        QVERIFY(waitForFigures(second));
        QCOMPARE(second->shaderCache(), cache);
        QCOMPARE(cache->size(), compiled);
    }

    // The built-in sample is 16-bit, as most artists' maps are: loading one keeps the height
    // texture's format, so llvmpipe has no shader variant to compile at the first frame.
    void theSampleGoesUpAsR16() {
        auto w = makeWindow();
        QVERIFY(w);
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(preview));
        QVERIFY(preview->gpuMaterial() && preview->gpuMaterial()->heightIs16Bit());
    }

    void viewportsTraceDifferentTechniques() {
        auto w = makeWindow(2);
        QVERIFY(w);
        Viewport* left = w->viewports()->viewport(0);
        Viewport* right = w->viewports()->viewport(1);
        QVERIFY(waitForFigures(right->preview()));
        // Without self-shadow (its march has layers of its own).
        if (w->materialPanel()->selfShadow()->isChecked()) {
            w->materialPanel()->selfShadow()->setFocus();
            QTest::keyClick(w->materialPanel()->selfShadow(), Qt::Key_Space);
        }
        QVERIFY(!w->document()->material().selfShadow);
        // Type the technique's name into viewport 2's chooser.
        right->techniqueCombo()->setFocus();
        QTest::keyClicks(right->techniqueCombo(), "offset");
        QCOMPARE(w->document()->state().view(1).technique, Technique::Offset);
        QCOMPARE(w->document()->state().view(0).technique, Technique::Pom);
        QVERIFY(waitForFigures(right->preview()));
        QVERIFY(waitForFigures(left->preview()) || left->preview()->stats().valid);
        // The march has a layer count; offset limiting has none: different shaders.
        QVERIFY(left->preview()->uniformValue("pxMaxLayers").has_value());
        QVERIFY(!right->preview()->uniformValue("pxMaxLayers").has_value());
        const QImage a = left->preview()->grabFramebuffer();
        const QImage b = right->preview()->grabFramebuffer();
        QVERIFY2(changedPixels(a, b) > a.width() * a.height() / 100,
                 "pom and offset must not draw the same picture");
        // Offset limiting is far from exact where pom is close.
        QVERIFY(right->preview()->stats().meanError > left->preview()->stats().meanError);
        QVERIFY(right->statsText().contains(QLatin1String("offset")));
    }

    void dropLoadsMaps() {
        auto w = makeWindow();
        QVERIFY(w);
        const std::string ramp = writeRamp(m_dir, "wall_height.png", 32);
        QVERIFY(!ramp.empty());
        QVERIFY(dropFiles(w.get(), {QString::fromStdString(ramp)}));
        QCOMPARE(w->document()->state().assets->height.width, 32);
        QVERIFY(w->mapsPanel()->row(MapKind::Height)->sourceText().contains("wall_height.png"));
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(preview));
        QVERIFY(preview->renderError().isEmpty());

        // A file dropped on a map's row loads as that map, whatever its name.
        Image colour(32, 32, 3);
        for (float& p : colour.pixels)
            p = 0.5f;
        const std::string plain = m_dir.filePath("photo.png").toStdString();
        QVERIFY(writeImage(plain, colour, {}));
        QVERIFY(dropFiles(w->mapsPanel()->row(MapKind::Albedo), {QString::fromStdString(plain)}));
        QCOMPARE(w->document()->state().assets->albedo.width, 32);

        // A material dropped on the window opens.
        const std::string material = m_dir.filePath("dropped.json").toStdString();
        Material m;
        m.name = "dropped";
        m.maps.height = "wall_height.png";
        m.heightScale = 0.02f;
        QVERIFY(saveMaterial(m, material));
        w->document()->reset(w->document()->state(), {}); // nothing unsaved to ask about
        QVERIFY(dropFiles(w.get(), {QString::fromStdString(material)}));
        QCOMPARE(w->document()->material().heightScale, 0.02f);
        QCOMPARE(QFileInfo(w->document()->filePath()).fileName(), QString("dropped.json"));
    }

    void bakingAConeMapEnablesCone() {
        auto w = makeWindow();
        QVERIFY(w);
        TechniqueCombo* combo = w->viewports()->viewport(0)->techniqueCombo();
        QVERIFY(!combo->isAvailable(Technique::Cone));
        QVERIFY(!w->techniquePanel()->techniqueCombo()->isAvailable(Technique::Cone));
        QToolButton* bake = w->mapsPanel()->row(MapKind::Cone)->bakeButton();
        QVERIFY(bake && bake->isEnabled());
        QTest::mouseClick(bake, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!w->baker()->isBusy(), 60000);
        QVERIFY(w->document()->state().hasMap(MapKind::Cone));
        QVERIFY(w->document()->state().isUnsaved(MapKind::Cone));
        QVERIFY(combo->isAvailable(Technique::Cone));
        QVERIFY(w->techniquePanel()->techniqueCombo()->isAvailable(Technique::Cone));
        QCOMPARE(w->mapsPanel()->progressBar()->value(), 100);

        combo->setFocus();
        QTest::keyClicks(combo, "cone");
        QCOMPARE(w->document()->material().technique, Technique::Cone);
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(preview));
        QVERIFY2(preview->renderError().isEmpty(), qPrintable(preview->renderError()));
        QVERIFY(preview->uniformValue("pxMaxSteps").has_value());
        // The bake is one undo step: undoing it takes the cone technique away again.
        w->document()->undoStack()->undo(); // the technique
        w->document()->undoStack()->undo(); // the bake
        QVERIFY(!w->document()->state().hasMap(MapKind::Cone));
        QVERIFY(!combo->isAvailable(Technique::Cone));
    }

    // Cone bakes chosen on the GPU (a context sharing the viewports', on the bake's worker) give
    // the CPU's map; the view keeps drawing while they run (dispatches of a few milliseconds).
    void coneBakesRunOnTheGpuWhileTheViewDraws() {
        auto w = makeWindow(1, 512);
        QVERIFY(w);
        // llvmpipe: a software rasteriser, which Automatic leaves alone; the artist's choice.
        QAction* gpu = nullptr;
        for (QAction* a : w->findChild<QMenu*>("bake-device")->actions())
            if (a->data().toInt() == static_cast<int>(BakeDevicePreference::Gpu))
                gpu = a;
        QVERIFY(gpu);
        gpu->trigger();
        QCOMPARE(w->baker()->devicePreference(), BakeDevicePreference::Gpu);
        const auto automatic =
            qScopeGuard([] { saveBakeDevicePreference(BakeDevicePreference::Automatic); });
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(preview));
        std::vector<BakeOutcome> finished;
        connect(w->baker(), &BakeRunner::finished, this,
                [&finished](const BakeOutcome& o) { finished.push_back(o); });
        std::vector<double> progress; // reported between the GPU's slices, in order
        connect(w->baker(), &BakeRunner::progress, this,
                [&progress](BakeKind, double f) { progress.push_back(f); });
        QString said; // every status bar message, one a line
        connect(w->statusBar(), &QStatusBar::messageChanged, this,
                [&said](const QString& message) { said += message + '\n'; });
        w->startBake(BakeKind::RelaxedCone);
        QVERIFY(w->baker()->isBusy());
        const int before = preview->framesRendered();
        QTRY_VERIFY_WITH_TIMEOUT(
            (preview->update(), preview->framesRendered() >= before + 3 || !w->baker()->isBusy()),
            60000);
        QVERIFY2(w->baker()->isBusy(), "the bake ended before the view drew three frames");
        QTRY_VERIFY_WITH_TIMEOUT(!w->baker()->isBusy(), 120000);
        QCOMPARE(finished.size(), std::size_t(1));
        const BakeOutcome& outcome = finished.front();
        QVERIFY2(outcome.error.isEmpty(), qPrintable(outcome.error));
        QVERIFY2(!outcome.gpu.isEmpty(), "the relaxed cone map was not baked on the GPU");
        QVERIFY(progress.size() >= 3);
        QVERIFY(std::is_sorted(progress.begin(), progress.end()));
        QVERIFY(progress.front() < 0.5 && progress.back() > 0.9);
        ConeMap cpu =
            bakeConeMap(outcome.request.source->height, outcome.request.wrap, ConeKind::Relaxed);
        quantiseDown(cpu, 65535);
        QVERIFY(outcome.cone.sqrtRatio == cpu.sqrtRatio);
        // Said once the view has drawn the new map (the wait the artist saw, with where it baked),
        // for 8 s: the messages are kept as they come (the CPU's bake above can take longer).
        const QRegularExpression line("on the GPU \\(.+\\), shown [0-9.]+ s after Bake");
        QTRY_VERIFY_WITH_TIMEOUT((preview->update(), said.contains(line)), 60000);
        // The panel's line says so too, naming the renderer.
        QVERIFY2(w->mapsPanel()->bakeStatus().contains(" s on the GPU (" + outcome.gpu +
                                                       ", as chosen in Bake ▸ Device), shown "),
                 qPrintable(w->mapsPanel()->bakeStatus()));
    }

    // Left to itself the editor bakes cones on the faster device: under llvmpipe (a software
    // rasteriser) the CPU, and the line says why; a window opened later keeps the choice made.
    void coneBakesRunOnTheCpuUnderASoftwareRasteriser() {
        saveBakeDevicePreference(BakeDevicePreference::Automatic);
        auto w = makeWindow(1, 128);
        QVERIFY(w);
        QCOMPARE(w->baker()->devicePreference(), BakeDevicePreference::Automatic);
        QVERIFY2(probeOpenGl().software(), qPrintable(probeOpenGl().renderer)); // Xvfb: llvmpipe
        std::vector<BakeOutcome> finished;
        connect(w->baker(), &BakeRunner::finished, this,
                [&finished](const BakeOutcome& o) { finished.push_back(o); });
        w->startBake(BakeKind::Cone);
        QTRY_VERIFY_WITH_TIMEOUT(!w->baker()->isBusy(), 120000);
        QCOMPARE(finished.size(), std::size_t(1));
        const BakeOutcome& outcome = finished.front();
        QVERIFY2(outcome.error.isEmpty(), qPrintable(outcome.error));
        QVERIFY2(outcome.gpu.isEmpty(), qPrintable(outcome.gpu));
        QVERIFY(!outcome.request.device.gpu);
        const QString expected =
            QString(" s on the CPU (the GPU, %1, is a software rasteriser: the CPU bakes faster)")
                .arg(probeOpenGl().renderer);
        QTRY_VERIFY_WITH_TIMEOUT((w->viewports()->viewport(0)->preview()->update(),
                                  w->mapsPanel()->bakeStatus().contains(expected)),
                                 60000);
        // The CPU chosen in the menu is kept for the next window.
        for (QAction* a : w->findChild<QMenu*>("bake-device")->actions())
            if (a->data().toInt() == static_cast<int>(BakeDevicePreference::Cpu))
                a->trigger();
        QCOMPARE(savedBakeDevicePreference(), BakeDevicePreference::Cpu);
        auto again = makeWindow(1, 32);
        QVERIFY(again);
        QCOMPARE(again->baker()->devicePreference(), BakeDevicePreference::Cpu);
        saveBakeDevicePreference(BakeDevicePreference::Automatic);
    }

    void cancelledBakeChangesNothing() {
        auto w = makeWindow(1, 768);
        QVERIFY(w);
        const int steps = w->document()->undoStack()->count();
        w->startBake(BakeKind::RelaxedCone);
        QVERIFY(w->baker()->isBusy());
        QVERIFY(w->mapsPanel()->cancelButton()->isEnabled());
        QTest::mouseClick(w->mapsPanel()->cancelButton(), Qt::LeftButton);
        // Said at once, and the button cannot be pressed again while the bake stops.
        QVERIFY2(w->mapsPanel()->bakeStatus().startsWith("Cancelling the relaxed cone"),
                 qPrintable(w->mapsPanel()->bakeStatus()));
        QVERIFY(!w->mapsPanel()->cancelButton()->isEnabled());
        QTRY_VERIFY_WITH_TIMEOUT(!w->baker()->isBusy(), 60000);
        QVERIFY(w->mapsPanel()->bakeStatus().contains("cancelled"));
        QVERIFY(!w->document()->state().hasMap(MapKind::RelaxedCone));
        QCOMPARE(w->document()->undoStack()->count(), steps);
        QVERIFY(w->lastProblem().isEmpty());
    }

    void undoRestoresThePreviousState() {
        auto w = makeWindow();
        QVERIFY(w);
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(preview));
        MaterialDocument* doc = w->document();
        const std::string json = materialToJson(doc->material());
        const auto assets = doc->state().assets;

        QSlider* slider = w->materialPanel()->heightScale()->slider();
        slider->setFocus();
        QTest::keyClick(slider, Qt::Key_PageUp);
        QTest::keyClick(slider, Qt::Key_PageUp);
        const bool shadow = doc->material().selfShadow;
        w->materialPanel()->selfShadow()->setFocus();
        QTest::keyClick(w->materialPanel()->selfShadow(), Qt::Key_Space);
        QCOMPARE(doc->material().selfShadow, !shadow);
        const std::string ramp = writeRamp(m_dir, "undo_height.png", 16);
        QVERIFY(dropFiles(w.get(), {QString::fromStdString(ramp)}));
        QCOMPARE(doc->state().assets->height.width, 16);
        QVERIFY(doc->isDirty());
        QVERIFY(waitForFrame(preview, preview->framesRendered()));

        // Ctrl+Z until nothing is left: the sample as it was opened.
        // Shortcuts reach only the active window, and X hands activation over asynchronously
        // (a window closed by the test before can take it away late): wait for it per key.
        const auto press = [&w](QKeySequence::StandardKey key) {
            w->activateWindow();
            if (!QTest::qWaitForWindowActive(w.get()))
                return false;
            QTest::keySequence(w.get(), key);
            return true;
        };
        for (int i = 0; i < doc->undoStack()->count(); ++i)
            QVERIFY(press(QKeySequence::Undo));
        QCOMPARE(doc->undoStack()->index(), 0);
        QCOMPARE(materialToJson(doc->material()), json);
        QVERIFY(doc->state().assets == assets);
        QVERIFY(!doc->isDirty());
        QVERIFY(waitForFrame(preview, preview->framesRendered()));
        QCOMPARE(preview->uniformValue("pxScale").value_or(-1), 0.06f);
        QCOMPARE(w->materialPanel()->heightScale()->value(), 0.06);
        // And redo brings the last edit back.
        QVERIFY(press(QKeySequence::Redo));
        QCOMPARE(doc->undoStack()->index(), 1);
        QVERIFY(doc->material().heightScale > 0.06f);
    }

    void corruptFileShowsAnErrorAndChangesNothing() {
        auto w = makeWindow(1, 64, true);
        QVERIFY(w);
        MaterialDocument* doc = w->document();
        const std::string json = materialToJson(doc->material());
        const auto assets = doc->state().assets;
        const int steps = doc->undoStack()->count();
        const std::string bad = m_dir.filePath("broken_height.png").toStdString();
        QVERIFY(writeTextFile(bad, "not an image at all"));
        QVERIFY(dropFiles(w.get(), {QString::fromStdString(bad)}));

        QMessageBox* box = nullptr;
        QTRY_VERIFY((box = w->findChild<QMessageBox*>()) && box->isVisible());
        QVERIFY2(box->text().contains("broken_height.png"), qPrintable(box->text()));
        QCOMPARE(materialToJson(doc->material()), json);
        QVERIFY(doc->state().assets == assets);
        QCOMPARE(doc->undoStack()->count(), steps);
        QVERIFY(!doc->isDirty());
        box->close();

        // A corrupt material file: the same.
        const std::string badJson = m_dir.filePath("broken.json").toStdString();
        QVERIFY(writeTextFile(badJson, "{ \"format\": \"parallax-studio-material\", "));
        QVERIFY(dropFiles(w.get(), {QString::fromStdString(badJson)}));
        QVERIFY(w->lastProblem().contains("broken.json"));
        QVERIFY(doc->state().assets == assets);
        QVERIFY(doc->filePath().isEmpty());
    }

    void heatMapAndWipeDraw() {
        auto w = makeWindow();
        QVERIFY(w);
        Viewport* v = w->viewports()->viewport(0);
        PreviewWidget* preview = v->preview();
        QVERIFY(waitForFigures(preview));
        const QImage plain = preview->grabFramebuffer();
        QTest::mouseClick(v->heatMapButton(), Qt::LeftButton);
        QVERIFY(preview->scene().overlays.heatMap);
        QVERIFY(waitForFigures(preview));
        const QImage heat = preview->grabFramebuffer();
        // The legend's labels read upright: the grab matches them as drawn (0.996 on llvmpipe;
        // 0.52 when the GL paint engine's glyphs came out upside down after the renderer), and
        // better than mirrored top to bottom.
        const double upright = legendLabelMatch(preview, heat, false);
        const double flipped = legendLabelMatch(preview, heat, true);
        QVERIFY2(
            upright > 0.9 && upright > flipped + 0.2,
            qPrintable(
                QStringLiteral("labels match %1 upright, %2 flipped").arg(upright).arg(flipped)));
        QVERIFY2(changedPixels(plain, heat) > plain.width() * plain.height() / 10,
                 qPrintable(QStringLiteral("%1 of %2 pixels changed; %3 pixels measured, error %4")
                                .arg(changedPixels(plain, heat))
                                .arg(plain.width() * plain.height())
                                .arg(preview->stats().pixels)
                                .arg(preview->renderError())));
        QTest::mouseClick(v->heatMapButton(), Qt::LeftButton);
        QTest::mouseClick(v->wipeButton(), Qt::LeftButton);
        QVERIFY(preview->scene().overlays.wipe);
        QVERIFY(v->wipeCombo()->isVisible());
        QVERIFY(waitForFigures(preview));
        QVERIFY2(preview->renderError().isEmpty(), qPrintable(preview->renderError()));
    }

    void everyMeshDraws() {
        auto w = makeWindow();
        QVERIFY(w);
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(preview));
        QImage last = preview->grabFramebuffer();
        QComboBox* mesh = w->viewPanel()->mesh();
        mesh->setFocus();
        for (const char* name : {"cube", "sphere", "cylinder"}) {
            QTest::keyClick(mesh, Qt::Key_Down); // the next mesh in the list
            QCOMPARE(mesh->currentText(), QString(name));
            QVERIFY(preview->scene().view.mesh == parseMeshKind(name));
            QVERIFY(waitForFigures(preview));
            QVERIFY2(preview->renderError().isEmpty(), qPrintable(preview->renderError()));
            QVERIFY(preview->stats().pixels > 0);
            const QImage now = preview->grabFramebuffer();
            QVERIFY(changedPixels(last, now) > now.width() * now.height() / 20);
            last = now;
        }
    }

    // Compare's GPU milliseconds come from the GPU that draws the viewports: a context shared
    // with theirs (Qt shares only within one device and driver), on the bench's worker thread.
    void compareTimesOnTheViewportsGpu() {
        auto w = makeWindow(1, 32);
        QVERIFY(w);
        QVERIFY(QOpenGLContext::globalShareContext());
        ComparePanel* compare = w->comparePanel();
        compare->parentWidget()->show();
        compare->raysField()->setValue(8);
        QSignalSpy finished(compare, &ComparePanel::finished);
        QTest::mouseClick(compare->runButton(), Qt::LeftButton);
        QVERIFY(compare->isRunning());
        QVERIFY(finished.wait(120000));
        QVERIFY(compare->chart().has_value());
        QCOMPARE(compare->chart()->axes.back(), CostAxis::GpuTime);
        const QString status = compare->statusText();
        QVERIFY2(status.contains("the editor's OpenGL context (shared with the viewports)"),
                 qPrintable(status));
        QVERIFY2(status.contains(probeOpenGl().renderer), qPrintable(status));
    }

    void ctrlDragMovesTheLightOfLinkedViews() {
        auto w = makeWindow(2);
        QVERIFY(w);
        PreviewWidget* left = w->viewports()->viewport(0)->preview();
        const float before = left->scene().view.light.azimuthDeg;
        const QPoint c = left->rect().center();
        QTest::mousePress(left, Qt::LeftButton, Qt::ControlModifier, c);
        QTest::mouseMove(left, c + QPoint(80, 0));
        QTest::mouseRelease(left, Qt::LeftButton, Qt::ControlModifier, c + QPoint(80, 0));
        const float after = left->scene().view.light.azimuthDeg;
        QVERIFY(std::abs(after - before) > 5.0f);
        QCOMPARE(w->viewports()->viewport(1)->view().light.azimuthDeg, after);
        // The keyboard does the same: Ctrl+arrows move the light, arrows orbit.
        left->setFocus();
        QTest::keyClick(left, Qt::Key_Left, Qt::ControlModifier);
        QCOMPARE(left->scene().view.light.azimuthDeg, after - 10.0f);
        const float orbitBefore = left->scene().view.camera.azimuthDeg;
        QTest::keyClick(left, Qt::Key_Right);
        QVERIFY(std::abs(left->scene().view.camera.azimuthDeg - orbitBefore) > 5.0f);
        // Unlinked, a plain drag orbits only its own view.
        w->viewports()->setLinked(false);
        const float camera = w->viewports()->viewport(1)->view().camera.azimuthDeg;
        QTest::mousePress(left, Qt::LeftButton, Qt::NoModifier, c);
        QTest::mouseMove(left, c + QPoint(60, 0));
        QTest::mouseRelease(left, Qt::LeftButton, Qt::NoModifier, c + QPoint(60, 0));
        QVERIFY(left->scene().view.camera.azimuthDeg != camera);
        QCOMPARE(w->viewports()->viewport(1)->view().camera.azimuthDeg, camera);
    }
};

QTEST_MAIN(StudioWindowTest)
#include "StudioWindowTest.moc"
