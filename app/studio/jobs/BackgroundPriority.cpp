#include "jobs/BackgroundPriority.h"

#include <future>
#include <tbb/task_arena.h>
#include <tbb/task_scheduler_observer.h>

#ifdef __linux__
#include <cerrno>
#include <sys/resource.h>
#include <unistd.h>
#endif

namespace px::studio {

namespace {

// Lowers each TBB worker's priority as it enters the arena.
class WorkerPriority : public tbb::task_scheduler_observer {
public:
    WorkerPriority() { observe(true); }
    WorkerPriority(const WorkerPriority&) = delete;
    WorkerPriority& operator=(const WorkerPriority&) = delete;
    ~WorkerPriority() override { observe(false); }
    void on_scheduler_entry(bool isWorker) override {
        if (isWorker)
            lowerThisThreadsPriority();
    }
};

} // namespace

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

void lowerThisThreadsPriority() {
#ifdef __linux__
    // Linux applies a thread id's nice value to that thread alone.
    if (thisThreadsNice() < kBackgroundNice)
        setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), kBackgroundNice);
#endif
}

void lowerTbbWorkersPriority() {
    static WorkerPriority observer;
}

} // namespace px::studio
