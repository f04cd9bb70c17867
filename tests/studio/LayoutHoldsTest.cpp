// The panels keep their controls whatever they say: at 1280 x 800 and 1920 x 1080 (and again at
// twice the scale, QT_SCALE_FACTOR=2, where the screen holds 960 x 540 logical pixels), after a
// bake, a bake's longest message, an import and its report, and an export with notes, every
// button of the Maps panel lies inside its panel's width (never scrolled sideways out of sight)
// and is reached by scrolling down at most; the import report's and the export dialog's buttons
// lie on screen, and the export's every note is shown or a scroll away.

#include "StudioTestSupport.h"
#include "TextureSets.h"
#include "jobs/BakeRunner.h"
#include "panels/ExportDialog.h"
#include "panels/ImportSummaryDialog.h"
#include "panels/MapsPanel.h"

#include <QAbstractButton>
#include <QComboBox>
#include <QGuiApplication>
#include <QLabel>
#include <QScreen>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalSpy>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;
using px::test::TextureSetSpec;
using px::test::writeTextureSet;

namespace {

QString describe(const QWidget* w) {
    const QString text = qobject_cast<const QAbstractButton*>(w)
                             ? qobject_cast<const QAbstractButton*>(w)->text()
                             : QString();
    return QString("%1 '%2' in %3")
        .arg(w->metaObject()->className(), text,
             w->parentWidget() ? w->parentWidget()->objectName() : QString());
}

// Every button of the Maps panel: inside its scroll area's width, and inside its height once
// scrolled to. Empty when all are; else what is not, one a line.
QString mapsButtonsOutOfSight(MainWindow* w) {
    QScrollArea* area = nullptr;
    for (QWidget* p = w->mapsPanel(); p; p = p->parentWidget())
        if ((area = qobject_cast<QScrollArea*>(p)))
            break;
    if (!area)
        return "no scroll area around the Maps panel";
    QStringList problems;
    if (area->horizontalScrollBar()->maximum() > 0) {
        problems << QString("the Maps panel is %1 px wider than its dock")
                        .arg(area->horizontalScrollBar()->maximum());
        for (QWidget* c : w->mapsPanel()->findChildren<QWidget*>())
            if (c->isVisibleTo(w->mapsPanel()) &&
                c->minimumSizeHint().width() > area->viewport()->width() - 40)
                problems << QString("  %1 %2 needs %3 px")
                                .arg(c->metaObject()->className(), c->objectName())
                                .arg(c->minimumSizeHint().width());
    }
    for (QAbstractButton* b : w->mapsPanel()->findChildren<QAbstractButton*>()) {
        if (!b->isVisibleTo(w->mapsPanel()))
            continue;
        area->ensureWidgetVisible(b, 0, 0);
        QCoreApplication::processEvents();
        // The viewport as it is now: the vertical scroll bar comes and goes with the scrolling.
        const QRect viewport = area->viewport()->rect();
        const QRect r(b->mapTo(area->viewport(), QPoint(0, 0)), b->size());
        if (!viewport.contains(r))
            problems << QString("%1 at %2,%3 %4x%5 outside the panel's %6x%7")
                            .arg(describe(b))
                            .arg(r.x())
                            .arg(r.y())
                            .arg(r.width())
                            .arg(r.height())
                            .arg(viewport.width())
                            .arg(viewport.height());
    }
    area->verticalScrollBar()->setValue(0);
    return problems.join('\n');
}

// Every button of a top-level widget inside it, and it on the screen.
QString buttonsOnScreen(QWidget* top) {
    QStringList problems;
    const QRect screen = top->screen()->availableGeometry();
    if (!screen.contains(top->frameGeometry()))
        problems << QString("%1 at %2,%3 %4x%5 leaves the screen %6x%7")
                        .arg(top->metaObject()->className())
                        .arg(top->frameGeometry().x())
                        .arg(top->frameGeometry().y())
                        .arg(top->frameGeometry().width())
                        .arg(top->frameGeometry().height())
                        .arg(screen.width())
                        .arg(screen.height());
    for (QAbstractButton* b : top->findChildren<QAbstractButton*>()) {
        if (!b->isVisibleTo(top) || qobject_cast<QScrollArea*>(b->parentWidget()))
            continue;
        const QRect r(b->mapTo(top, QPoint(0, 0)), b->size());
        if (!top->rect().contains(r))
            problems << describe(b) + " outside its window";
    }
    return problems.join('\n');
}

} // namespace

class LayoutHoldsTest : public GlWindowTest {
    Q_OBJECT

private slots:
    void initTestCase() { QVERIFY(glReady()); }

    void buttonsStayInSight_data() {
        QTest::addColumn<QSize>("size");
        QTest::addRow("1280x800") << QSize(1280, 800);
        QTest::addRow("1920x1080") << QSize(1920, 1080);
    }
    void buttonsStayInSight() {
        QFETCH(QSize, size);
        auto w = makeWindow(2, 64);
        QVERIFY(w);
        // As large as asked, or as the screen's free area (960 x 540 at scale 2).
        const QSize room = w->screen()->availableGeometry().size();
        const QSize frame = w->frameGeometry().size() - w->size();
        w->resize(size.boundedTo(room - frame));
        QCoreApplication::processEvents();
        const QString scale = QString("at %1 x %2, scale %3")
                                  .arg(w->width())
                                  .arg(w->height())
                                  .arg(w->devicePixelRatioF());
        QString problems = mapsButtonsOutOfSight(w.get());
        QVERIFY2(problems.isEmpty(), qPrintable(scale + ", opened:\n" + problems));

        // A bake and its line (where it ran, and why).
        w->startBake(BakeKind::RelaxedCone);
        QTRY_VERIFY_WITH_TIMEOUT(!w->baker()->isBusy(), 120000);
        QTRY_VERIFY_WITH_TIMEOUT((w->viewports()->viewport(0)->preview()->update(),
                                  w->mapsPanel()->bakeStatus().contains("shown")),
                                 60000);
        problems = mapsButtonsOutOfSight(w.get());
        QVERIFY2(problems.isEmpty(), qPrintable(scale + ", after a bake (" +
                                                w->mapsPanel()->bakeStatus() + "):\n" + problems));
        // Any message: one long word and a long sentence (a failure naming a deep path).
        BakeOutcome failed;
        failed.request.kind = BakeKind::Cone;
        failed.error = "/home/artist/" + QString(120, 'x') + "/textures/kart_tyre_sidewall_" +
                       QString(40, 'y') + ".png: the bake failed because " +
                       QString("the reason is very long ").repeated(12);
        emit w->baker()->finished(failed);
        QCoreApplication::processEvents();
        problems = mapsButtonsOutOfSight(w.get());
        QVERIFY2(problems.isEmpty(), qPrintable(scale + ", after a long message:\n" + problems));

        // An import: its report, and the rows naming the set's files.
        QTemporaryDir dir;
        TextureSetSpec spec;
        spec.stem = "kart_tyre_sidewall_rubber_worn_2k_" + std::string(30, 'z');
        writeTextureSet(dir.path().toStdString(), spec);
        QVERIFY(w->importFolder(dir.path()));
        ImportSummaryDialog* summary = w->importSummary();
        QVERIFY(summary);
        summary->show();
        QVERIFY(QTest::qWaitForWindowExposed(summary));
        problems = buttonsOnScreen(summary);
        QVERIFY2(problems.isEmpty(), qPrintable(scale + ", the import report:\n" + problems));
        summary->close();
        problems = mapsButtonsOutOfSight(w.get());
        QVERIFY2(problems.isEmpty(), qPrintable(scale + ", after an import:\n" + problems));

        // An export with notes (the engines' set-up, what is not exported).
        w->document()->edit("shadow", [](DocumentState& s) { s.material.selfShadow = true; });
        QVERIFY(w->saveTo(dir.filePath("kart.json")));
        ExportDialog dialog(w->document()->material(), w->document()->filePath(), w.get());
        dialog.findChild<QComboBox*>()->setCurrentText("unreal");
        dialog.show();
        QVERIFY(QTest::qWaitForWindowExposed(&dialog));
        QSignalSpy done(&dialog, &ExportDialog::exportFinished);
        dialog.startExport();
        QVERIFY(done.wait(60000));
        QVERIFY2(done.front().front().toBool(), qPrintable(dialog.resultText()));
        QCoreApplication::processEvents();
        qInfo("%s", qPrintable(dialog.resultText()));
        problems = buttonsOnScreen(&dialog);
        QVERIFY2(problems.isEmpty(), qPrintable(scale + ", the export dialog:\n" + problems));
        // Every note in view, or a scroll away: the label holds its whole text and the area
        // scrolls to its end.
        auto* result = dialog.findChild<QLabel*>("export-result");
        QVERIFY(result);
        QScrollArea* area = dialog.resultArea();
        const int needed = result->heightForWidth(result->width());
        QVERIFY2(result->height() >= needed,
                 qPrintable(QString("%1 px of notes in %2 px").arg(needed).arg(result->height())));
        const int hidden = result->height() - area->viewport()->height();
        QVERIFY2(hidden <= 0 || area->verticalScrollBar()->maximum() >= hidden,
                 qPrintable(QString("%1 px of notes below, a scroll of %2")
                                .arg(hidden)
                                .arg(area->verticalScrollBar()->maximum())));
        // Grown to show them where the screen has room.
        if (hidden > 0)
            QVERIFY2(dialog.frameGeometry().height() >=
                         dialog.screen()->availableGeometry().height() - 2,
                     qPrintable(QString("%1 px of notes hidden in a dialog of %2 px")
                                    .arg(hidden)
                                    .arg(dialog.height())));
    }
};

QTEST_MAIN(LayoutHoldsTest)
#include "LayoutHoldsTest.moc"
