// Prints when the window's still view first changes while it refines by FIS, and when it is done
// (issue 30: with Lighting = FIS the image did not change for about 60 s at 1193x902 on llvmpipe,
// then popped in). The real MainWindow at 1193x902 on the default project (fis, 1024 samples:
// levels of 64, 256 and 1024, FrameRenderer::fisRefinementLevels), timed from its first frame;
// also the longest gap between two event-loop turns meanwhile (how long input waits), overall and
// while the refinement draws, and how many turns took longer than 100 ms.
// Checks nothing: it measures. Usage (needs a display): tests/with-display.sh build/ci/bench/fis_refinement

#include "core/project/Project.h"
#include "ui/MainWindow.h"
#include "ui/document/Document.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportRenderer.h"
#include "ui/viewport/ViewportWidget.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <algorithm>
#include <cstdio>

using namespace facet;

int main(int argc, char** argv)
{
    QStandardPaths::setTestModeEnabled(true);
    qunsetenv("FACET_NEW_PROJECT_METHOD"); // the default: fis
    installViewportSurfaceFormat();
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("FacetBench"));
    QTemporaryDir recovery;
    MainWindow window(nullptr, recovery.path());
    window.show();
    QElapsedTimer clock;
    clock.start();
    ViewportWidget* viewport = window.viewport();
    // The central view at 1193 x 902, as the issue measured.
    window.resize(window.width() + 1193 - viewport->width(), window.height() + 902 - viewport->height());
    double firstFrame = -1.0, firstChange = -1.0, done = -1.0, longest = 0.0;
    // While the refinement draws (its first draw on): the longest gap, how many exceeded 100 ms,
    // and the most bands a draw was split into (FrameRenderer::refine's sliceMs).
    double longestRefining = 0.0;
    int gapsOver100 = 0, turns = 0, mostBands = 1;
    double bandMsSum = 0.0, longestBand = 0.0;
    int bandsSeen = 0;
    double lastSlice = -1.0;
    int shownLevel = 0;
    qint64 last = clock.nsecsElapsed();
    while (clock.elapsed() < 300000 && done < 0.0) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        const qint64 now = clock.nsecsElapsed();
        const qint64 previous = last;
        longest = std::max(longest, double(now - last) / 1e6);
        last = now;
        const ViewportFrameStats& stats = viewport->lastFrameStats();
        const double ms = double(now) / 1e6;
        if (stats.refineMethod == IblMethod::Fis
            && (stats.refinement.draws > 0 || stats.refinement.levelShown > 0)) {
            const double gap = double(now - previous) / 1e6;
            longestRefining = std::max(longestRefining, gap);
            gapsOver100 += gap > 100.0 ? 1 : 0;
            ++turns;
            const FrameRenderer::Refinement& current = viewport->refinementNow();
            mostBands = std::max(mostBands, current.bands);
            if (current.lastSliceMs != lastSlice) { // a new band or draw
                lastSlice = current.lastSliceMs;
                bandMsSum += lastSlice;
                longestBand = std::max(longestBand, lastSlice);
                ++bandsSeen;
            }
        }
        if (firstFrame < 0.0 && viewport->frameCount() > 0)
            firstFrame = ms;
        if (stats.refinement.levelShown > shownLevel) {
            shownLevel = stats.refinement.levelShown;
            std::printf("  %.1f s: FIS %d samples shown (%dx%d)\n", ms / 1000.0, shownLevel, stats.width,
                stats.height);
            if (firstChange < 0.0)
                firstChange = ms;
        }
        if (stats.refineMethod == IblMethod::Fis && stats.refinement.done())
            done = ms;
    }
    std::printf("fis_refinement: first frame %.1f s, first FIS image %.1f s, done %.1f s; longest event-loop "
                "gap %.0f ms\n",
        firstFrame / 1000.0, firstChange / 1000.0, done / 1000.0, longest);
    std::printf(
        "  while refining: longest gap %.0f ms, %d of %d event-loop turns over 100 ms, draws split into up "
        "to %d bands\n",
        longestRefining, gapsOver100, turns, mostBands);
    std::printf("  bands (or whole draws): %d, %.0f ms on average, longest %.0f ms\n", bandsSeen,
        bandMsSum / std::max(bandsSeen, 1), longestBand);
    return 0;
}
