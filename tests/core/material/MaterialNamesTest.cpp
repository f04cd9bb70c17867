// The names of a material's enums: one table each, every value spelled once per spelling and
// read back to itself; a normal source's two spellings (file, command line) name the same value.

#include "parallax/material/MaterialNames.h"

#include <QtTest>
#include <set>
#include <string>

using namespace px;

class MaterialNamesTest : public QObject {
    Q_OBJECT

private slots:
    void normalSourcesRoundTripInBothSpellings();
    void spellingsAreNotInterchangeable();
    void lightingModelsRoundTrip();
};

void MaterialNamesTest::normalSourcesRoundTripInBothSpellings() {
    const auto file = normalSourceNames();
    const auto cli = normalSourceShortNames();
    QCOMPARE(file.size(), cli.size());
    QCOMPARE(file.size(), std::size_t{4});
    std::set<std::string> seen;
    for (std::size_t i = 0; i < file.size(); ++i) {
        const auto source = static_cast<NormalSource>(i);
        QCOMPARE(toString(source), file[i]);
        QCOMPARE(shortName(source), cli[i]);
        QCOMPARE(parseNormalSource(file[i]), std::optional(source));
        QCOMPARE(parseNormalSourceShortName(cli[i]), std::optional(source));
        seen.emplace(cli[i]);
    }
    QCOMPARE(seen.size(), file.size()); // no two sources share a short name
    QCOMPARE(shortName(NormalSource::HeightSobel), std::string_view("sobel"));
    QCOMPARE(toString(NormalSource::HeightSobel), std::string_view("height-sobel"));
}

void MaterialNamesTest::spellingsAreNotInterchangeable() {
    // The material file keeps its own spelling: a file saying "sobel" is an error, not a guess.
    QVERIFY(!parseNormalSource("sobel"));
    QVERIFY(!parseNormalSourceShortName("height-sobel"));
    QVERIFY(!parseNormalSourceShortName(""));
    QCOMPARE(toString(static_cast<NormalSource>(7)), std::string_view("?"));
    QCOMPARE(shortName(static_cast<NormalSource>(-1)), std::string_view("?"));
}

void MaterialNamesTest::lightingModelsRoundTrip() {
    const auto names = lightingModelNames();
    QCOMPARE(names.size(), std::size_t{2});
    for (std::size_t i = 0; i < names.size(); ++i) {
        const auto model = static_cast<LightingModel>(i);
        QCOMPARE(toString(model), names[i]);
        QCOMPARE(parseLightingModel(names[i]), std::optional(model));
    }
    QVERIFY(!parseLightingModel("phong"));
}

QTEST_APPLESS_MAIN(MaterialNamesTest)
#include "MaterialNamesTest.moc"
