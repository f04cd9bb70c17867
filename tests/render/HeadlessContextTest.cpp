// The headless context: OpenGL 4.3 core or better with no display, and a clear refusal otherwise.

#include "parallax/render/HeadlessContext.h"

#include "RenderTestSupport.h"
#include "parallax/render/GlInfo.h"

#include <QtTest>
#include <cstdlib>

using namespace px;

class HeadlessContextTest : public QObject {
    Q_OBJECT

private slots:
    void createsA43CoreContextWithoutDisplay();
    void requirementNamesWhatItFound();
    void eachPlatformOnRequest();
};

void HeadlessContextTest::createsA43CoreContextWithoutDisplay() {
    qunsetenv("DISPLAY"); // prove no X server is involved
    HeadlessContext* context = test::glContext();
    QVERIFY2(context, "no headless OpenGL 4.3 context (see the message above)");
    const GlInfo& info = context->info();
    QVERIFY2(requireGl43(info).ok(), info.summary().c_str());
    QVERIFY(info.core);
    QVERIFY(!context->platform().empty());
    qInfo("%s on %s", info.summary().c_str(), context->platform().c_str());
}

void HeadlessContextTest::requirementNamesWhatItFound() {
    GlInfo old;
    old.version = "3.3 (Core Profile) Mesa 22.3.6";
    old.renderer = "softpipe";
    old.major = 3;
    old.minor = 3;
    const Status s = requireGl43(old);
    QVERIFY(!s.ok());
    QCOMPARE(QString::fromStdString(s.error().message),
             QString("the renderer needs OpenGL 4.3; found OpenGL 3.3 (Core Profile) Mesa 22.3.6, "
                     "softpipe"));
    QVERIFY(old.software());
    GlInfo none;
    QVERIFY(!requireGl43(none).ok());
    QVERIFY(requireGl43(none).error().message.find("no OpenGL context") != std::string::npos);
}

// The EGL device platform is what NVIDIA machines use; Mesa offers it too (a software device),
// so CI exercises both paths. An unknown request is refused, saying what is accepted.
void HeadlessContextTest::eachPlatformOnRequest() {
    QVERIFY(test::glContext());
    for (const char* platform : {"device", "surfaceless"}) {
        qputenv("PX_EGL_PLATFORM", platform);
        Result<std::unique_ptr<HeadlessContext>> c = HeadlessContext::create();
        QVERIFY2(c.ok(), c ? "" : c.error().message.c_str());
        QVERIFY2(requireGl43((*c)->info()).ok(), (*c)->info().summary().c_str());
        const std::string expected =
            std::string(platform) == "device" ? "EGL device" : "surfaceless Mesa";
        QVERIFY2((*c)->platform().rfind(expected, 0) == 0, (*c)->platform().c_str());
    }
    qputenv("PX_EGL_PLATFORM", "wayland");
    Result<std::unique_ptr<HeadlessContext>> refused = HeadlessContext::create();
    qunsetenv("PX_EGL_PLATFORM");
    QVERIFY(!refused.ok());
    QVERIFY2(refused.error().message.find("expected device or surfaceless") != std::string::npos,
             refused.error().message.c_str());
    QVERIFY(test::glContext()->makeCurrent());
}

QTEST_APPLESS_MAIN(HeadlessContextTest)
#include "HeadlessContextTest.moc"
