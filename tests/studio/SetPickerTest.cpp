// The texture-set picker: a folder of several sets is searched by typing (the list keeps the
// matches, Enter imports the first), and a set whose files name no height, bump or normal map is
// marked, as the import would refuse it.

#include "StudioTestSupport.h"
#include "TextureSets.h"
#include "panels/SetPickerDialog.h"
#include "parallax/image/ImageFile.h"
#include "parallax/material/TextureSet.h"

#include <QDialogButtonBox>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>

using namespace px;
using namespace px::studio;
using px::test::TextureSetSpec;
using px::test::writeTextureSet;

class SetPickerTest : public QObject {
    Q_OBJECT

private slots:
    void filtersAndMarksSetsWithoutRelief() {
        QTemporaryDir dir;
        for (const char* stem : {"rock", "wall_07", "Wallpaper_plain"}) {
            TextureSetSpec spec;
            spec.stem = stem;
            spec.size = 16;
            writeTextureSet(dir.path().toStdString(), spec);
        }
        // A set of colour alone: nothing in it gives relief.
        Image colour(16, 16, 3);
        QVERIFY(writeImage(dir.filePath("paper_albedo.png").toStdString(), colour, {}).ok());
        QVERIFY(writeImage(dir.filePath("paper_roughness.png").toStdString(), colour, {}).ok());
        Result<std::vector<std::string>> files = folderFiles(dir.path().toStdString());
        QVERIFY(files);
        const std::vector<SetChoice> choices = setChoices(*files);
        QCOMPARE(choices.size(), std::size_t(4));
        for (const SetChoice& c : choices)
            QVERIFY2(c.relief == (c.name != "paper"), qPrintable(c.name));

        SetPickerDialog picker("maps", choices);
        QCOMPARE(picker.shown().size(), 4);
        for (int i = 0; i < picker.list()->count(); ++i) {
            const QListWidgetItem* item = picker.list()->item(i);
            const bool paper = item->data(Qt::UserRole).toString() == "paper";
            QCOMPARE(item->text().contains("no relief"), paper);
            QCOMPARE(item->toolTip().contains("refuses"), paper);
        }
        QTest::keyClicks(picker.filterField(), "wal");
        QStringList matches = picker.shown();
        matches.sort();
        QCOMPARE(matches, (QStringList{"Wallpaper_plain", "wall_07"}));
        QVERIFY(picker.shown().contains(picker.chosen()));
        QTest::keyClick(picker.filterField(), Qt::Key_Down); // the arrows move in the list
        QTest::keyClicks(picker.filterField(), "l_");
        QCOMPARE(picker.shown(), QStringList{"wall_07"});
        QCOMPARE(picker.chosen(), QString("wall_07"));
        auto* ok = picker.findChild<QDialogButtonBox*>()->button(QDialogButtonBox::Ok);
        QVERIFY(ok->isEnabled());
        QTest::keyClicks(picker.filterField(), "zzz");
        QVERIFY(picker.shown().isEmpty());
        QVERIFY(picker.chosen().isEmpty());
        QVERIFY(!ok->isEnabled());
    }
};

QTEST_MAIN(SetPickerTest)
#include "SetPickerTest.moc"
