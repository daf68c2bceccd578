// Prints the window's resident memory while it switches through environments and texture sets
// (issue 30, "Memory grows without bound"): the real MainWindow, 20 environments (the installed
// library's CC0 maps, and 2048x1024 EXRs written into a temporary folder to make up the count)
// and 10 texture sets (base colour, normal and roughness PNGs, --size pixels a side), each set
// through the Document as the docks do and shown until its frame is complete (lighting ready,
// every map uploaded). VmRSS after each cycle, the time each cycle took, and what the first
// texture set and the first environment added. Checks nothing (the UI tests do): it measures.
// Usage (needs a display):
//   tests/with-display.sh build/ci/bench/cache_budget [--cycles N] [--size PX] [--budget MB]
//       [--hdri DIR] [--return-freed on|off]
//   --return-freed off: the window keeps what it freed (ui/widgets/FreedMemoryTimer stopped), for comparison.
//   --cycles 0: ends at once (std::_Exit) after the first set and environment, so that a heap
//     profiler (heaptrack) reports what they hold as not freed.
//   --budget: the window's cache budget in MiB (Edit > Preferences; set here as FACET_CACHE_BUDGET_MB).

#include "core/image/Image.h"
#include "core/project/Project.h"
#include "core/support/FreedMemory.h"
#include "ui/MainWindow.h"
#include "ui/document/Document.h"
#include "ui/document/ProjectFileController.h"
#include "ui/viewport/SceneController.h"
#include "ui/viewport/SurfaceFormat.h"
#include "ui/viewport/ViewportWidget.h"
#include "ui/widgets/CacheBudget.h"
#include "ui/widgets/FreedMemoryTimer.h"

#include <QApplication>
#include <QDir>
#include <QElapsedTimer>
#include <QFile>
#include <QImage>
#include <QMessageBox>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

using namespace facet;

namespace {

double residentMiB()
{
    QFile status(QStringLiteral("/proc/self/status"));
    if (!status.open(QIODevice::ReadOnly))
        return -1.0;
    for (const QByteArray& line : status.readAll().split('\n'))
        if (line.startsWith("VmRSS:"))
            return line.mid(6).trimmed().split(' ').value(0).toDouble() / 1024.0;
    return -1.0;
}

// A map with some structure (a constant image would compress to nothing and decode as fast).
bool writeMap(const QString& path, int size, int seed, bool grey)
{
    QImage image(size, size, grey ? QImage::Format_Grayscale8 : QImage::Format_RGB888);
    for (int y = 0; y < size; ++y) {
        uchar* row = image.scanLine(y);
        for (int x = 0; x < size; ++x) {
            const int v = ((x / 64 + y / 64 + seed) % 2) * 96 + (x * 7 + y * 3 + seed * 31) % 64;
            if (grey)
                row[x] = uchar(v);
            else {
                row[3 * x] = uchar(v);
                row[3 * x + 1] = uchar((v + seed * 40) % 256);
                row[3 * x + 2] = uchar(255 - v);
            }
        }
    }
    return image.save(path, "PNG", 90);
}

bool writeEnvironment(const QString& path, int seed)
{
    Image image(2048, 1024);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const float sky = 0.2f + 0.8f * float(image.height() - y) / float(image.height());
            const bool sun = std::abs(x - 200 * seed) < 12 && std::abs(y - 300) < 12;
            image.at(x, y) = glm::vec4(sky * 0.6f, sky * 0.8f, sky, 1.0f) * (sun ? 500.0f : 1.0f);
        }
    std::string error;
    if (!image.save(path.toStdString(), &error)) {
        std::fprintf(stderr, "cache_budget: %s\n", error.c_str());
        return false;
    }
    return true;
}

// Runs the event loop until a frame shows the scene complete: the lighting ready, every map
// decoded and uploaded, at full resolution. Returns the milliseconds it took (-1: not in 120 s).
double showComplete(MainWindow& window)
{
    QElapsedTimer clock;
    clock.start();
    ViewportWidget* viewport = window.viewport();
    SceneController* scene = window.sceneController();
    const std::uint64_t first = viewport->frameCount();
    while (clock.elapsed() < 120000) {
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
        const ViewportFrameStats& stats = viewport->lastFrameStats();
        if (viewport->frameCount() > first && !stats.lightingPending && !stats.loadingMaps
            && stats.mapsHeldBack == 0 && !stats.reduced && scene->pendingMapLoads() == 0
            && scene->pendingAssetLoads() == 0)
            return double(clock.nsecsElapsed()) / 1e6;
    }
    return -1.0;
}

// The event loop for `ms` more (the refinement that follows a complete frame, the freed-memory
// timer's checks are not what a switch costs, but what it leaves is).
void settle(int ms)
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < ms)
        QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
}

} // namespace

int main(int argc, char** argv)
{
    const QString defaultHdri = QDir::homePath() + QStringLiteral("/.local/share/facet/assets/hdri");
    std::setvbuf(stdout, nullptr, _IOLBF, 0); // each line as it is measured, also into a file
    QStandardPaths::setTestModeEnabled(true);
    installViewportSurfaceFormat();
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("FacetBench"));
    int cycles = 3;
    int size = 2048;
    int budget = 0;
    QString hdri = defaultHdri;
    bool returnFreed = true;
    const QStringList args = app.arguments();
    for (int i = 1; i + 1 < args.size(); ++i) {
        if (args[i] == QStringLiteral("--cycles"))
            cycles = args[i + 1].toInt();
        if (args[i] == QStringLiteral("--size"))
            size = args[i + 1].toInt();
        if (args[i] == QStringLiteral("--budget"))
            budget = args[i + 1].toInt();
        if (args[i] == QStringLiteral("--return-freed"))
            returnFreed = args[i + 1] != QStringLiteral("off");
        if (args[i] == QStringLiteral("--hdri"))
            hdri = args[i + 1];
    }
    // The budget through the environment, so that the benchmark leaves no setting behind.
    QSettings().remove(QStringLiteral("cache/budgetMB"));
    if (budget > 0)
        qputenv("FACET_CACHE_BUDGET_MB", QByteArray::number(budget));
    else
        qunsetenv("FACET_CACHE_BUDGET_MB");
    CacheBudget::reload();

    QTemporaryDir dir;
    std::vector<std::string> environments;
    for (const QFileInfo& file :
        QDir(hdri).entryInfoList({QStringLiteral("*.exr"), QStringLiteral("*.hdr")}, QDir::Files, QDir::Name))
        if (environments.size() < 20)
            environments.push_back(file.absoluteFilePath().toStdString());
    for (int i = 0; environments.size() < 20; ++i) {
        const QString path = dir.filePath(QStringLiteral("made%1.exr").arg(i));
        if (!writeEnvironment(path, i))
            return 1;
        environments.push_back(path.toStdString());
    }
    std::vector<std::array<std::string, 3>> sets;
    for (int s = 0; s < 10; ++s) {
        const QString base = dir.filePath(QStringLiteral("set%1_").arg(s));
        if (!writeMap(base + QStringLiteral("basecolor.png"), size, s, false)
            || !writeMap(base + QStringLiteral("normal.png"), size, s + 1, false)
            || !writeMap(base + QStringLiteral("roughness.png"), size, s + 2, true)) {
            std::fprintf(stderr, "cache_budget: could not write the maps into %s\n", qPrintable(dir.path()));
            return 1;
        }
        sets.push_back({(base + QStringLiteral("basecolor.png")).toStdString(),
            (base + QStringLiteral("normal.png")).toStdString(),
            (base + QStringLiteral("roughness.png")).toStdString()});
    }

    QTemporaryDir recovery;
    MainWindow window(nullptr, recovery.path());
    window.projectFiles()->setErrorDialogsEnabled(false);
    window.projectFiles()->setUnsavedChangesAnswer(QMessageBox::Discard);
    window.resize(1280, 800);
    if (!returnFreed)
        window.findChild<FreedMemoryTimer*>()->setEnabled(false);
    window.show();
    Document* document = window.document();
    const double startMs = showComplete(window);
    settle(6000);
    const double start = residentMiB();
    std::printf("cache_budget: %zu environments, %zu texture sets of three %dx%d maps, budget %d MiB%s%s\n",
        environments.size(), sets.size(), size, size, CacheBudget::megabytes(),
        budget > 0 ? "" : " (the default)", returnFreed ? "" : ", freed memory not handed back");
    std::printf("  at start: VmRSS %.0f MiB (first frame after %.0f ms)\n", start, startMs);

    auto showSet = [&](const std::array<std::string, 3>& set) {
        Material material = document->project().material();
        material.map(MapSlot::BaseColor).path = set[0];
        material.map(MapSlot::BaseColor).colorSpace = ColorEncoding::SRGB;
        material.map(MapSlot::Normal).path = set[1];
        material.map(MapSlot::Roughness).path = set[2];
        material.map(MapSlot::Roughness).channel = MapChannel::R;
        document->setMaterial(material, QStringLiteral("Texture Set"));
        return showComplete(window);
    };
    auto showEnvironment = [&](const std::string& source) {
        EnvironmentSettings environment = document->project().environment;
        environment.source = source;
        document->setEnvironment(environment, QStringLiteral("Environment"));
        return showComplete(window);
    };

    // What one texture set and one environment add, the first time.
    const double setMs = showSet(sets[0]);
    settle(6000);
    const double withSet = residentMiB();
    const double environmentMs = showEnvironment(environments[0]);
    settle(6000);
    const double withEnvironment = residentMiB();
    std::printf("  the first texture set: +%.0f MiB (%.0f ms); the first environment: +%.0f MiB (%.0f ms)\n",
        withSet - start, setMs, withEnvironment - withSet, environmentMs);
    // The next ones, without what the first of each paid once (the image decoders' code and
    // tables, the view's full-size targets): what one more asset costs.
    const double secondSetMs = showSet(sets[1]);
    settle(6000);
    const double withSecondSet = residentMiB();
    const double secondEnvironmentMs = showEnvironment(environments[1]);
    settle(6000);
    const double withSecondEnvironment = residentMiB();
    std::printf(
        "  the second texture set: %+.0f MiB (%.0f ms); the second environment: %+.0f MiB (%.0f ms)\n",
        withSecondSet - withEnvironment, secondSetMs, withSecondEnvironment - withSecondSet,
        secondEnvironmentMs);
    if (cycles == 0) // what is held now is what a heap profiler reports as not freed
        std::_Exit(0);

    double peak = withEnvironment;
    for (int cycle = 1; cycle <= cycles; ++cycle) {
        QElapsedTimer clock;
        clock.start();
        double slowest = 0.0;
        int incomplete = 0;
        for (std::size_t i = 0; i < environments.size(); ++i) {
            const double ms = showEnvironment(environments[i]);
            incomplete += ms < 0.0 ? 1 : 0;
            slowest = std::max(slowest, ms);
            peak = std::max(peak, residentMiB());
            if (i % 2 == 0) {
                const double setShown = showSet(sets[(i / 2) % sets.size()]);
                incomplete += setShown < 0.0 ? 1 : 0;
                slowest = std::max(slowest, setShown);
                peak = std::max(peak, residentMiB());
            }
        }
        const double seconds = double(clock.elapsed()) / 1000.0;
        settle(6000);
        const ViewportFrameStats& stats = window.viewport()->lastFrameStats();
        std::printf("  cycle %d: VmRSS %.0f MiB (peak so far %.0f MiB, %.0f MiB free in the allocator); IBL "
                    "cache %d entries, %.0f MiB; %.1f s, slowest switch %.0f ms%s\n",
            cycle, residentMiB(), peak, double(freedMemoryHeld()) / double(1 << 20), stats.iblCacheEntries,
            double(stats.iblCacheBytes) / double(1 << 20), seconds, slowest,
            incomplete > 0 ? qPrintable(QStringLiteral(", %1 never complete").arg(incomplete)) : "");
    }
    return 0;
}
