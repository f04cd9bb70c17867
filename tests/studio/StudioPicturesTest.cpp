// Pictures out of the editor, under Xvfb with llvmpipe: the active view at any size (larger than
// the view too), every view side by side, a turntable whose frames orbit, and a folder that does
// not exist as a message naming the file.

#include "StudioTestSupport.h"
#include "parallax/image/ImageFile.h"

#include <QDir>
#include <QProgressDialog>
#include <QPushButton>
#include <QStatusBar>
#include <QTimer>
#include <cmath>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;

namespace {

// Mean absolute difference of two images' colour channels, in 8-bit steps.
double difference(const Image& a, const Image& b) {
    double sum = 0.0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x)
            for (int c = 0; c < 3; ++c)
                sum += std::abs(a.at(x, y, c) - b.at(x, y, c));
    return 255.0 * sum / (3.0 * a.width * a.height);
}

// Pixels that are not the backdrop's colour (the mesh is in the picture).
int drawnPixels(const Image& image) {
    int n = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x)
            n += std::abs(image.at(x, y, 0) - image.at(0, 0, 0)) > 0.05f;
    return n;
}

} // namespace

class StudioPicturesTest : public GlWindowTest {
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY(glReady()); }

    void activeViewAtAnySize() {
        auto w = makeWindow(1, 32);
        QVERIFY(w);
        QVERIFY(waitForFigures(w->viewports()->viewport(0)->preview()));
        for (const QSize size : {QSize(200, 120), QSize(900, 700)}) {
            const QString file = m_dir.filePath(QStringLiteral("view-%1.png").arg(size.width()));
            QVERIFY(w->saveViewImage(file, size, false));
            Result<Image> image = readImage(file.toStdString());
            QVERIFY(image.ok());
            QCOMPARE(QSize(image->width, image->height), size);
            QVERIFY(drawnPixels(*image) > size.width() * size.height() / 10);
        }
    }

    void allViewsSideBySide() {
        auto w = makeWindow(4, 32);
        QVERIFY(w);
        const QString file = m_dir.filePath("all.png");
        QVERIFY(w->saveViewImage(file, QSize(96, 64), true));
        Result<Image> image = readImage(file.toStdString());
        QVERIFY(image.ok());
        QCOMPARE(image->width, 2 * 96);
        QCOMPARE(image->height, 2 * 64);
        // Every quarter holds a view with the mesh in it.
        for (int q = 0; q < 4; ++q) {
            Image quarter(96, 64, 4);
            for (int y = 0; y < 64; ++y)
                for (int x = 0; x < 96; ++x)
                    for (int c = 0; c < 4; ++c)
                        quarter.at(x, y, c) = image->at((q % 2) * 96 + x, (q / 2) * 64 + y, c);
            QVERIFY2(drawnPixels(quarter) > 96 * 64 / 10, qPrintable(QString("view %1").arg(q)));
        }
    }

    void turntableOrbits() {
        auto w = makeWindow(1, 32);
        QVERIFY(w);
        const QString file = m_dir.filePath("spin.png");
        QVERIFY(w->saveTurntable(file, QSize(64, 48), 4));
        std::vector<Image> frames;
        for (const char* name : {"spin-000.png", "spin-001.png", "spin-002.png", "spin-003.png"}) {
            Result<Image> frame = readImage(m_dir.filePath(name).toStdString());
            QVERIFY2(frame.ok(), name);
            frames.push_back(*frame);
        }
        // A quarter turn apart: the bricks face another way in each.
        for (std::size_t i = 1; i < frames.size(); ++i)
            QVERIFY2(difference(frames[i - 1], frames[i]) > 2.0,
                     qPrintable(QString::number(difference(frames[i - 1], frames[i]))));
        QVERIFY(!QFileInfo::exists(m_dir.filePath("spin-004.png")));
    }

    // The turntable renders one frame per turn of the event loop under a progress dialog: events
    // run before every frame (the poll sees each frame's number), and Cancel at the fourth of six
    // frames writes nothing: the previous set stays byte for byte, no frame or temporary is left.
    void turntableCancelsBetweenFrames() {
        auto w = makeWindow(1, 32);
        QVERIFY(w);
        QTemporaryDir dir;
        const QString file = dir.filePath("turn.png");
        QVERIFY(w->saveTurntable(file, QSize(48, 32), 3));
        const QDir folder(dir.path());
        const QDir::Filters all = QDir::Files | QDir::Hidden | QDir::System;
        const QStringList previous = folder.entryList(all, QDir::Name);
        QCOMPARE(previous, (QStringList{"turn-000.png", "turn-001.png", "turn-002.png"}));
        QList<QByteArray> bytes;
        for (const QString& name : previous) {
            QFile f(folder.filePath(name));
            QVERIFY(f.open(QIODevice::ReadOnly));
            bytes << f.readAll();
        }
        QList<int> seen; // the dialog's value each time the poll ran
        QTimer poll;
        connect(&poll, &QTimer::timeout, this, [&] {
            auto* dialog = w->findChild<QProgressDialog*>();
            if (!dialog || !dialog->isVisible() || dialog->wasCanceled())
                return;
            if (seen.isEmpty() || seen.back() != dialog->value())
                seen << dialog->value();
            if (dialog->value() == 3)
                QTest::mouseClick(dialog->findChild<QPushButton*>(), Qt::LeftButton);
        });
        poll.start(0);
        QVERIFY(!w->saveTurntable(file, QSize(48, 32), 6));
        poll.stop();
        QCOMPARE(seen, (QList<int>{0, 1, 2, 3}));
        QVERIFY(w->lastProblem().isEmpty());
        QVERIFY(w->statusBar()->currentMessage().contains("cancelled"));
        QCOMPARE(folder.entryList(all, QDir::Name), previous);
        for (int i = 0; i < previous.size(); ++i) {
            QFile f(folder.filePath(previous[i]));
            QVERIFY(f.open(QIODevice::ReadOnly));
            QVERIFY2(f.readAll() == bytes[i], qPrintable(previous[i]));
        }
    }

    void missingFolderIsAMessage() {
        auto w = makeWindow(1, 32);
        QVERIFY(w);
        const QString file = m_dir.filePath("no/such/folder/view.png");
        QVERIFY(!w->saveViewImage(file, QSize(32, 32), false));
        QVERIFY2(w->lastProblem().contains(file), qPrintable(w->lastProblem()));
        QVERIFY(!w->saveTurntable(m_dir.filePath("no/such/spin.png"), QSize(32, 32), 2));
        // The frames' folder is what is missing: the message names it.
        QVERIFY2(
            w->lastProblem().contains(m_dir.filePath("no/such") + ": the folder does not exist"),
            qPrintable(w->lastProblem()));
    }
};

QTEST_MAIN(StudioPicturesTest)
#include "StudioPicturesTest.moc"
