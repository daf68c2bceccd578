// Prints what a change description costs and saves (ui/document/DocumentChanges.h): changesBetween for one
// edit of a project of N materials, whole Document edits (a roughness factor, a normal map), and
// the window's SceneController alone handling a map change that names its slot, against a change
// of kinds alone (what every map edit cost before changes named their slots: every material's
// files looked at on disk).
// Each material has three files of its own. Then choosing an environment file and a mesh file:
// how long the edit keeps the GUI thread (the file loads on a worker, ui/document/DocumentAssets), how long
// until it arrives, and the load alone (what the GUI thread waited for before the window's asset
// cache). Checks nothing (SceneControllerUiTest, DocumentAssetsUiTest and DocumentChangesTest do).
// Usage: document_changes [repeats]   (default 20; the median is printed)

#include "BenchStats.h"
#include "core/image/MapImageCache.h"
#include "core/project/AssetLibrary.h"
#include "core/project/Project.h"
#include "core/project/ProjectAssets.h"
#include "ui/document/Document.h"
#include "ui/document/DocumentChanges.h"
#include "ui/viewport/SceneController.h"

#include "TestSupport.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFileInfo>
#include <QTemporaryDir>

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <vector>

using namespace facet;

namespace {

bool writeTinyPng(const std::string& path)
{
    const unsigned char pixels[4 * 4 * 3] = {};
    auto output = OIIO::ImageOutput::create(path);
    OIIO::ImageSpec spec(4, 4, 3, OIIO::TypeDesc::UINT8);
    return output && output->open(path, spec) && output->write_image(OIIO::TypeDesc::UINT8, pixels)
        && output->close();
}

double medianMicroseconds(int repeats, const std::function<void(int)>& run)
{
    std::vector<double> times;
    for (int i = 0; i < repeats; ++i) {
        QElapsedTimer clock;
        clock.start();
        run(i);
        times.push_back(double(clock.nsecsElapsed()) / 1e3);
    }
    return bench::median(std::move(times));
}

} // namespace

int main(int argc, char** argv)
{
    QCoreApplication app(argc, argv);
    const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 20;
    QTemporaryDir dir;
    if (!dir.isValid())
        return 1;

    std::printf(
        "| materials | files | changesBetween, one roughness edit | Document edit, roughness | "
        "Document edit, one normal map | SceneController, a change naming one slot | SceneController, "
        "kinds alone (every file) |\n|---|---|---|---|---|---|---|\n");
    for (int materials : {1, 16, 256, 1024}) {
        Project project = Project::defaultProject();
        project.materials.assign(std::size_t(materials), project.materials[0]);
        for (int m = 0; m < materials; ++m)
            for (MapSlot slot : {MapSlot::BaseColor, MapSlot::Normal, MapSlot::Roughness}) {
                const std::string path
                    = dir.filePath(QStringLiteral("m%1_%2.png").arg(m).arg(QLatin1String(toString(slot))))
                          .toStdString();
                if (!writeTinyPng(path))
                    return 1;
                project.materials[std::size_t(m)].map(slot).path = path;
            }
        const std::string normalA = dir.filePath(QStringLiteral("normal_a.png")).toStdString();
        const std::string normalB = dir.filePath(QStringLiteral("normal_b.png")).toStdString();
        if (!writeTinyPng(normalA) || !writeTinyPng(normalB))
            return 1;

        Project edited = project;
        edited.materials.back().setFactor(MapSlot::Roughness, 0.9);
        volatile std::size_t sink = 0;
        const double between = medianMicroseconds(
            repeats * 10, [&](int) { sink = sink + changesBetween(project, edited).materialEdits().size(); });

        Document document;
        document.setProject(project, QStringLiteral("Set"));
        SceneController scene(&document);
        const auto settle = [&] {
            while (scene.pendingMapLoads() > 0)
                QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 50);
        };
        settle();
        const double roughness = medianMicroseconds(repeats, [&](int i) {
            Project next = document.project();
            next.materials.back().setFactor(MapSlot::Roughness, i % 2 ? 0.25 : 0.75);
            document.setProject(next, QStringLiteral("Roughness"));
        });
        // The last material's normal map flips between two files: the edit's own work is timed,
        // not the decode, which runs on a worker thread.
        const double named = medianMicroseconds(repeats, [&](int i) {
            Project next = document.project();
            next.materials.back().map(MapSlot::Normal).path = i % 2 ? normalA : normalB;
            document.setProject(next, QStringLiteral("Normal"));
        });
        settle();
        // The SceneController alone, nothing changed on disk: a change naming the slot (what a map
        // edit reports now) against kinds alone (what every map edit reported before).
        const DocumentChanges oneSlot = DocumentChanges::ofMaterial(
            std::size_t(materials - 1), MaterialChange::ofMap(MapSlot::Normal, MapProperty::Path));
        const double sceneNamed
            = medianMicroseconds(repeats, [&](int) { document.notifyFilesChangedOnDisk(oneSlot); });
        const double kindsAlone = medianMicroseconds(
            repeats, [&](int) { document.notifyFilesChangedOnDisk(DocumentChange::MaterialMaps); });
        settle();
        std::printf("| %d | %d | %.1f us | %.1f us | %.1f us | %.1f us | %.1f us |\n", materials,
            materials * 3, between, roughness, named, sceneNamed, kindsAlone);
    }

    // Choosing a file: a fresh SceneController (its own asset cache, so nothing is cached) each
    // time, the edit timed, then the wait for the arrival; and the load alone, synchronously.
    std::printf("\n| file | edit returns (GUI thread) | arrives | load alone |\n|---|---|---|---|\n");
    struct Choice {
        std::string spec;
        bool environment;
    };
    // A 4K equirect (4096 x 2048 floats) besides the installed 1K-2K ones: the size a studio HDRI
    // comes in.
    const std::string large = dir.filePath(QStringLiteral("large-4k.exr")).toStdString();
    if (!test::writeConstantExr(QString::fromStdString(large), 0.5f, 4096))
        return 1;
    for (const Choice& choice : {Choice {large, true}, Choice {"library:installed/hdri/forest.exr", true},
             Choice {"library:installed/hdri/night.exr", true},
             Choice {"library:installed/models/suzi.glb", false},
             Choice {"library:installed/models/bunny.glb", false}}) {
        std::string error;
        const std::string spec = choice.spec;
        const std::optional<std::string> file = AssetLibrary::fileForSpec(spec, "bench", &error);
        const bool available = file && QFileInfo::exists(QString::fromStdString(*file));
        if (!available) {
            std::printf("| %s | (not installed: %s) | | |\n", choice.spec.c_str(), error.c_str());
            continue;
        }
        const int loads = std::max(3, repeats / 4);
        std::vector<double> edits;
        std::vector<double> arrivals;
        for (int i = 0; i < loads; ++i) {
            Document document;
            SceneController scene(&document);
            QElapsedTimer clock;
            clock.start();
            Project next = document.project();
            (choice.environment ? next.environment.source : next.view.mesh) = spec;
            document.setProject(next, QStringLiteral("Choose"));
            edits.push_back(double(clock.nsecsElapsed()) / 1e6);
            while (scene.pendingAssetLoads() > 0)
                QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 5);
            arrivals.push_back(double(clock.nsecsElapsed()) / 1e6);
        }
        const double alone = medianMicroseconds(loads, [&](int) {
            std::string problem;
            if (choice.environment)
                Environment::fromSpec(spec, &problem);
            else
                loadViewMesh(spec, &problem);
        }) / 1e3;
        std::sort(edits.begin(), edits.end());
        std::sort(arrivals.begin(), arrivals.end());
        const std::string name = choice.spec == large ? "4096x2048 EXR (generated)" : choice.spec;
        std::printf("| %s | %.1f ms | %.1f ms | %.1f ms |\n", name.c_str(), edits[edits.size() / 2],
            arrivals[arrivals.size() / 2], alone);
    }
    return 0;
}
