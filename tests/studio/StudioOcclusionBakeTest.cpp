// Bake ▸ Ambient Occlusion in the editor: the occlusion map is baked in the background from the
// height map at the panel's distance, equal to the core's bake texel for texel, one undo step; the
// Maps panel says it was baked and with what distance (and when it no longer matches the height
// scale); the preview draws with it (darker than without); Cancel leaves the material unchanged.

#include "StudioTestSupport.h"
#include "jobs/BakeRunner.h"
#include "jobs/Baking.h"
#include "panels/MapRow.h"
#include "panels/MapsPanel.h"
#include "parallax/bake/OcclusionBaker.h"
#include "parallax/image/ImageFile.h"
#include "parallax/render/GpuMaterial.h"
#include "widgets/FileDialogs.h"

#include <QDoubleSpinBox>
#include <QProgressBar>
#include <QPushButton>
#include <QStatusBar>
#include <QToolButton>
#include <QUndoStack>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;

namespace {

// The summed brightness of a grab.
double brightness(const QImage& image) {
    const QImage rgb = image.convertToFormat(QImage::Format_RGB32);
    double sum = 0.0;
    for (int y = 0; y < rgb.height(); ++y) {
        const auto* row = reinterpret_cast<const QRgb*>(rgb.constScanLine(y));
        for (int x = 0; x < rgb.width(); ++x)
            sum += qGray(row[x]);
    }
    return sum;
}

} // namespace

class StudioOcclusionBakeTest : public GlWindowTest {
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY(glReady()); }

    void bakeFillsTheOcclusionMap() {
        auto w = makeWindow();
        QVERIFY(w);
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        QVERIFY(waitForFigures(preview));
        const QImage before = preview->grabFramebuffer();
        MapRow* row = w->mapsPanel()->row(MapKind::Ao);
        QCOMPARE(row->sourceText(), QString("none"));
        w->mapsPanel()->occlusionDistanceBox()->setValue(0.25);
        QToolButton* bake = row->bakeButton();
        QVERIFY(bake && bake->isEnabled());
        const int steps = w->document()->undoStack()->count();
        QTest::mouseClick(bake, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!w->baker()->isBusy(), 60000);
        QCOMPARE(w->mapsPanel()->progressBar()->value(), 100);

        // The core's bake of the same surface, texel for texel.
        const DocumentState& state = w->document()->state();
        QVERIFY(state.hasMap(MapKind::Ao));
        QVERIFY(state.isUnsaved(MapKind::Ao));
        OcclusionBakeOptions options;
        options.heightScale = state.material.heightScale;
        options.wrap = state.material.wrap;
        options.distance = 0.25;
        Result<OcclusionMaps> expected =
            bakeOcclusion(state.assets->height, options, OcclusionOutputs::AmbientOcclusion);
        QVERIFY(expected.ok());
        QVERIFY(state.assets->ao.pixels == expected->occlusion.pixels);
        QCOMPARE(w->document()->undoStack()->count(), steps + 1);

        // The panel says so, with the distance and directions.
        QVERIFY2(row->sourceText().contains(QString("baked here: distance 0.25 uv, %1 directions")
                                                .arg(occlusionDirections(options))),
                 qPrintable(row->sourceText()));
        QVERIFY(row->warningText().isEmpty());

        // The preview draws with it: its material has the surface map and the frame is darker.
        QTRY_VERIFY_WITH_TIMEOUT(preview->gpuMaterial() &&
                                     preview->gpuMaterial()->hasSurfaceMap() &&
                                     !preview->uploading(),
                                 30000);
        QVERIFY(waitForFigures(preview));
        const QImage after = preview->grabFramebuffer();
        QVERIFY2(brightness(after) < brightness(before),
                 qPrintable(QString("%1 >= %2").arg(brightness(after)).arg(brightness(before))));
        QVERIFY(changedPixels(before, after) > 0);

        // Another height scale: the panel says the bake is out of date.
        w->document()->edit("scale", [](DocumentState& s) { s.material.heightScale *= 2.0f; });
        QVERIFY2(row->warningText().startsWith("Out of date: baked at height scale"),
                 qPrintable(row->warningText()));
        w->document()->undoStack()->undo(); // the scale
        QVERIFY(row->warningText().isEmpty());

        // One undo step: undone, the material has no occlusion map again; redone, the same one.
        w->document()->undoStack()->undo();
        QVERIFY(!w->document()->state().hasMap(MapKind::Ao));
        QCOMPARE(row->sourceText(), QString("none"));
        w->document()->undoStack()->redo();
        QVERIFY(w->document()->state().assets->ao.pixels == expected->occlusion.pixels);
    }

    // Unlimited by default; cancelled, nothing changes and the panel says so.
    void cancelLeavesTheMaterialAsItWas() {
        auto w = makeWindow(1, 512);
        QVERIFY(w);
        QCOMPARE(w->mapsPanel()->occlusionDistance(), std::numeric_limits<double>::infinity());
        const int steps = w->document()->undoStack()->count();
        w->startBake(BakeKind::Occlusion);
        QVERIFY(w->baker()->isBusy());
        QVERIFY(w->mapsPanel()->cancelButton()->isEnabled());
        QTest::mouseClick(w->mapsPanel()->cancelButton(), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(!w->baker()->isBusy(), 60000);
        // A 512² bake takes far longer than the click after it: it is always cancelled.
        QCOMPARE(w->mapsPanel()->bakeStatus(),
                 QString("The ambient occlusion map bake was cancelled."));
        QVERIFY(!w->document()->state().hasMap(MapKind::Ao));
        QCOMPARE(w->document()->undoStack()->count(), steps);
        QCOMPARE(w->mapsPanel()->progressBar()->value(), 0);
    }

    // Bake > Bent Normal Map: the occlusion map fills the material's, the bent normals go to the
    // file the user names (16-bit), equal to the core's bake within the file's rounding.
    void bentNormalsAreSavedToAFile() {
        auto w = makeWindow();
        QVERIFY(w);
        QString file = m_dir.filePath("bent.png");
        const DialogRunner previous =
            setDialogRunner([file](QFileDialog&) { return QString(file); });
        w->startBake(BakeKind::BentNormal);
        QTRY_VERIFY_WITH_TIMEOUT(!w->baker()->isBusy(), 60000);
        setDialogRunner(previous);
        const DocumentState& state = w->document()->state();
        OcclusionBakeOptions options;
        options.heightScale = state.material.heightScale;
        options.wrap = state.material.wrap;
        options.green = state.material.normalGreen;
        Result<OcclusionMaps> expected =
            bakeOcclusion(state.assets->height, options, OcclusionOutputs::Both);
        QVERIFY(expected.ok());
        QVERIFY(state.assets->ao.pixels == expected->occlusion.pixels);
        Result<Image> saved = readImage(file.toStdString());
        QVERIFY2(saved.ok(), saved.ok() ? "" : saved.error().message.c_str());
        QCOMPARE(saved->channels, 3);
        QCOMPARE(saved->pixels.size(), expected->bentNormals.pixels.size());
        for (std::size_t i = 0; i < saved->pixels.size(); ++i)
            QVERIFY(std::abs(saved->pixels[i] - expected->bentNormals.pixels[i]) <=
                    0.5f / 65535 + 1e-6f);
    }

    // The bake request carries the material's surface and the panel's distance.
    void requestCarriesTheSurface() {
        DocumentState state;
        state.material.heightScale = 0.3f;
        state.material.wrap = WrapMode::Clamp;
        const BakeRequest r = makeBakeRequest(state, BakeKind::Occlusion, NormalFilter::Sobel, 0.5);
        QCOMPARE(r.occlusion.heightScale, 0.3f);
        QVERIFY(r.occlusion.wrap == WrapMode::Clamp);
        QCOMPARE(r.occlusion.distance, 0.5);
        QVERIFY(mapKindOf(BakeKind::Occlusion) == MapKind::Ao);
    }
};

QTEST_MAIN(StudioOcclusionBakeTest)
#include "StudioOcclusionBakeTest.moc"
