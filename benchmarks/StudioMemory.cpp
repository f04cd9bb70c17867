// The editor on a big height map, as an artist meets it: a 16-bit PNG of N² texels (8192 by
// default; value noise, or another generated map) loaded into a window with two viewports, then a
// cone bake and a view on `cone`. Reports the process's peak resident memory after the load and
// after the bake (VmHWM; the map's generation is freed and the peak restarted before the window
// opens) and the longest the event loop went without running a 10 ms timer through each phase.
// Needs a display (Xvfb will do) and, for the previews, GL 4.3.
//
//   parallax-bench-studio-memory [--size N] [--views 1..4] [--map noise|bricks|...]
//                                [--slow-events MS]
//                                [--trace-resizes on|off]
//
// Memory is measured here rather than in a unit test: what it reads depends on the GL driver
// (llvmpipe keeps textures in process memory, a GPU does not).

#include "StudioBenchSupport.h"
#include "jobs/BakeRunner.h"
#include "model/MaterialDocument.h"
#include "parallax/image/ImageFile.h"
#include "parallax/sample/ProceduralMaps.h"
#include "preview/GlSupport.h"
#include "preview/PreviewWidget.h"
#include "preview/Viewport.h"
#include "preview/ViewportGrid.h"
#include "window/MainWindow.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTemporaryDir>
#include <QTimer>
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <string>

using namespace px;
using namespace px::studio;
using namespace px::studio::bench;

namespace {

// A field of /proc/self/status in MiB (VmHWM: peak resident, VmRSS: resident now).
double statusMiB(const std::string& field) {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind(field + ":", 0) == 0)
            return std::stod(line.substr(field.size() + 1)) / 1024.0; // kB
    return -1.0;
}

// Restarts VmHWM at the current resident size (Linux: "5" to clear_refs).
bool restartPeak() {
    std::ofstream clear("/proc/self/clear_refs");
    clear << "5";
    return static_cast<bool>(clear);
}

// The longest gap between ticks of a 10 ms timer while `until` is false; with `reportMs` > 0,
// every gap that long is printed with the time it ended (QElapsedTimer's monotonic clock).
struct StallWatch {
    QElapsedTimer clock;
    qint64 last = 0, longest = 0;
    QTimer timer;
    explicit StallWatch(qint64 reportMs) {
        timer.setInterval(10);
        QObject::connect(&timer, &QTimer::timeout, [this, reportMs] {
            const qint64 now = clock.elapsed();
            longest = std::max(longest, now - last);
            if (reportMs > 0 && now - last >= reportMs)
                std::fprintf(stderr, "gap: %lld ms, ended at monotonic %.3f\n",
                             static_cast<long long>(now - last),
                             (clock.msecsSinceReference() + now) / 1000.0);
            last = now;
        });
        clock.start();
        timer.start();
    }
};

// Draws a frame in every viewport shown, so the maps are on the GPU when memory is read.
bool drawEveryView(MainWindow& window, int views) {
    for (int i = 0; i < views; ++i) {
        PreviewWidget* preview = window.viewports()->viewport(i)->preview();
        if (!preview)
            return false;
        const int frames = preview->framesRendered();
        preview->update();
        if (!waitUntil([&] { return preview->framesRendered() > frames; }, 600000))
            return false;
        // Big maps go up on a worker meanwhile: until then the frame shows the maps before.
        if (!waitUntil([&] { return !preview->uploading(); }, 600000))
            return false;
        const int uploaded = preview->framesRendered();
        preview->update();
        if (!waitUntil([&] { return preview->framesRendered() > uploaded; }, 600000))
            return false;
    }
    return true;
}

std::string argumentOf(int argc, char** argv, const char* flag, const char* otherwise) {
    for (int i = 1; i + 1 < argc; i += 2)
        if (std::string(argv[i]) == flag)
            return argv[i + 1];
    return otherwise;
}

} // namespace

int main(int argc, char** argv) {
    setUpOpenGl();
    TracingApplication app(argc, argv);
    int size = 8192, views = 2;
    std::optional<ProceduralMap> map = ProceduralMap::Noise;
    for (int i = 1; i + 1 < argc; i += 2) {
        const std::string flag = argv[i];
        if (flag == "--size")
            size = std::atoi(argv[i + 1]);
        else if (flag == "--views")
            views = std::atoi(argv[i + 1]);
        else if (flag == "--slow-events")
            app.slowMs = std::atoi(argv[i + 1]);
        else if (flag == "--map")
            map = parseProceduralMap(argv[i + 1]);
        else if (flag == "--trace-resizes")
            app.traceResizes = std::string(argv[i + 1]) == "on";
    }
    app.since.start();
    auto mark = [&app](const char* phase) {
        if (app.slowMs > 0)
            std::fprintf(stderr, "-- %s at %.3f s\n", phase, app.since.elapsed() / 1000.0);
    };
    if (size < 16 || views < 1 || views > 4 || !map) {
        std::fprintf(stderr, "usage: parallax-bench-studio-memory [--size N>=16] [--views 1..4] "
                             "[--map noise|bricks|...] [--slow-events MS] "
                             "[--trace-resizes on|off]\n");
        return 2;
    }
    const GlProbe& gl = probeOpenGl();
    if (!gl.usable) {
        std::fprintf(stderr, "parallax-bench-studio-memory: no GL 4.3 (%s)\n",
                     gl.reason.toUtf8().constData());
        return 1;
    }
    QTemporaryDir dir;
    const std::string file = dir.filePath("height.png").toStdString();
    {
        const Status written = writeImage(file, makeProceduralMap(*map, size, size).toImage(),
                                          {PixelFormat::UInt16, false});
        if (!written) {
            std::fprintf(stderr, "%s\n", written.error().message.c_str());
            return 1;
        }
    }

    MainWindow window(gl.reason);
    window.setInteractive(false);
    window.newSample(ProceduralMap::Bricks, 64);
    window.viewports()->setLayoutCount(views);
    window.resize(1280, 720);
    window.show();
    if (!drawEveryView(window, views)) {
        std::fprintf(stderr, "parallax-bench-studio-memory: the window did not draw\n");
        return 1;
    }
    if (!restartPeak())
        std::fprintf(stderr, "parallax-bench-studio-memory: /proc/self/clear_refs is not writable: "
                             "the peaks include the map's generation\n");
    const double before = statusMiB("VmHWM");

    mark("load");
    StallWatch loadWatch(app.slowMs);
    QElapsedTimer clock;
    clock.start();
    if (!window.loadMap(MapKind::Height, QString::fromStdString(file)) ||
        window.document()->state().assets->height.width != size || !drawEveryView(window, views)) {
        std::fprintf(stderr, "parallax-bench-studio-memory: %s did not load\n", file.c_str());
        return 1;
    }
    const double loadSeconds = clock.elapsed() / 1000.0;
    const qint64 loadStall = loadWatch.longest;
    const double afterLoad = statusMiB("VmHWM");
    const double residentLoad = statusMiB("VmRSS");

    mark("bake");
    StallWatch bakeWatch(app.slowMs);
    clock.restart();
    window.startBake(BakeKind::Cone);
    if (!waitUntil([&] { return !window.baker()->isBusy(); }, 3600000) ||
        !window.document()->state().hasMap(MapKind::Cone)) {
        std::fprintf(stderr, "parallax-bench-studio-memory: the cone bake did not finish\n");
        return 1;
    }
    // Where the phase peaks: the bake, or the cone view's upload after it.
    const double bakePeak = statusMiB("VmHWM");
    const double residentBake = statusMiB("VmRSS");
    restartPeak();
    // What the bake was for: the last view traces `cone`, so its map is on the GPU too.
    mark("cone view");
    window.document()->edit("cone", [views](DocumentState& s) {
        s.setView(views - 1, {Technique::Cone, info(Technique::Cone).defaults});
    });
    if (!drawEveryView(window, views) ||
        window.document()->state().view(views - 1).technique != Technique::Cone) {
        std::fprintf(stderr, "parallax-bench-studio-memory: the cone view did not draw\n");
        return 1;
    }
    mark("end");
    const double bakeSeconds = clock.elapsed() / 1000.0;
    const qint64 bakeStall = bakeWatch.longest;
    const double afterBake = std::max(bakePeak, statusMiB("VmHWM"));
    const double viewPeak = statusMiB("VmHWM");
    const double residentView = statusMiB("VmRSS");

    std::printf("editor, %d² 16-bit height map (%s), %d viewports, %s\n", size,
                argumentOf(argc, argv, "--map", "noise").c_str(), views,
                gl.renderer.toUtf8().constData());
    std::printf("| phase | peak resident | longest event-loop gap | wall |\n|---|---|---|---|\n");
    std::printf("| window on the 64² sample | %.0f MiB | | |\n", before);
    std::printf("| height map loaded, drawn | %.0f MiB | %lld ms | %.1f s |\n", afterLoad,
                static_cast<long long>(loadStall), loadSeconds);
    std::printf("| cone map baked, a view on `cone` drawn | %.0f MiB | %lld ms | %.1f s |\n",
                afterBake, static_cast<long long>(bakeStall), bakeSeconds);
    std::printf("\nresident after the load %.0f MiB; the bake's peak %.0f MiB, resident after it "
                "%.0f MiB; the cone view's peak %.0f MiB, resident after it %.0f MiB\n",
                residentLoad, bakePeak, residentBake, viewPeak, residentView);
    return 0;
}
