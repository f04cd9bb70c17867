// What the editor's panels show is whole and in its place: the heat map's scale keeps its labels
// apart at any font size and view width, the Compare dock opens under the viewports without
// squeezing the side panels and says it is measuring while it measures.

#include "StudioTestSupport.h"
#include "panels/ComparePanel.h"
#include "panels/TechniquePanel.h"
#include "panels/WorkPrecisionView.h"
#include "preview/ErrorStats.h"
#include "preview/HeatLegend.h"

#include <QDockWidget>
#include <QFontMetrics>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QSignalSpy>
#include <QSpinBox>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;

class PanelLayoutTest : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;

private slots:
    void initTestCase() { isolateSettings(m_dir); }

    // Every font size and view width: no two labels touch, each stop's label sits under its
    // colour, all lie on the legend's backdrop and, where the view has room, in the view; the
    // middle labels give way before the ends in a narrow view.
    void heatLegendLabelsNeverOverlap() {
        const std::span<const HeatStop> stops = heatStops();
        for (int points : {6, 8, 9, 10, 12, 16, 20, 28}) {
            QFont font;
            font.setPointSize(points);
            const QFontMetrics fm(font);
            for (int width : {96, 140, 200, 320, 480, 900}) {
                const QSize view(width, 300);
                const HeatLegendLayout legend = layoutHeatLegend(fm, view);
                const QString where = QString("%1 pt, view %2 px").arg(points).arg(width);
                QVERIFY2(legend.labels.size() >= 3, qPrintable(where)); // 0, the top, the unit
                QCOMPARE(legend.labels.front().text, QString("0"));
                QCOMPARE(legend.labels.back().text, QString("texels"));
                QVERIFY2(legend.labels[legend.labels.size() - 2].text.startsWith("≥"),
                         qPrintable(where));
                for (std::size_t i = 0; i < legend.labels.size(); ++i) {
                    const QRect& a = legend.labels[i].rect;
                    QVERIFY2(legend.backdrop.contains(a), qPrintable(where));
                    QCOMPARE(a.width(), fm.horizontalAdvance(legend.labels[i].text)); // whole
                    for (std::size_t j = i + 1; j < legend.labels.size(); ++j)
                        QVERIFY2(!a.intersects(legend.labels[j].rect),
                                 qPrintable(where + ": " + legend.labels[i].text + " and " +
                                            legend.labels[j].text));
                }
                // A stop's label lies under its colour: the stop's place on the bar is inside it.
                for (std::size_t i = 0; i + 1 < legend.labels.size(); ++i) {
                    const QString text = legend.labels[i].text;
                    const auto stop =
                        std::find_if(stops.begin(), stops.end(), [&](const HeatStop& s) {
                            return text.endsWith(QString::number(s.texels, 'g', 3));
                        });
                    QVERIFY2(stop != stops.end(), qPrintable(text));
                    const double x =
                        legend.bar.left() + legend.bar.width() * stop->texels / stops.back().texels;
                    const QRect& r = legend.labels[i].rect;
                    QVERIFY2(r.left() <= x + 1 && x <= r.right() + 2,
                             qPrintable(where + ": " + text));
                }
                const bool room = width >= 20 * fm.height();
                if (room) {
                    QVERIFY2(QRect(QPoint(0, 0), view).contains(legend.backdrop),
                             qPrintable(where));
                    QCOMPARE(legend.labels.size(), stops.size() + 1); // every stop
                }
            }
        }
    }

    // Shown, the Compare dock lies under the viewports: the Maps and Parameters docks keep the
    // window's height.
    void compareDockLeavesTheSidePanelsTheirHeight() {
        auto w = makeWindow(1, 16);
        QVERIFY(w);
        w->resize(1400, 900);
        QCoreApplication::processEvents();
        auto* maps = w->findChild<QDockWidget*>("MapsDock");
        auto* parameters = w->findChild<QDockWidget*>("ParametersDock");
        auto* compare = w->findChild<QDockWidget*>("CompareDock");
        QVERIFY(maps && parameters && compare);
        const int mapsHeight = maps->height(), parametersHeight = parameters->height();
        compare->show();
        QTRY_VERIFY(compare->isVisible() && compare->height() > 0);
        QCoreApplication::processEvents();
        QCOMPARE(maps->height(), mapsHeight);
        QCOMPARE(parameters->height(), parametersHeight);
        QVERIFY(compare->geometry().left() >= maps->geometry().right());
        QVERIFY(compare->geometry().right() <= parameters->geometry().left());
        QVERIFY(compare->geometry().top() >= w->viewports()->geometry().bottom());
    }

    // While it measures, the empty plot says so (not "Run the comparison"); cancelled, it says
    // that.
    void comparePlotSaysWhatIsHappening() {
        auto w = makeWindow(1, 16);
        QVERIFY(w);
        ComparePanel* compare = w->comparePanel();
        WorkPrecisionView* plot = compare->chartView();
        QVERIFY(plot->placeholderText().contains("Run the comparison"));
        compare->raysField()->setValue(8);
        QSignalSpy finished(compare, &ComparePanel::finished);
        compare->run();
        QVERIFY(compare->isRunning());
        QVERIFY2(!plot->placeholderText().contains("Run the comparison"),
                 qPrintable(plot->placeholderText()));
        QVERIFY(plot->placeholderText().startsWith("Measuring"));
        compare->cancel();
        QVERIFY(finished.wait(120000));
        QVERIFY2(plot->placeholderText().contains("cancelled"),
                 qPrintable(plot->placeholderText()));
    }

    // Auto's result (several sentences) shows whole in the Parameters panel, however wide the
    // panel: every line of it inside the panel's width, the label as tall as its wrapped text.
    void autoResultIsShownWhole_data() {
        QTest::addColumn<int>("dockWidth");
        QTest::addRow("narrow") << 240;
        QTest::addRow("default") << 0;
        QTest::addRow("wide") << 520;
    }
    void autoResultIsShownWhole() {
        QFETCH(int, dockWidth);
        auto w = makeWindow(1, 32);
        QVERIFY(w);
        auto* dock = w->findChild<QDockWidget*>("ParametersDock");
        QVERIFY(dock);
        if (dockWidth > 0)
            w->resizeDocks({dock}, {dockWidth}, Qt::Horizontal);
        QCoreApplication::processEvents();
        TechniquePanel* technique = w->techniquePanel();
        const int widthBefore =
            dock->widget()
                ? qobject_cast<QScrollArea*>(dock->widget())->widget()->minimumSizeHint().width()
                : 0;
        technique->autoPick()->click(); // measures in the background, the event loop running
        QTRY_VERIFY_WITH_TIMEOUT(technique->autoStatus().contains("resolved"), 120000);
        QCoreApplication::processEvents();
        QLabel* status = nullptr;
        for (QLabel* label : technique->findChildren<QLabel*>())
            if (label->text() == technique->autoStatus())
                status = label;
        QVERIFY(status && status->isVisible());
        auto* area = qobject_cast<QScrollArea*>(dock->widget());
        QVERIFY(area);
        const QRect shown(status->mapTo(area->widget(), QPoint(0, 0)), status->size());
        const QString where = QString("label %1 x %2 at x %3, panel %4 wide: %5")
                                  .arg(status->width())
                                  .arg(status->height())
                                  .arg(shown.x())
                                  .arg(area->viewport()->width())
                                  .arg(status->text());
        // Within the panel's width (a panel narrower than its other controls scrolls sideways,
        // by design), and its chart never what makes the panel wider.
        QVERIFY2(shown.right() < area->widget()->width(), qPrintable(where));
        QVERIFY(technique->autoChart()->isVisible());
        QVERIFY(area->widget()->minimumSizeHint().width() <= widthBefore);
        QVERIFY2(status->height() >= status->heightForWidth(status->width()), qPrintable(where));
    }
};

QTEST_MAIN(PanelLayoutTest)
#include "PanelLayoutTest.moc"
