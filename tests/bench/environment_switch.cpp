// Prints how long the window's event loop stalls when the environment changes (issue 12, "No
// stalls in the window"): the real MainWindow, the environment set through the Document as the
// Environment dock does, and a 1 ms timer whose longest gap is the longest stall, from the edit
// until the status bar says the lighting is ready, plus 300 ms. Each case: the file's first use
// (decode on the DocumentAssets worker, precompute on the lighting worker with an empty IBL disk
// cache), back to an environment the view holds in memory, and the same file in a fresh window
// with the disk cache warm. Checks nothing (the UI tests do): it measures.
// Usage (needs a display): tests/with-display.sh build/ci/bench/environment_switch [--large]
//   --large: also a 4096x2048 EXR (written once into the temporary folder).
//   --screenshots DIR: the window grabbed into DIR as each case's progress is first shown
//     (NN-progress.png) and once its lighting is ready (NN-ready.png), to look at.

#include "core/image/Image.h"
#include "core/project/AssetLibrary.h"
#include "core/project/Project.h"
#include "ui/MainWindow.h"
#include "ui/document/Document.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportWidget.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace facet;

namespace {

struct Stalls {
    double longestMs = 0.0;
    int over100 = 0;
    double readyMs = -1.0;
};

// Runs the event loop until the status bar says "Lighting of ... ready" (or `limitMs`), then
// 300 ms more, and returns the 1 ms timer's longest gap over that time, counted from `edit`.
QString g_screenshots; // --screenshots DIR, else empty
int g_case = 0;

QString screenshotPath(const char* what)
{
    return QStringLiteral("%1/%2-%3.png")
        .arg(g_screenshots)
        .arg(g_case, 2, 10, QLatin1Char('0'))
        .arg(QLatin1String(what));
}

template <typename Edit> Stalls measure(MainWindow& window, Edit edit, int limitMs = 60000)
{
    ++g_case;
    bool progressShot = false;
    Stalls stalls;
    QElapsedTimer clock;
    QElapsedTimer tick;
    QTimer monitor;
    monitor.setTimerType(Qt::PreciseTimer);
    monitor.setInterval(1);
    QObject::connect(&monitor, &QTimer::timeout, [&] {
        const double gap = double(tick.nsecsElapsed()) / 1e6;
        tick.start();
        stalls.longestMs = std::max(stalls.longestMs, gap);
        stalls.over100 += gap > 100.0 ? 1 : 0;
    });
    const QMetaObject::Connection ready = QObject::connect(
        window.statusBar(), &QStatusBar::messageChanged, [&](const QString& text) {
            if (stalls.readyMs < 0.0 && text.startsWith(QStringLiteral("Lighting of"))
                && text.contains(QStringLiteral("ready")))
                stalls.readyMs = double(clock.nsecsElapsed()) / 1e6;
            // (grabbing draws the window: the stall figures of a run with --screenshots count it)
            if (!g_screenshots.isEmpty() && !progressShot && text.endsWith(QLatin1Char('%'))) {
                progressShot = true;
                QTimer::singleShot(0, &window, [&window] { window.grab().save(screenshotPath("progress")); });
            }
        });
    clock.start();
    tick.start();
    monitor.start();
    edit(); // (its own time on the GUI thread counts: the first gap includes it)
    while (stalls.readyMs < 0.0 && clock.elapsed() < limitMs)
        QApplication::processEvents(QEventLoop::AllEvents, 5);
    const qint64 settle = clock.elapsed() + 300;
    while (clock.elapsed() < settle)
        QApplication::processEvents(QEventLoop::AllEvents, 5);
    monitor.stop();
    QObject::disconnect(ready);
    if (!g_screenshots.isEmpty())
        window.grab().save(screenshotPath("ready"));
    return stalls;
}

void setEnvironment(MainWindow& window, const std::string& spec)
{
    EnvironmentSettings environment = window.document()->project().environment;
    environment.source = spec;
    window.document()->setEnvironment(environment, QStringLiteral("Environment"));
}

void print(const char* what, const std::string& spec, const Stalls& stalls)
{
    std::printf("| %s | %s | %.0f ms | %d | %.0f ms |\n", what, spec.c_str(), stalls.longestMs,
        stalls.over100, stalls.readyMs);
}

} // namespace

int main(int argc, char** argv)
{
    QStandardPaths::setTestModeEnabled(true);
    installViewportSurfaceFormat();
    QApplication app(argc, argv);
    const bool large = app.arguments().contains(QStringLiteral("--large"));
    if (const qsizetype at = app.arguments().indexOf(QStringLiteral("--screenshots"));
        at >= 0 && at + 1 < app.arguments().size())
        g_screenshots = app.arguments().at(at + 1);
    QTemporaryDir temporary;
    qputenv("FACET_CACHE_DIR", temporary.filePath(QStringLiteral("cache")).toUtf8());

    const std::string hdri = AssetLibrary::installed().folder + "/hdri/";
    std::vector<std::string> specs = {hdri + "forest.exr", hdri + "night.exr"};
    if (large) {
        // A 4096x2048 map: the largest an environment is kept at (core/ibl/Environment.h kMaxWidth).
        Image image(4096, 2048, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                image.at(x, y) = glm::vec4(0.5f + 0.5f * std::sin(x * 0.01f),
                    0.5f + 0.5f * std::cos(y * 0.013f), (x ^ y) % 7 == 0 ? 20.0f : 0.2f, 1.0f);
        const std::string path = temporary.filePath(QStringLiteral("large.exr")).toStdString();
        std::string error;
        if (!image.save(path, &error, false)) {
            std::fprintf(stderr, "environment_switch: %s\n", error.c_str());
            return 1;
        }
        specs.push_back(path);
    }

    std::printf("| case | environment | longest stall | stalls > 100 ms | lighting ready after "
                "|\n|---|---|---|---|---|\n");
    for (int pass = 0; pass < 2; ++pass) {
        // Pass 0: an empty IBL disk cache; pass 1: a fresh window, the disk cache now warm.
        MainWindow window(nullptr, temporary.filePath(QStringLiteral("recovery")));
        window.resize(1280, 800);
        window.show();
        const Stalls start = measure(
            window, [] {}, 5000); // (the first frame's note may differ)
        print(pass == 0 ? "window opens (studio, built in)" : "window opens again", "studio", start);
        for (const std::string& spec : specs) {
            print(pass == 0 ? "first use, empty disk cache" : "disk cache warm", spec,
                measure(window, [&] { setEnvironment(window, spec); }));
            if (pass == 0)
                print("back to studio (in memory)", "studio",
                    measure(window, [&] { setEnvironment(window, "studio"); }));
        }
    }
    return 0;
}
