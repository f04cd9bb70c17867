// The built-in sky in the editor, under Xvfb with llvmpipe: its sun is the directional light and
// follows it when the light moves.

#include "StudioTestSupport.h"
#include "parallax/image/ImageFile.h"

#include <QLineF>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;

namespace {

// Where the camera sees direction d (a point at infinity), in the image's pixels.
QPointF projectDirection(const OrbitCamera& camera, glm::vec3 d, QSize size) {
    const glm::vec4 clip = camera.projection(float(size.width()) / float(size.height())) *
                           camera.view() * glm::vec4(d, 0.0f);
    return {(clip.x / clip.w * 0.5 + 0.5) * size.width(),
            (0.5 - clip.y / clip.w * 0.5) * size.height()};
}

// The centre of the sky's brightest pixels (the sun's disc and the inner glow, white once tone
// mapped), above the horizon: the mesh below it has highlights of its own.
QPointF brightestSky(const QImage& image, const OrbitCamera& camera) {
    const double horizon = projectDirection(camera, {0.0f, 0.0f, -1.0f}, image.size()).y();
    double x = 0.0, y = 0.0;
    int n = 0;
    for (int j = 0; j < int(horizon) - 4; ++j)
        for (int i = 0; i < image.width(); ++i)
            if (qGray(image.pixel(i, j)) >= 250) {
                x += i + 0.5;
                y += j + 0.5;
                ++n;
            }
    return n > 0 ? QPointF(x / n, y / n) : QPointF(-1e6, -1e6);
}

} // namespace

class StudioSkyTest : public GlWindowTest {
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY(glReady()); }

    // The sky's sun is the light: moving the light (Ctrl+Left, as a drag does) makes the sky again
    // with its sun there, and the brightest part of the sky behind the mesh moves to where the
    // camera sees the light's direction.
    void skySunFollowsTheLight() {
        auto w = makeWindow();
        QVERIFY(w);
        PreviewWidget* preview = w->viewports()->viewport(0)->preview();
        SharedView view = w->viewports()->activeView();
        view.camera.azimuthDeg = 0.0f; // at +z, looking down -z, 5 degrees down
        view.camera.elevationDeg = 5.0f;
        view.light.azimuthDeg = 185.0f; // low in front of the camera, to the right of the centre
        view.light.elevationDeg = 9.0f;
        w->viewports()->editView(view);
        QVERIFY(w->setEnvironment("sky"));
        QVERIFY(waitForFigures(preview));
        const QImage first = preview->grabFramebuffer();
        const DirectionalLight before = w->viewports()->activeView().light;
        preview->setFocus();
        QTest::keyClick(preview, Qt::Key_Left, Qt::ControlModifier); // ten degrees
        const DirectionalLight after = w->viewports()->activeView().light;
        QCOMPARE(after.azimuthDeg, before.azimuthDeg - 10.0f);
        QTRY_VERIFY_WITH_TIMEOUT(w->viewports()->activeView().skySun == after.direction(), 20000);
        QVERIFY(waitForFigures(preview));
        const QImage second = preview->grabFramebuffer();
        const OrbitCamera& camera = w->viewports()->activeView().camera;
        for (const auto& [image, light] : {std::pair{first, before}, std::pair{second, after}}) {
            const QPointF expected = projectDirection(camera, light.direction(), image.size());
            const QPointF found = brightestSky(image, camera);
            qInfo("light at azimuth %g: sun drawn at (%.1f, %.1f), seen at (%.1f, %.1f), %d x %d",
                  light.azimuthDeg, found.x(), found.y(), expected.x(), expected.y(), image.width(),
                  image.height());
            QVERIFY2(QLineF(found, expected).length() < 0.03 * image.width(),
                     qPrintable(QString("sun drawn at (%1, %2), the light is at (%3, %4)")
                                    .arg(found.x())
                                    .arg(found.y())
                                    .arg(expected.x())
                                    .arg(expected.y())));
        }
        // Ten degrees apart: the sun moved across the view, not within the tolerance.
        QVERIFY(QLineF(brightestSky(first, camera), brightestSky(second, camera)).length() >
                0.1 * first.width());
    }

    // A saved material opens under the light it was last shown with (the editor's settings, as
    // its mesh): the sky, an HDR file, exposure and the background; a file that is gone is named
    // and the light drawn before stays.
    void environmentIsRememberedWithTheMaterial() {
        const QString material = m_dir.filePath("lit.json");
        const QString hdr = m_dir.filePath("studio.exr");
        Image map(64, 32, 3);
        for (int y = 0; y < map.height; ++y)
            for (int x = 0; x < map.width; ++x)
                for (int c = 0; c < 3; ++c)
                    map.at(x, y, c) = y < 16 ? 2.0f : 0.25f;
        QVERIFY(writeImage(hdr.toStdString(), map, {PixelFormat::Half, false}));
        {
            auto w = makeWindow(1, 16);
            QVERIFY(w);
            QVERIFY(w->saveTo(material));
            QVERIFY(w->setEnvironment("sky"));
            SharedView view = w->viewports()->activeView();
            view.exposure = 1.5f;
            w->viewports()->editView(view);
        }
        {
            auto w = makeWindow(1, 16); // another session: the settings are what it has
            QVERIFY(w);
            QVERIFY(!w->viewports()->activeView().environment);
            QVERIFY(w->openFile(material));
            const SharedView& view = w->viewports()->activeView();
            QVERIFY(view.environment);
            QCOMPARE(view.environmentName, QString("sky"));
            QCOMPARE(view.exposure, 1.5f);
            QVERIFY2(w->lastProblem().isEmpty(), qPrintable(w->lastProblem()));
            // Now an HDR file, without the environment behind.
            QVERIFY(w->setEnvironment(hdr));
            SharedView edited = w->viewports()->activeView();
            edited.showEnvironment = false;
            w->viewports()->editView(edited);
        }
        {
            auto w = makeWindow(1, 16);
            QVERIFY(w);
            QVERIFY(w->openFile(material));
            const SharedView& view = w->viewports()->activeView();
            QVERIFY(view.environment);
            QCOMPARE(view.environmentName, QFileInfo(hdr).absoluteFilePath());
            QCOMPARE(view.showEnvironment, false);
            QCOMPARE(view.exposure, 1.5f);
        }
        QVERIFY(QFile::remove(hdr));
        auto w = makeWindow(1, 16);
        QVERIFY(w);
        QVERIFY(w->openFile(material)); // the material opens; its light cannot be made
        QVERIFY(!w->viewports()->activeView().environment);
        QVERIFY2(w->lastProblem().contains("studio.exr"), qPrintable(w->lastProblem()));
    }
};

QTEST_MAIN(StudioSkyTest)
#include "StudioSkyTest.moc"
