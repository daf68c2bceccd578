// Prints what a change description costs and saves (ui/DocumentChanges.h): changesBetween for one
// edit of a project of N materials, whole Document edits (a roughness factor, a normal map), and
// the window's SceneController alone handling a map change that names its slot, against a change
// of kinds alone (what every map edit cost before changes named their slots: every material's
// files looked at on disk).
// Each material has three files of its own. Checks nothing (SceneControllerUiTest and
// DocumentChangesTest do).
// Usage: document_changes [repeats]   (default 20; the median is printed)

#include "core/MapImageCache.h"
#include "core/Project.h"
#include "ui/Document.h"
#include "ui/DocumentChanges.h"
#include "ui/SceneController.h"

#include <QCoreApplication>
#include <QElapsedTimer>
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
    std::sort(times.begin(), times.end());
    return times[times.size() / 2];
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
    return 0;
}
