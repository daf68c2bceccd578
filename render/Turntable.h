#pragma once
// A turntable: the object or the environment turned about +Y, for the window's live turntable
// (View > Turntable, ui/viewport/CameraController) and for sequences of frames (`facet render --turntable
// N`, File > Save Turntable…). docs/app.md "Turntables" has the conventions.
//
// The object turns in place under a fixed camera, environment and lights (the model matrix
// R_y(angle)): its highlights move over it and the background stays. The environment turns under
// a fixed object, camera and lights (its rotation, docs/architecture.md, plus the angle): the
// background moves. Frame i of N is at 360 i / N degrees, so frame N would be frame 0 again and
// a looping video has no repeated frame.

#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include "core/image/Image.h"
#include "render/RenderScene.h"

namespace facet {

enum class TurntableSubject { Object, Environment };
const char* toString(TurntableSubject subject); // "object", "environment"
std::optional<TurntableSubject> turntableSubjectFromString(std::string_view name);

// The object's turn: R_y(degrees) as a model matrix (picking uses it too).
glm::dmat4 turntableModelMatrix(double degrees);
// The scene turned by `degrees` (right-handed about +Y: counter-clockwise seen from above).
void applyTurntable(RenderScene& scene, TurntableSubject subject, double degrees);

// Frame `index` of a full turn in `frames` frames: 360 * index / frames degrees.
double turntableDegrees(int index, int frames);

// Where frame `index` of `frames` goes, from the output the user named: a run of '#' in the file
// name is replaced by the index padded to its length ("turn_####.png" -> "turn_0007.png");
// otherwise "_NNNN" goes before the extension ("turn.png" -> "turn_0007.png"), with as many digits
// as the largest index needs (at least 4).
std::string turntableFramePath(const std::string& output, int index, int frames);

// What writeTurntable() did.
struct TurntableWrite {
    int framesWritten = 0;
    bool stopped = false; // `cancelled` said so after framesWritten frames: those kept, no video
    double renderSeconds = 0.0; // making and saving the frames
    double encodeSeconds = 0.0; // the video's encode
};
// The one way a turn is written (`facet render --turntable`, File > Save Turntable…): frame i of
// `frames` is made by `frame(i, turntableDegrees(i, frames), error)` and saved as
// turntableFramePath(output, i, frames) (with its alpha when `keepAlpha`) or, when `output` is a
// video (core/image/VideoEncoder.h), as PNG into a temporary folder and then encoded at `fps`.
// `cancelled` (optional) is asked after each frame (the last's answer is moot). nullopt with *error ("frame 3
// of 24: <why>", or the encoder's message) on failure; a stop is not one.
std::optional<TurntableWrite> writeTurntable(const std::string& output, int frames, int fps, bool keepAlpha,
    const std::function<std::optional<Image>(int index, double degrees, std::string* error)>& frame,
    std::string* error, const std::function<bool()>& cancelled = {});

} // namespace facet
