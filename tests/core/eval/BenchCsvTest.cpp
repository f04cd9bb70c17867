// The bench CSV: the documented header, one line per row, parameters only where the technique
// reads them, quoting of free text.

#include "parallax/eval/BenchCsv.h"

#include <QtTest>

using namespace px;

class BenchCsvTest : public QObject {
    Q_OBJECT

private slots:
    void headerAndRows();
    void fields();
    void readsBackWhatItWrote();
    void readsReportsWithoutGpuErrors();
    void refusesOtherFiles();
};

namespace {

BenchReport report() {
    BenchReport r;
    r.polarDeg = {80.0};
    r.azimuthDeg = 35.0;
    r.rays = 128;
    BenchRow row;
    row.map = "bricks, old.png";
    row.width = 256;
    row.height = 128;
    row.scale = 0.05f;
    row.polarDeg = 80.0;
    row.setting = qualitySweep(Technique::Pom)[1];
    row.stats.meanError = 1.5;
    row.stats.p99Error = 12.25;
    row.stats.maxError = 40.0;
    row.stats.wrongSurface = 321;
    row.stats.meanFetches = 27.5;
    row.stats.p99Fetches = 33;
    row.stats.maxFetches = 33;
    row.cpuNsPerRay = 812.345;
    row.gpuRenderer = "no GPU timing: no renderer";
    r.rows.push_back(row);
    BenchRow pooled = row;
    pooled.pooled = true;
    pooled.map = "all";
    pooled.scale.reset();
    pooled.setting = defaultSetting(Technique::Pyramid);
    pooled.gpuMsPerFrame = 241.5;
    pooled.gpuRenderer = "llvmpipe (LLVM 15.0.6, 256 bits) [software]";
    HitErrorStats gpu;
    gpu.meanError = 0.25;
    gpu.p99Error = 0.5;
    gpu.maxError = 2.0;
    gpu.meanFetches = 18.5;
    pooled.gpuStats = gpu;
    pooled.gpuKernels = "production";
    r.pooled.push_back(pooled);
    return r;
}

QStringList lines(const std::string& csv) {
    QStringList l = QString::fromStdString(csv).split('\n');
    if (!l.isEmpty() && l.back().isEmpty())
        l.pop_back();
    return l;
}

} // namespace

void BenchCsvTest::headerAndRows() {
    const QStringList l = lines(benchCsv(report()));
    QCOMPARE(l.size(), 3);
    QCOMPARE(l[0], QString::fromLatin1(kBenchCsvHeader.data(), kBenchCsvHeader.size()));
    QCOMPARE(l[0].split(',').size(), 32);
}

void BenchCsvTest::fields() {
    const QStringList l = lines(benchCsv(report()));
    QCOMPARE(l[1], QString("\"bricks, old.png\",256,128,repeat,0.05,80,35,128,pom,layers 8-32,1,"
                           "8,32,,,,1.5,12.25,40,321,0,27.5,33,33,812.3,,"
                           "no GPU timing: no renderer,,,,,"));
    QCOMPARE(l[2], QString("all,,,repeat,,80,35,128,pyramid,nodes 65536,1,,,,,65536,1.5,12.25,40,"
                           "321,0,27.5,33,33,812.3,241.500,"
                           "\"llvmpipe (LLVM 15.0.6, 256 bits) [software]\","
                           "production,0.25,0.5,2,18.5"));
}

void BenchCsvTest::readsBackWhatItWrote() {
    const std::string csv = benchCsv(report());
    Result<BenchReport> back = parseBenchCsv(csv, "r.csv");
    QVERIFY2(back.ok(), back.ok() ? "" : back.error().message.c_str());
    QCOMPARE(back->rows.size(), std::size_t(1));
    QCOMPARE(back->pooled.size(), std::size_t(1));
    QCOMPARE(back->pooled[0].setting.technique, Technique::Pyramid);
    QCOMPARE(back->pooled[0].setting.params.maxSteps, 65536);
    QCOMPARE(back->rows[0].setting.params.maxLayers, 32);
    QCOMPARE(back->polarDeg, std::vector<double>{80.0});
    QVERIFY(!back->rows[0].gpuStats.has_value());
    QVERIFY(back->pooled[0].gpuStats.has_value());
    QCOMPARE(back->pooled[0].gpuStats->p99Error, 0.5);
    QCOMPARE(back->pooled[0].gpuKernels, std::string("production"));
    QCOMPARE(benchCsv(*back), csv);
}

// Reports written before the GPU kernels' errors were columns still read (docs/bench/ holds one).
void BenchCsvTest::readsReportsWithoutGpuErrors() {
    std::string csv = benchCsv(report());
    QStringList l = lines(csv);
    std::string old = std::string(kBenchCsvHeaderV1) + "\n";
    for (int i = 1; i < l.size(); ++i) {
        QStringList f = l[i].split(',');
        old += f.mid(0, f.size() - 5).join(',').toStdString() + "\n";
    }
    Result<BenchReport> back = parseBenchCsv(old, "v1.csv");
    QVERIFY2(back.ok(), back.ok() ? "" : back.error().message.c_str());
    QCOMPARE(back->pooled.size(), std::size_t(1));
    QVERIFY(!back->pooled[0].gpuStats.has_value());
    QCOMPARE(back->pooled[0].gpuMsPerFrame.value_or(0.0), 241.5);
    // A V1 header with the new columns' values is a malformed file, not a silent misread.
    QVERIFY(!parseBenchCsv(std::string(kBenchCsvHeaderV1) + "\n" + l[2].toStdString() + "\n",
                           "mixed.csv")
                 .ok());
}

void BenchCsvTest::refusesOtherFiles() {
    Result<BenchReport> r = parseBenchCsv("i,j,u,v,t,fetches\n0,0,0.5,0.5,1,1\n", "trace.csv");
    QVERIFY(!r.ok());
    QCOMPARE(r.error().message,
             std::string("trace.csv: not a bench report: the header differs from the bench's"));
    std::string csv = benchCsv(report());
    csv.insert(csv.rfind("pyramid"), "x");
    r = parseBenchCsv(csv, "r.csv");
    QVERIFY(!r.ok());
    QCOMPARE(r.error().message, std::string("r.csv: line 3: unknown technique 'xpyramid'"));
    QVERIFY(!parseBenchCsv(std::string(kBenchCsvHeader) + "\n", "empty.csv").ok());
    QVERIFY(!parseBenchCsv(std::string(kBenchCsvHeader) + "\nall,1,2\n", "short.csv").ok());
}

QTEST_APPLESS_MAIN(BenchCsvTest)
#include "BenchCsvTest.moc"
