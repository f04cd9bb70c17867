// The bench's sweeps: each technique's default is measured, POM includes the tutorial shaders'
// baseline, and the technique list parses as documented.

#include "parallax/eval/QualitySweep.h"

#include "parallax/trace/Tracer.h"

#include <QtTest>

using namespace px;

class QualitySweepTest : public QObject {
    Q_OBJECT

private slots:
    void everySweepHoldsItsDefault();
    void pomHoldsTheSeedsBaseline();
    void sweepsGrowInCost();
    void labelsNameTheParametersUsed();
    void techniqueLists();
    void sweepsByHand();
};

void QualitySweepTest::everySweepHoldsItsDefault() {
    for (const TechniqueInfo& ti : allTechniques()) {
        if (!ti.parallax)
            continue;
        const std::vector<BenchSetting> sweep = qualitySweep(ti.id);
        QVERIFY2(!sweep.empty(), ti.name.data());
        const int defaults = static_cast<int>(std::count_if(
            sweep.begin(), sweep.end(), [](const BenchSetting& s) { return s.isDefault; }));
        QVERIFY2(defaults == 1, ti.name.data());
        for (const BenchSetting& s : sweep) {
            QCOMPARE(s.technique, ti.id);
            QVERIFY(validate(s.params).ok());
        }
    }
}

void QualitySweepTest::pomHoldsTheSeedsBaseline() {
    const std::vector<BenchSetting> sweep = qualitySweep(Technique::Pom);
    auto seeds = std::find_if(sweep.begin(), sweep.end(), [](const BenchSetting& s) {
        return s.params.minLayers == 8 && s.params.maxLayers == 32;
    });
    QVERIFY(seeds != sweep.end());
    QCOMPARE(seeds->label, std::string("layers 8-32"));
}

void QualitySweepTest::sweepsGrowInCost() {
    for (Technique t : {Technique::Steep, Technique::Pom, Technique::Relief, Technique::Secant}) {
        const std::vector<BenchSetting> sweep = qualitySweep(t);
        for (std::size_t k = 1; k < sweep.size(); ++k)
            QVERIFY(sweep[k].params.maxLayers > sweep[k - 1].params.maxLayers);
    }
    for (Technique t : {Technique::Cone, Technique::RelaxedCone, Technique::Pyramid}) {
        const std::vector<BenchSetting> sweep = qualitySweep(t);
        for (std::size_t k = 1; k < sweep.size(); ++k)
            QVERIFY(sweep[k].params.maxSteps > sweep[k - 1].params.maxSteps);
    }
}

void QualitySweepTest::labelsNameTheParametersUsed() {
    TraceParams p;
    p.minLayers = 4;
    p.maxLayers = 16;
    p.binarySteps = 5;
    p.secantSteps = 2;
    p.maxSteps = 24;
    QCOMPARE(settingLabel(Technique::Pom, p), std::string("layers 4-16"));
    QCOMPARE(settingLabel(Technique::Relief, p), std::string("layers 4-16, binary 5"));
    QCOMPARE(settingLabel(Technique::Secant, p), std::string("layers 4-16, secant 2"));
    // relaxed-cone solves its last step exactly: no binary steps to name.
    QCOMPARE(settingLabel(Technique::RelaxedCone, p), std::string("steps 24"));
    QCOMPARE(settingLabel(Technique::Pyramid, p), std::string("nodes 24"));
    QCOMPARE(settingLabel(Technique::Offset, p), std::string());
    QCOMPARE(settingLabel(Technique::Exact, p), std::string());
}

void QualitySweepTest::techniqueLists() {
    Result<std::vector<Technique>> all = parseTechniqueList("all");
    QVERIFY(all.ok());
    QCOMPARE(all->front(), Technique::Offset);
    QCOMPARE(all->back(), Technique::Exact);
    QVERIFY(std::find(all->begin(), all->end(), Technique::None) == all->end());

    Result<std::vector<Technique>> two = parseTechniqueList("pom, pyramid");
    QVERIFY(two.ok());
    QCOMPARE(*two, (std::vector<Technique>{Technique::Pom, Technique::Pyramid}));

    Result<std::vector<Technique>> unknown = parseTechniqueList("pom,magic");
    QVERIFY(!unknown.ok());
    QCOMPARE(unknown.error().message,
             std::string("unknown technique 'magic' in the technique list"));
    QVERIFY(!parseTechniqueList("pom,pom").ok());
    QVERIFY(!parseTechniqueList("none").ok());
    QVERIFY(!parseTechniqueList("").ok());
}

void QualitySweepTest::sweepsByHand() {
    Result<std::vector<BenchSetting>> steps = parseSweep("relaxed-cone:max-steps=16, 40");
    QVERIFY(steps.ok());
    QCOMPARE(steps->size(), std::size_t(2));
    QCOMPARE((*steps)[1].params.maxSteps, 40);
    QCOMPARE((*steps)[1].params.binarySteps, info(Technique::RelaxedCone).defaults.binarySteps);
    QCOMPARE((*steps)[1].label, std::string("steps 40"));

    Result<std::vector<BenchSetting>> layers = parseSweep("pom:layers=8-32,12-48");
    QVERIFY(layers.ok());
    QVERIFY((*layers)[0].isDefault);
    QCOMPARE((*layers)[1].params.minLayers, 12);
    QCOMPARE((*layers)[1].params.maxLayers, 48);

    auto error = [](std::string_view spec) {
        Result<std::vector<BenchSetting>> r = parseSweep(spec);
        return r.ok() ? std::string() : r.error().message;
    };
    // The message lists what the technique reads, never the parameter it refuses.
    QCOMPARE(error("pom:binary-steps=4"), std::string("pom has no parameter 'binary-steps' (it "
                                                      "reads layers)"));
    QCOMPARE(error("relief:max-steps=4"), std::string("relief has no parameter 'max-steps' (it "
                                                      "reads layers, binary-steps)"));
    QCOMPARE(error("pom:layers=8"), std::string("'8' is not a value of layers (MIN-MAX)"));
    QCOMPARE(error("pom:layers=40-8"), std::string("pom: min layers (40) exceed max layers (8)"));
    QCOMPARE(error("magic:max-steps=3"), std::string("unknown technique 'magic' in the sweep"));
    QCOMPARE(error("cone=3"),
             std::string("a sweep is TECHNIQUE:PARAMETER=V1,V2,..., not 'cone=3'"));
    // Numbers as every option reads them (parallax/NumberText.h): never wrapped, never partly read.
    QCOMPARE(error("cone:max-steps=3x"), std::string("cone:max-steps: '3x' is not a number"));
    QCOMPARE(error("cone:max-steps=4294967424"),
             std::string("cone:max-steps: '4294967424' is out of range (1 to 16777216)"));
    QCOMPARE(error("cone:max-steps=nan"),
             std::string("cone:max-steps: 'nan' is not a finite number"));
    QCOMPARE(error("pom:layers=8-99999999999999999999"),
             std::string("pom:layers: '99999999999999999999' is out of range (1 to 4096)"));
    QCOMPARE(error("relief:binary-steps=2.5"),
             std::string("relief:binary-steps: '2.5' is not a whole number"));
}

QTEST_APPLESS_MAIN(QualitySweepTest)
#include "QualitySweepTest.moc"
