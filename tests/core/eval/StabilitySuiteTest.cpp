// The stability suite: every case runs and passes , each documented case is
// there, a row fails when its bound is broken, input rejection is checked, and it can be cancelled.

#include "parallax/eval/StabilitySuite.h"

#include "parallax/trace/TraceScene.h"

#include <QtTest>
#include <cstdlib>
#include <random>
#include <set>
#include <string>

using namespace px;

class StabilitySuiteTest : public QObject {
    Q_OBJECT

private slots:
    void everyCasePasses();
    void theIssuesCasesAreThere();
    void everyTechniqueDocumentsABound();
    void fetchCaps();
    void boundsFailWhenBroken();
    void unknownCase();
    void cancel();

private:
    void everyCasePassesWith(unsigned seed);
};

// With seed 1 and one that changes from run to run (seed 5 once failed `steep` on the 1x1 map,
// whose random constant seed 1 happened to put on a layer).
void StabilitySuiteTest::everyCasePasses() {
    const char* given = std::getenv("PX_TEST_SEED");
    const unsigned seed = given ? static_cast<unsigned>(std::strtoul(given, nullptr, 10))
                                : std::random_device{}() % 100000u;
    qInfo("map seeds 1 and %u (PX_TEST_SEED=%u repeats it)", seed, seed);
    for (unsigned s : {1u, seed})
        everyCasePassesWith(s);
}

void StabilitySuiteTest::everyCasePassesWith(unsigned seed) {
    StabilityOptions options;
    options.seed = seed;
    Result<std::vector<StabilityRow>> rows = runStabilitySuite(options);
    QVERIFY(rows.ok());
    std::set<std::string> cases;
    for (const StabilityRow& r : *rows) {
        cases.insert(r.caseName);
        QVERIFY2(r.passed, qPrintable(QString::fromStdString("seed " + std::to_string(seed) + ", " +
                                                             r.caseName + " " + r.technique + ": " +
                                                             r.failure + " (" + r.figure + ")")));
        QVERIFY2(!r.figure.empty(), r.caseName.c_str());
        if (r.technique != "loader")
            QCOMPARE(r.stats.invalid, std::int64_t(0));
    }
    QCOMPARE(cases.size(), stabilityCases().size());
    QVERIFY(suitePassed(*rows));
}

void StabilitySuiteTest::theIssuesCasesAreThere() {
    std::set<std::string_view> names;
    for (const StabilityCaseInfo& c : stabilityCases())
        names.insert(c.name);
    for (std::string_view required : {"polar-89.9",
                                      "scale-0",
                                      "tiny-scale",
                                      "huge-scale",
                                      "flat-0",
                                      "flat-1",
                                      "checkerboard",
                                      "needles",
                                      "vertical-steps",
                                      "thin-cracks",
                                      "1x1",
                                      "non-power-of-two",
                                      "uv0-near-4096",
                                      "zero-cones",
                                      "nan-in-float-map",
                                      "foreign-cone-map",
                                      "adversarial-spike-flat",
                                      "adversarial-walls",
                                      "adversarial-treads",
                                      "adversarial-pits",
                                      "adversarial-terraces",
                                      "adversarial-outliers",
                                      "adversarial-spike-flat-clamp",
                                      "adversarial-walls-clamp",
                                      "adversarial-treads-clamp",
                                      "adversarial-pits-clamp",
                                      "adversarial-terraces-clamp",
                                      "adversarial-outliers-clamp"})
        QVERIFY2(names.count(required) == 1, required.data());
}

void StabilitySuiteTest::everyTechniqueDocumentsABound() {
    for (const TechniqueInfo& ti : allTechniques()) {
        if (!ti.parallax)
            continue;
        const auto rules = boundRules();
        QVERIFY2(std::any_of(rules.begin(), rules.end(),
                             [&](const BoundRule& r) { return r.technique == ti.id; }),
                 ti.name.data());
    }
}

void StabilitySuiteTest::fetchCaps() {
    TraceParams p;
    p.maxLayers = 32;
    p.binarySteps = 6;
    p.secantSteps = 3;
    p.maxSteps = 24;
    const long long cells = 100; // the exact walk that finishes the cone marches and the pyramid
    QCOMPARE(fetchCap(Technique::Offset, p, cells), 1LL);
    QCOMPARE(fetchCap(Technique::Pom, p, cells), 33LL);
    QCOMPARE(fetchCap(Technique::Relief, p, cells), 39LL);
    QCOMPARE(fetchCap(Technique::Secant, p, cells), 36LL);
    QCOMPARE(fetchCap(Technique::RelaxedCone, p, cells), 124LL);
    QCOMPARE(fetchCap(Technique::Cone, p, cells), 124LL);
    QCOMPARE(fetchCap(Technique::Pyramid, p, cells), 148LL);
    QCOMPARE(fetchCap(Technique::Exact, p, cells), 24LL);
    // A ray 2.5 x 0.5 tiles on a 10 x 20 map crosses at most 25 + 10 borders, plus its first
    // cell and one per axis for rounding.
    QCOMPARE(rayCellBound(glm::vec2(-2.5f, 0.5f), 10, 20), 38LL);
}

void StabilitySuiteTest::boundsFailWhenBroken() {
    // Four rays on a 10 x 10 map; the third ends 1 texel past the reference, the fourth 3 short.
    const std::vector<TraceResult> ref(4, TraceResult{0.5, 0.5, 0.5f, 1});
    std::vector<TraceResult> hits = ref;
    hits[2] = TraceResult{0.6, 0.5, 0.6f, 1};
    hits[3] = TraceResult{0.2, 0.5, 0.2f, 1};
    auto check = [&](BoundKind kind, double limit) {
        return checkBound(ErrorBound{kind, limit, "rule"}, hits, ref, 10, 10);
    };
    QCOMPARE(check(BoundKind::MaxTexels, 3.0).failure, std::string());
    QCOMPARE(check(BoundKind::MaxTexels, 2.9).failure, std::string("error above the bound"));
    // Beside the bound, the tail every figure reports: p99, max and the rays on another surface.
    QCOMPARE(check(BoundKind::MaxTexels, 2.9).figure,
             std::string("max 3 <= 2.9 texels (p99 3, max 3, 1 rays > 2 texels)"));
    QCOMPARE(check(BoundKind::None, 0.0).figure,
             std::string("no bound: rule (p99 3, max 3, 1 rays > 2 texels)"));
    QCOMPARE(check(BoundKind::P99Texels, 2.9).failure, std::string("p99 error above the bound"));
    QCOMPARE(check(BoundKind::NoOvershoot, 1.0).failure, std::string());
    QCOMPARE(check(BoundKind::NoOvershoot, 0.5).failure, std::string("a ray ended past the hit"));
    QCOMPARE(check(BoundKind::MaxDepth, 0.31).failure, std::string());
    QVERIFY(!check(BoundKind::MaxDepth, 0.29).failure.empty());
    QCOMPARE(check(BoundKind::None, 0.0).failure, std::string());
    hits[0].u = std::nan("");
    QCOMPARE(check(BoundKind::MaxTexels, 3.0).failure, std::string());
}

void StabilitySuiteTest::unknownCase() {
    StabilityOptions options;
    options.cases = {"scale-0", "bogus"};
    Result<std::vector<StabilityRow>> rows = runStabilitySuite(options);
    QVERIFY(!rows.ok());
    QCOMPARE(rows.error().message, std::string("unknown stability case 'bogus'"));
}

void StabilitySuiteTest::cancel() {
    std::atomic<bool> stop{false};
    int calls = 0;
    EvalControl control;
    control.cancel = &stop;
    control.progress = [&](const EvalProgress&) {
        ++calls;
        stop = true;
    };
    Result<std::vector<StabilityRow>> rows = runStabilitySuite({}, control);
    QVERIFY(!rows.ok());
    QVERIFY(isEvaluationCancelled(rows.error()));
    QCOMPARE(calls, 1);
}

QTEST_APPLESS_MAIN(StabilitySuiteTest)
#include "StabilitySuiteTest.moc"
