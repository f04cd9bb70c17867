// The headless context: OpenGL 4.3 core or better with no display, and a clear refusal otherwise.

#include "HeadlessContext.h"

#include "GlInfo.h"
#include "RenderTestSupport.h"

#include <QtTest>
#include <cstdlib>

using namespace px;

class HeadlessContextTest : public QObject {
    Q_OBJECT

private slots:
    void createsA43CoreContextWithoutDisplay();
    void requirementNamesWhatItFound();
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

QTEST_APPLESS_MAIN(HeadlessContextTest)
#include "HeadlessContextTest.moc"
