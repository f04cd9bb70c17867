// The editor's words: no tooltip or text speaks of "the seeds" (each names the technique's
// origin), the shortcut list is grouped by menu with every shortcut once, and its dialog's title
// is not cut.

#include "StudioTestSupport.h"
#include "widgets/Hints.h"

#include <QAction>
#include <QDialog>
#include <QRegularExpression>

using namespace px;
using namespace px::studio;
using namespace px::studio::test;

class StudioTextsTest : public QObject {
    Q_OBJECT
    QTemporaryDir m_settings;

private slots:
    void initTestCase() { isolateSettings(m_settings); }

    void noTextSpeaksOfTheSeeds() {
        auto w = makeWindow(4);
        QVERIFY(w);
        QStringList texts;
        for (const QWidget* widget : w->findChildren<QWidget*>())
            texts << widget->toolTip() << widget->statusTip() << widget->whatsThis()
                  << widget->property("text").toString();
        for (const QAction* action : w->findChildren<QAction*>())
            texts << action->text() << action->toolTip() << action->statusTip();
        for (const TechniqueInfo& t : allTechniques())
            texts << hints::technique(t.id) << hints::stepCap(t.id);
        texts << hints::viewportHelp() << hints::qualityRange() << hints::minLayers();
        QVERIFY(texts.size() > 100);
        for (const QString& text : texts)
            QVERIFY2(!text.contains(QStringLiteral("seed"), Qt::CaseInsensitive), qPrintable(text));
    }

    void shortcutsAreGroupedByMenuEachOnce() {
        auto w = makeWindow();
        QVERIFY(w);
        const QString table = w->shortcutsTable();
        int last = -1;
        for (const char* group : {"File", "Edit", "View", "Bake", "Compare", "Mouse"}) {
            const int at = table.indexOf(QStringLiteral("<br>%1</th>").arg(group));
            QVERIFY2(at > last, group); // present, in menu order
            last = at;
        }
        for (const QAction* a : w->findChildren<QAction*>()) {
            if (a->shortcut().isEmpty() || a->text().isEmpty())
                continue;
            const QString row = QStringLiteral("<tr><td>%1</td>").arg(a->text().remove('&'));
            QCOMPARE(table.count(row), 1);
        }
        QVERIFY(table.contains("<b>Ctrl+Z</b>"));

        QAction* f1 = nullptr;
        for (QAction* a : w->findChildren<QAction*>())
            if (a->shortcut() == QKeySequence(QKeySequence::HelpContents))
                f1 = a;
        QVERIFY(f1);
        f1->trigger();
        auto* dialog = w->findChild<QDialog*>("shortcuts");
        QVERIFY(dialog);
        QVERIFY(dialog->width() > dialog->fontMetrics().horizontalAdvance(dialog->windowTitle()));
        dialog->close();
    }
};

QTEST_MAIN(StudioTextsTest)
#include "StudioTextsTest.moc"
