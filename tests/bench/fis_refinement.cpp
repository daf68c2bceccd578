// Prints when the window's still view first changes while it refines by FIS, and when it is done
// (issue 30: with Lighting = FIS the image did not change for about 60 s at 1193x902 on llvmpipe,
// then popped in). The real MainWindow at 1193x902 on the default project (fis, 1024 samples:
// levels of 64, 256 and 1024, FrameRenderer::fisRefinementLevels), timed from its first frame;
// also the longest gap between two event-loop turns meanwhile (how long input waits).
// Checks nothing: it measures. Usage (needs a display): tests/with-display.sh build/ci/bench/fis_refinement

#include "core/Project.h"
#include "ui/Document.h"
#include "ui/MainWindow.h"
#include "ui/SurfaceFormat.h"
#include "ui/ViewportRenderer.h"
#include "ui/ViewportWidget.h"

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
    int shownLevel = 0;
    qint64 last = clock.nsecsElapsed();
    while (clock.elapsed() < 300000 && done < 0.0) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 5);
        const qint64 now = clock.nsecsElapsed();
        longest = std::max(longest, double(now - last) / 1e6);
        last = now;
        const ViewportFrameStats& stats = viewport->lastFrameStats();
        const double ms = double(now) / 1e6;
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
    return 0;
}
