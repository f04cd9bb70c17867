// The window fits small screens: with 1, 2 or 4 viewports its minimum size fits 1280 x 720 at
// scale 1 (run again with QT_SCALE_FACTOR=2: 1920 x 1080 physical pixels, 960 x 540 logical), and
// it never opens larger than the screen's free area.

#include "StudioTestSupport.h"

#include <QGuiApplication>
#include <QScreen>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;

class WindowFitTest : public QObject {
    Q_OBJECT
    QTemporaryDir m_settings;

private slots:
    void initTestCase() { isolateSettings(m_settings); }

    void minimumSizeFitsTheSmallScreen_data() {
        QTest::addColumn<int>("layout");
        for (int layout : {1, 2, 4})
            QTest::addRow("%d views", layout) << layout;
    }
    void minimumSizeFitsTheSmallScreen() {
        QFETCH(int, layout);
        auto w = makeWindow(layout);
        QVERIFY(w);
        const bool doubled = qgetenv("QT_SCALE_FACTOR") == "2";
        const QSize room = doubled ? QSize(1920 / 2, 1080 / 2) : QSize(1280, 720);
        const QSize least = w->minimumSizeHint().expandedTo(w->minimumSize());
        QVERIFY2(least.width() <= room.width() && least.height() <= room.height(),
                 qPrintable(QStringLiteral("minimum %1 x %2, room %3 x %4")
                                .arg(least.width())
                                .arg(least.height())
                                .arg(room.width())
                                .arg(room.height())));
    }

    void neverOpensLargerThanTheScreen() {
        const GlProbe& gl = probeOpenGl();
        MainWindow w(gl.usable ? QString() : gl.reason);
        w.setInteractive(false);
        const QSize free = QGuiApplication::primaryScreen()->availableGeometry().size();
        QVERIFY2(w.width() <= free.width() && w.height() <= free.height(),
                 qPrintable(QStringLiteral("%1 x %2 on %3 x %4")
                                .arg(w.width())
                                .arg(w.height())
                                .arg(free.width())
                                .arg(free.height())));
    }
};

QTEST_MAIN(WindowFitTest)
#include "WindowFitTest.moc"
