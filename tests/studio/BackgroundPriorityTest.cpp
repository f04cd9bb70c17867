// Bakes run below the GUI thread, and only bakes: the bake's own thread and the TBB workers while
// they bake run at kBackgroundNice, the GUI thread, Qt's global pool (loads, exports) and TBB's
// default arena (an environment's prefilter, the bench) at their own priority, before and after a
// bake (jobs/BackgroundPriority.h, jobs/BakeRunner.h). Run twice by ctest: as the machine lets it,
// and (PX_TEST_ORDINARY_USER=1) as an ordinary user, who cannot raise a thread's priority again
// (no CAP_SYS_NICE, RLIMIT_NICE 0): there the workers must never be left lowered.

#include "jobs/BackgroundPriority.h"

#include "ArenaProbe.h"
#include "jobs/BakeRunner.h"
#include "jobs/Baking.h"
#include "model/SampleMaterial.h"

#include <QTest>
#include <QThreadPool>
#include <QtConcurrent/QtConcurrentRun>
#include <atomic>
#include <linux/capability.h>
#include <sys/resource.h>
#include <sys/syscall.h>
#include <thread>
#include <unistd.h>

using namespace px;
using namespace px::studio;

namespace {

// The nice value of every thread of Qt's global pool: as many jobs as it has threads, each held
// until all have started, so each runs on a thread of its own.
std::vector<int> globalPoolNices() {
    QThreadPool* pool = QThreadPool::globalInstance();
    const int threads = pool->maxThreadCount();
    std::atomic<int> started{0};
    std::vector<QFuture<int>> jobs;
    jobs.reserve(static_cast<std::size_t>(threads));
    for (int i = 0; i < threads; ++i)
        jobs.push_back(QtConcurrent::run(pool, [&started, threads] {
            ++started;
            while (started.load() < threads)
                std::this_thread::yield();
            return thisThreadsNice();
        }));
    std::vector<int> nices;
    nices.reserve(jobs.size());
    for (QFuture<int>& job : jobs)
        nices.push_back(job.result());
    return nices;
}

} // namespace

class BackgroundPriorityTest : public QObject {
    Q_OBJECT

private slots:
    // As an ordinary user: CAP_SYS_NICE dropped from this thread (every thread made later
    // inherits it), RLIMIT_NICE 0.
    void initTestCase() {
        if (qEnvironmentVariableIntValue("PX_TEST_ORDINARY_USER") != 1)
            return;
        __user_cap_header_struct header{_LINUX_CAPABILITY_VERSION_3, 0};
        __user_cap_data_struct data[2] = {};
        QVERIFY(syscall(SYS_capget, &header, data) == 0);
        const unsigned bit = 1u << (CAP_SYS_NICE % 32);
        data[CAP_SYS_NICE / 32].effective &= ~bit;
        data[CAP_SYS_NICE / 32].permitted &= ~bit;
        data[CAP_SYS_NICE / 32].inheritable &= ~bit;
        QVERIFY(syscall(SYS_capset, &header, data) == 0);
        const rlimit none{0, 0};
        QVERIFY(setrlimit(RLIMIT_NICE, &none) == 0);
        QVERIFY2(!canRaisePriority(), "still allowed to raise a thread's priority");
    }

    // A cone bake in the editor's runner: its thread at kBackgroundNice; the GUI thread, every
    // thread of Qt's global pool and TBB's default arena as they were, before and after.
    void bakesRunBelowTheGuiThreadAlone() {
        const int gui = thisThreadsNice();
        QVERIFY2(gui < kBackgroundNice, "the test runs at a nice value below the background's");
        BakeRunner runner;
        QCOMPARE(tbbWorkerNice(), gui); // a runner alone lowers nothing
        std::optional<BakeOutcome> outcome;
        connect(&runner, &BakeRunner::finished, this,
                [&outcome](const BakeOutcome& o) { outcome = o; });
        // The global pool's threads exist (and would be reused) before the bake starts.
        for (int nice : globalPoolNices())
            QCOMPARE(nice, gui);
        runner.start(makeBakeRequest(makeSampleState(ProceduralMap::Bricks, 64), BakeKind::Cone));
        QTRY_VERIFY_WITH_TIMEOUT(outcome.has_value(), 60000);
        QVERIFY(outcome->error.isEmpty());
        QCOMPARE(outcome->threadNice, kBackgroundNice);
        QCOMPARE(thisThreadsNice(), gui);
        for (int nice : globalPoolNices())
            QCOMPARE(nice, gui); // loads and exports run as before
        // Every worker of TBB's default arena too, whether or not the system lets a thread rise.
        for (const auto& [thread, nice] : test::threadNicesInDefaultLoop())
            QCOMPARE(nice, gui);
    }

    // In the background arena every worker runs lowered (where it can rise again after) and the
    // calling thread as it was; after it, every worker is back at its own priority.
    void arenaWorkersAreLoweredWhileTheyWorkThere() {
        const int gui = thisThreadsNice();
        const int caller = static_cast<int>(gettid());
        BackgroundArena arena;
        QCOMPARE(arena.lowersWorkers(), canRaisePriority());
        const std::map<int, int> seen = test::threadNicesInLoop(arena);
        QCOMPARE(thisThreadsNice(), gui);
        int workers = 0;
        for (const auto& [thread, nice] : seen) {
            QCOMPARE(nice, thread == caller || !arena.lowersWorkers() ? gui : kBackgroundNice);
            workers += thread != caller;
        }
        if (std::thread::hardware_concurrency() > 1)
            QVERIFY(workers >= 1);
        for (const auto& [thread, nice] : test::threadNicesInDefaultLoop())
            QCOMPARE(nice, gui);
    }
};

QTEST_GUILESS_MAIN(BackgroundPriorityTest)
#include "BackgroundPriorityTest.moc"
