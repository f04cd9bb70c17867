// Cone maps kept on disk between recommendations (RecommendConfig::cacheDir): a second run reads
// them instead of baking and answers the same; a damaged file is baked again and replaced; a
// cache that cannot be written (or a full disk) costs nothing but time; the oldest files go first
// when the cache is full, and files it did not name are never touched.

#include "parallax/eval/Recommendation.h"
#include "parallax/io/Temporaries.h"
#include "parallax/sample/ProceduralMaps.h"

#include <QTemporaryDir>
#include <QtTest>
#include <filesystem>
#include <fstream>

using namespace px;
namespace fs = std::filesystem;

namespace {

RecommendConfig configFor(const HeightField& field, const std::string& dir) {
    RecommendConfig c;
    c.field = std::make_shared<const HeightField>(field);
    c.name = "test.png";
    c.maxPolarDeg = 70.0;
    c.raysPerSide = 8;
    c.techniques = {Technique::Pom, Technique::Cone, Technique::RelaxedCone};
    c.cacheDir = dir;
    return c;
}

std::vector<fs::path> filesIn(const fs::path& dir) {
    std::vector<fs::path> files;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec))
        files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

// The same answer: the chosen setting and every setting's cost.
bool sameAnswer(const Recommendation& a, const Recommendation& b) {
    if (a.found != b.found || a.measured.size() != b.measured.size() ||
        a.chosen.setting.technique != b.chosen.setting.technique ||
        a.chosen.setting.label != b.chosen.setting.label || a.chosen.cost != b.chosen.cost)
        return false;
    for (std::size_t i = 0; i < a.measured.size(); ++i)
        if (a.measured[i].cost != b.measured[i].cost || a.measured[i].meets != b.measured[i].meets)
            return false;
    return true;
}

} // namespace

class ConeCacheTest : public QObject {
    Q_OBJECT
    const HeightField m_stones = makeProceduralMap(ProceduralMap::Stones, 48, 40, 3);

private slots:
    void keptBakesGiveTheSameAnswer() {
        QTemporaryDir dir;
        const std::string cache = dir.filePath("cones").toStdString();
        clearRecommendationCache();
        Result<Recommendation> first = recommend(configFor(m_stones, cache));
        QVERIFY(first);
        QCOMPARE(first->mapsBaked, 2);
        QCOMPARE(first->mapsFromDisk, 0);
        const std::vector<fs::path> files = filesIn(cache);
        QCOMPARE(files.size(), std::size_t(2)); // the two kinds, no temporaries left
        for (const fs::path& f : files)
            QVERIFY2(f.extension() == ".pxcone", f.c_str());

        clearRecommendationCache(); // another run of the command line
        Result<Recommendation> second = recommend(configFor(m_stones, cache));
        QVERIFY(second);
        QCOMPARE(second->mapsBaked, 0);
        QCOMPARE(second->mapsFromDisk, 2);
        QVERIFY(sameAnswer(*first, *second));

        // Another map of the same size is baked, not read.
        clearRecommendationCache();
        Result<Recommendation> other =
            recommend(configFor(makeProceduralMap(ProceduralMap::Stones, 48, 40, 4), cache));
        QVERIFY(other);
        QCOMPARE(other->mapsBaked, 2);
        QCOMPARE(filesIn(cache).size(), std::size_t(4));
    }

    // The files are named after the bakers' fingerprint (their output on a small fixed map): the
    // bakers of issue 32 bake other cones than those before them, so they name their files
    // otherwise and never read an entry the earlier bakers wrote (whose fingerprint, at fc05edd,
    // was 92cd7ed75ac95a8c).
    void newBakersStartNewEntries() {
        QTemporaryDir dir;
        const std::string cache = dir.path().toStdString();
        clearRecommendationCache();
        QVERIFY(recommend(configFor(m_stones, cache)));
        const std::vector<fs::path> files = filesIn(cache);
        QCOMPARE(files.size(), std::size_t(2));
        for (const fs::path& f : files) {
            const std::string name = f.filename().string();
            QVERIFY2(name.find("-92cd7ed75ac95a8c.pxcone") == std::string::npos, name.c_str());
            // The fingerprint is the name's last field: the same for both kinds.
            QCOMPARE(name.substr(name.rfind('-')),
                     files.front().filename().string().substr(
                         files.front().filename().string().rfind('-')));
        }
    }

    void damagedFilesAreBakedAgain_data() {
        QTest::addColumn<bool>("truncate");
        QTest::addRow("a flipped byte") << false;
        QTest::addRow("cut short") << true;
    }
    void damagedFilesAreBakedAgain() {
        QFETCH(bool, truncate);
        QTemporaryDir dir;
        const std::string cache = dir.path().toStdString();
        clearRecommendationCache();
        Result<Recommendation> first = recommend(configFor(m_stones, cache));
        QVERIFY(first);
        const fs::path damaged = filesIn(cache).front();
        const auto size = fs::file_size(damaged);
        if (truncate) {
            fs::resize_file(damaged, size - 5);
        } else {
            std::fstream f(damaged, std::ios::in | std::ios::out | std::ios::binary);
            f.seekp(std::streamoff(size - 7));
            f.put('\x5a');
        }
        clearRecommendationCache();
        Result<Recommendation> again = recommend(configFor(m_stones, cache));
        QVERIFY(again);
        QCOMPARE(again->mapsBaked, 1);
        QCOMPARE(again->mapsFromDisk, 1);
        QVERIFY(sameAnswer(*first, *again));
        QCOMPARE(fs::file_size(damaged), size); // replaced by a whole one
        clearRecommendationCache();
        Result<Recommendation> third = recommend(configFor(m_stones, cache));
        QVERIFY(third);
        QCOMPARE(third->mapsFromDisk, 2);
    }

    void aCacheThatCannotBeWrittenCostsOnlyTime() {
        QTemporaryDir dir;
        const fs::path blocker = dir.filePath("blocker").toStdString();
        std::ofstream(blocker) << "not a folder";
        clearRecommendationCache();
        Result<Recommendation> r = recommend(configFor(m_stones, (blocker / "cones").string()));
        QVERIFY(r);
        QCOMPARE(r->mapsBaked, 2);
        QCOMPARE(filesIn(dir.path().toStdString()).size(), std::size_t(1));
        std::ifstream in(blocker);
        std::string text;
        std::getline(in, text);
        QCOMPARE(text, std::string("not a folder"));
    }

    // A full disk (the write fails part-way): the answer as without a cache, no file and no
    // temporary left, and a kept file from before untouched.
    void aFullDiskLeavesNothingBehind() {
        QTemporaryDir dir;
        const fs::path cache = dir.path().toStdString();
        clearRecommendationCache();
        Result<Recommendation> baked = recommend(configFor(m_stones, cache.string()));
        QVERIFY(baked);
        const std::vector<fs::path> before = filesIn(cache);
        std::vector<std::uintmax_t> sizes;
        sizes.reserve(before.size());
        for (const fs::path& f : before)
            sizes.push_back(fs::file_size(f));
        px::TestHooks full1000;
        full1000.failWriteAt = 1000; // every cache write fails as on a full disk
        px::setTestHooks(full1000);
        const auto restore = qScopeGuard([] { px::setTestHooks({}); });
        clearRecommendationCache();
        const HeightField other = makeProceduralMap(ProceduralMap::Stones, 48, 40, 5);
        Result<Recommendation> full = recommend(configFor(other, cache.string()));
        QVERIFY(full);
        QCOMPARE(full->mapsBaked, 2);
        QCOMPARE(filesIn(cache), before); // no new file, no temporary
        for (std::size_t i = 0; i < before.size(); ++i)
            QCOMPARE(fs::file_size(before[i]), sizes[i]);
        clearRecommendationCache();
        px::setTestHooks({});
        Result<Recommendation> plain = recommend(configFor(other, std::string()));
        QVERIFY(plain);
        QVERIFY(sameAnswer(*full, *plain));
    }

    void theOldestGoFirstAndOthersAreKept() {
        QTemporaryDir dir;
        const fs::path cache = dir.path().toStdString();
        std::ofstream(cache / "notes.txt") << "mine";
        std::ofstream(cache / "cone-mine.bin") << "mine too";
        clearRecommendationCache();
        RecommendConfig first = configFor(m_stones, cache.string());
        QVERIFY(recommend(first));
        std::uintmax_t one = 0; // the larger of the two files
        for (const fs::path& f : filesIn(cache))
            if (f.extension() == ".pxcone")
                one = std::max(one, fs::file_size(f));
        // Room for three files: the second map's two push out one of the first map's.
        RecommendConfig second =
            configFor(makeProceduralMap(ProceduralMap::Stones, 48, 40, 9), cache.string());
        second.cacheLimitBytes = 3 * one;
        clearRecommendationCache();
        QVERIFY(recommend(second));
        int kept = 0;
        for (const fs::path& f : filesIn(cache))
            kept += f.extension() == ".pxcone" ? 1 : 0;
        QCOMPARE(kept, 3);
        QVERIFY(fs::exists(cache / "notes.txt"));
        QVERIFY(fs::exists(cache / "cone-mine.bin"));
        // The second map's, written last, are both there: read, not baked.
        clearRecommendationCache();
        second.cacheLimitBytes = std::uint64_t(2) << 30;
        Result<Recommendation> again = recommend(second);
        QVERIFY(again);
        QCOMPARE(again->mapsFromDisk, 2);
    }
};

QTEST_APPLESS_MAIN(ConeCacheTest)
#include "ConeCacheTest.moc"
