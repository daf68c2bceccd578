#pragma once
// `facet render`: a headless render of a project (or of the built-in default) to an image.
//
//   facet render [PROJECT.json] [--env PATH|NAME|uniform:VALUE] [--material PRESET |
//       --base-color r,g,b --metallic m --roughness r] [--brdf gltf|learnopengl]
//       [--multiscatter on|off] [--mesh NAME|PATH] [--view NAME] [--size WxH] [--reference-view]
//       [--spp N] [--quality PRESET] [--stats] [the scene flags of app/SceneFlags.h: --camera-position,
//       --camera-target, --fov, --exposure, --tone-mapper, --env-rotation, --env-intensity,
//       --background, --set PATH=VALUE, --save-project FILE]
//       [--turntable N [--turntable-subject object|environment] [--fps F]] -o OUT.(exr|png|mp4|webm)
//
// EXR output is linear scene radiance (no exposure, no tone mapping); PNG is display-referred
// through the project's view transform. With --spp N the image comes from core's ground-truth
// integrator (always the reference view of docs/architecture.md) instead of the GPU renderer, so the two
// can be compared pixel for pixel. Flag names are an interface: scripts outside Facet use them.

#include <optional>
#include <string>

#include <QString>
#include <QStringList>

#include "core/project/Project.h"
#include "render/Turntable.h"

namespace facet {

struct RenderRequest {
    Project project;          // the default project or the file, with the flags applied
    std::string outputPath;   // .exr or .png
    int width = 512;
    int height = 512;
    bool referenceView = false;
    int samplesPerPixel = 0;  // > 0: render with the ground-truth integrator
    bool printStats = false;
    std::string saveProjectPath; // --save-project: written before rendering
    // --turntable N: N frames of a full turn (render/Turntable.h) into numbered files
    // (turntableFramePath) or, for a .mp4 / .webm output, a video at `fps` (core/image/VideoEncoder.h).
    int turntableFrames = 0;
    TurntableSubject turntableSubject = TurntableSubject::Object;
    int fps = 30;
};

class RenderCommand {
public:
    // Exit codes: 0 done, 1 the request was valid but failed (unreadable input, write error),
    // 2 the command line is wrong.
    static constexpr int kExitFailure = 1;
    static constexpr int kExitUsage = 2;

    // `arguments` are what follows "render" on the command line. On failure returns nullopt,
    // `exitCode` says 1 or 2 and `error` the message (without the "facet render: " prefix).
    static std::optional<RenderRequest> parse(const QStringList& arguments, QString* error, int* exitCode);
    static QString helpText();
    // Renders and writes the image; messages go to stderr, --stats to stdout.
    static int run(const RenderRequest& request);
};

} // namespace facet
