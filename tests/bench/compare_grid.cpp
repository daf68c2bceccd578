// The Compare view's environment grid (issue 9): a 3x3 grid at 1600x1000 on whatever OpenGL this
// machine has (llvmpipe here), against the single view at the same size. Prints numbers; checks
// nothing (docs/benchmarks.md, "Compare grid", has the measured values and how they were taken).
// Needs a display: run it under tests/with-display.sh.
//
//   compare_grid [--frames N] [--stalls]
//
// Printed: the time from showing the grid to its first complete frame (every environment loaded
// on the worker threads and precomputed, every cell at full resolution) and the event loop's
// longest stall on the way (a 1 ms timer's longest gap; --stalls lists each over 50 ms), the IBL
// precomputes that ran (9 environments: 9, each once; how many on the view's lighting worker),
// the frame time while orbiting (linked cameras, reduced resolution, as a drag draws) and of full
// frames, for the 3x3 grid, a 2x2 grid and the single view at the same size. Environments: the
// CC0 HDRIs in the installed sample library (packaging/fetch-assets.sh) when there are nine, else
// built-in and uniform ones. The IBL disk cache is not used (every precompute is counted), IBL
// quality is the default preset.

#include "core/project/AssetLibrary.h"
#include "core/project/Project.h"
#include "ui/compare/CompareController.h"
#include "ui/compare/CompareView.h"
#include "ui/document/Document.h"
#include "ui/document/DocumentAssets.h"
#include "ui/viewport/CameraController.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportWidget.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QStandardPaths>
#include <QTimer>

#include <algorithm>
#include <cstdio>
#include <numeric>
#include <string>
#include <vector>

using namespace facet;

namespace {

constexpr int kWidth = 1600;
constexpr int kHeight = 1000;

// Runs the event loop until `signal` of `sender` fires (or `timeoutMs` passes); false on timeout.
template <typename Sender, typename Signal>
bool waitFor(Sender* sender, Signal signal, int timeoutMs = 120000)
{
    QEventLoop loop;
    QTimer timeout;
    timeout.setSingleShot(true);
    QObject::connect(&timeout, &QTimer::timeout, &loop, [&loop] { loop.exit(1); });
    QObject::connect(sender, signal, &loop, [&loop] { loop.exit(0); });
    timeout.start(timeoutMs);
    return loop.exec() == 0;
}

std::vector<std::string> nineEnvironments()
{
    const QDir hdri(QString::fromStdString(AssetLibrary::installed().folder) + QStringLiteral("/hdri"));
    std::vector<std::string> sources;
    for (const QString& file : hdri.entryList({QStringLiteral("*.exr")}, QDir::Files, QDir::Name))
        sources.push_back(hdri.filePath(file).toStdString());
    if (sources.size() >= 9) {
        sources.resize(9);
        return sources;
    }
    return {"studio", "sky", "uniform:1", "uniform:0.5", "uniform:0.25", "uniform:2", "uniform:0.75",
        "uniform:1.5", "uniform:0.125"};
}

struct Times {
    double meanMs = 0.0;
    double maxMs = 0.0;
    double renderMs = 0.0; // the renderer's own time (glFinish), mean
};

Times summarise(const std::vector<double>& ms, const std::vector<double>& renderMs)
{
    Times t;
    if (ms.empty())
        return t;
    t.meanMs = std::accumulate(ms.begin(), ms.end(), 0.0) / double(ms.size());
    t.maxMs = *std::max_element(ms.begin(), ms.end());
    t.renderMs = std::accumulate(renderMs.begin(), renderMs.end(), 0.0) / double(renderMs.size());
    return t;
}

// Orbit frames of the Compare view: each a camera step and the reduced frame it draws (wall
// clock from the step to the frame, as a drag feels it).
Times orbitCompare(Document& document, CompareView& view, int frames)
{
    std::vector<double> ms;
    std::vector<double> render;
    for (int i = 0; i < frames; ++i) {
        QElapsedTimer clock;
        clock.start();
        document.setCamera(CameraController::orbited(document.project().camera, 8.0, 0.0));
        view.markInteractive();
        if (!waitFor(&view, &CompareView::frameRendered))
            break;
        ms.push_back(double(clock.nsecsElapsed()) / 1e6);
        render.push_back(view.lastFrameStats().frameMs);
    }
    return summarise(ms, render);
}

Times fullCompare(Document& document, CompareView& view, int frames)
{
    std::vector<double> ms;
    std::vector<double> render;
    for (int i = 0; i < frames; ++i) {
        while (view.isPreviewing())
            waitFor(&view, &CompareView::frameRendered, 2000);
        QElapsedTimer clock;
        clock.start();
        document.setCamera(CameraController::orbited(document.project().camera, 8.0, 0.0));
        if (!waitFor(&view, &CompareView::frameRendered))
            break;
        ms.push_back(double(clock.nsecsElapsed()) / 1e6);
        render.push_back(view.lastFrameStats().frameMs);
    }
    return summarise(ms, render);
}

// The same for the single view (ViewportWidget draws on SceneController::sceneChanged).
Times orbitSingle(Document& document, ViewportWidget& view, int frames, bool reduced)
{
    std::vector<double> ms;
    std::vector<double> render;
    for (int i = 0; i < frames; ++i) {
        while (!reduced && view.isPreviewing())
            waitFor(&view, &ViewportWidget::frameRendered, 2000);
        QElapsedTimer clock;
        clock.start();
        document.setCamera(CameraController::orbited(document.project().camera, 8.0, 0.0));
        if (reduced)
            view.markInteractive();
        if (!waitFor(&view, &ViewportWidget::frameRendered))
            break;
        ms.push_back(double(clock.nsecsElapsed()) / 1e6);
        render.push_back(view.lastFrameStats().frameMs);
    }
    return summarise(ms, render);
}

void print(const char* what, const Times& t)
{
    std::printf("  %-38s step to frame: mean %6.1f ms, max %6.1f ms; renderer %6.1f ms\n", what, t.meanMs,
        t.maxMs, t.renderMs);
}

} // namespace

int main(int argc, char** argv)
{
    QStandardPaths::setTestModeEnabled(true);
    installViewportSurfaceFormat();
    QApplication app(argc, argv);
    int frames = 10;
    const QStringList arguments = app.arguments();
    if (const int at = int(arguments.indexOf(QStringLiteral("--frames")));
        at >= 0 && at + 1 < arguments.size())
        frames = std::max(1, arguments[at + 1].toInt());
    const bool listStalls = arguments.contains(QStringLiteral("--stalls"));

    const std::vector<std::string> sources = nineEnvironments();
    Project project = Project::defaultProject();
    project.compare = CompareLayout::defaultFor(project);
    project.compare.mode = CompareMode::Environments;
    project.compare.environments.cells.clear();
    for (const std::string& source : sources) {
        EnvironmentCell cell;
        cell.source = source;
        project.compare.environments.cells.push_back(cell);
    }

    Document document;
    SceneController scene(&document);
    CompareController controller(&document);
    document.setProject(project, QStringLiteral("bench"));

    std::printf("compare_grid: %dx%d, %d environments (%s), IBL quality %s, no disk cache\n", kWidth, kHeight,
        int(sources.size()), sources.front().find('/') != std::string::npos ? "CC0 HDRIs" : "built-in",
        toString(project.environment.quality));

    // --- 3x3 grid: first complete frame.
    CompareView view(&document, &scene, &controller);
    view.setUseDiskCache(false);
    view.resize(kWidth, kHeight);
    QElapsedTimer clock;
    clock.start();
    // The longest the event loop went without running a 1 ms timer: what a user's input waits.
    QElapsedTimer sinceTick;
    double longestStallMs = 0.0;
    QTimer ticks;
    ticks.setTimerType(Qt::PreciseTimer);
    QObject::connect(&ticks, &QTimer::timeout, [&] {
        longestStallMs = std::max(longestStallMs, double(sinceTick.nsecsElapsed()) / 1e6);
        if (listStalls && sinceTick.nsecsElapsed() > 50'000'000)
            std::printf("  stall of %.0f ms ending %lld ms after show, %llu frames drawn\n",
                double(sinceTick.nsecsElapsed()) / 1e6, static_cast<long long>(clock.elapsed()),
                static_cast<unsigned long long>(view.frameCount()));
        sinceTick.restart();
    });
    sinceTick.start();
    ticks.start(1);
    view.show();
    int framesToComplete = 0;
    while (clock.elapsed() < 600000) {
        if (!waitFor(&view, &CompareView::frameRendered))
            break;
        ++framesToComplete;
        if (!view.isLoading() && !view.lastFrameStats().reduced && view.lastError().isEmpty())
            break;
    }
    const double firstCompleteMs = double(clock.nsecsElapsed()) / 1e6;
    // The frame that completed it ended a gap the timer has not seen yet.
    longestStallMs = std::max(longestStallMs, double(sinceTick.nsecsElapsed()) / 1e6);
    ticks.stop();
    const CompareFrameStats first = view.lastFrameStats();
    std::printf(
        "3x3 grid\n  first complete grid: %.0f ms (%d frames drawn on the way; environments decoded: %d); "
        "longest event-loop stall on the way %.0f ms\n",
        firstCompleteMs, framesToComplete, view.assets()->loads(DocumentAssets::Kind::Environment),
        longestStallMs);
    std::printf("  IBL: %d environments asked for, %d precomputed, %d from disk, %d of them on the lighting "
                "worker\n",
        first.iblRequests, first.iblComputed, first.iblFromDisk, first.iblFromWorker);
    if (!view.lastError().isEmpty())
        std::printf("  error: %s\n", qPrintable(view.lastError()));
    print("orbit (reduced, 9 cells)", orbitCompare(document, view, frames));
    print("full frames (9 cells)", fullCompare(document, view, std::max(3, frames / 3)));
    std::printf("  IBL after orbiting: %d asked for, %d precomputed\n", view.lastFrameStats().iblRequests,
        view.lastFrameStats().iblComputed);

    // --- 2x2 grid (the target: as responsive as the single view).
    project = document.project();
    project.compare.environments.cells.resize(4);
    document.setProject(project, QStringLiteral("bench"));
    waitFor(&view, &CompareView::frameRendered);
    print("2x2 grid: orbit (reduced, 4 cells)", orbitCompare(document, view, frames));
    print("2x2 grid: full frames (4 cells)", fullCompare(document, view, std::max(3, frames / 3)));
    view.hide();

    // --- The single view at the same size.
    ViewportWidget single;
    single.resize(kWidth, kHeight);
    single.setSceneController(&scene);
    single.show();
    waitFor(&single, &ViewportWidget::frameRendered);
    while (single.lastFrameStats().loadingMaps || single.isPreviewing())
        waitFor(&single, &ViewportWidget::frameRendered, 2000);
    print("single view: orbit (reduced)", orbitSingle(document, single, frames, true));
    print("single view: full frames", orbitSingle(document, single, std::max(3, frames / 3), false));
    return 0;
}
