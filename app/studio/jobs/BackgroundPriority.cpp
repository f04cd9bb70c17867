#include "jobs/BackgroundPriority.h"

#include <future>
#include <memory>
#include <tbb/task_arena.h>
#include <tbb/task_scheduler_observer.h>
#include <thread>

#ifdef __linux__
#include <cerrno>
#include <sys/resource.h>
#include <unistd.h>
#endif

namespace px::studio {

namespace {

bool setThisThreadsNice(int nice) {
#ifdef __linux__
    // Linux applies a thread id's nice value to that thread alone.
    return setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), nice) == 0;
#else
    (void)nice;
    return false;
#endif
}

// Lowers each worker as it enters the arena, and raises it again as it leaves (where allowed).
class WorkerPriority : public tbb::task_scheduler_observer {
public:
    explicit WorkerPriority(tbb::task_arena& arena) : tbb::task_scheduler_observer(arena) {
        observe(true);
    }
    WorkerPriority(const WorkerPriority&) = delete;
    WorkerPriority& operator=(const WorkerPriority&) = delete;
    ~WorkerPriority() override { observe(false); }
    void on_scheduler_entry(bool isWorker) override {
        if (!isWorker)
            return;
        t_before = thisThreadsNice();
        if (t_before < kBackgroundNice)
            setThisThreadsNice(kBackgroundNice);
    }
    void on_scheduler_exit(bool isWorker) override {
        if (isWorker && t_before < kBackgroundNice)
            setThisThreadsNice(t_before);
    }

private:
    static thread_local int t_before;
};

thread_local int WorkerPriority::t_before = 0;

} // namespace

struct BackgroundArena::Impl {
    tbb::task_arena arena;
    // Only where a worker can be raised again: TBB's workers serve every arena after this one.
    std::unique_ptr<WorkerPriority> observer =
        canRaisePriority() ? std::make_unique<WorkerPriority>(arena) : nullptr;
};

BackgroundArena::BackgroundArena() : m_impl(std::make_unique<Impl>()) {}

BackgroundArena::~BackgroundArena() = default;

void BackgroundArena::execute(const std::function<void()>& work) {
    m_impl->arena.execute(work);
}

bool BackgroundArena::lowersWorkers() const {
    return m_impl->observer != nullptr;
}

int thisThreadsNice() {
#ifdef __linux__
    errno = 0;
    const int nice = getpriority(PRIO_PROCESS, static_cast<id_t>(gettid()));
    return errno == 0 ? nice : 0;
#else
    return 0;
#endif
}

int tbbWorkerNice() {
    // An enqueued task runs on a worker, never on the thread that waits here.
    std::promise<int> nice;
    tbb::task_arena arena(tbb::task_arena::attach{});
    arena.enqueue([&nice] { nice.set_value(thisThreadsNice()); });
    return nice.get_future().get();
}

bool canRaisePriority() {
    // Tried on a thread of its own, which ends with it.
    bool raised = false;
    std::thread probe([&raised] {
        const int own = thisThreadsNice();
        raised = setThisThreadsNice(own + 1) && setThisThreadsNice(own);
    });
    probe.join();
    return raised;
}

void lowerThisThreadsPriority() {
    if (thisThreadsNice() < kBackgroundNice)
        setThisThreadsNice(kBackgroundNice);
}

} // namespace px::studio
