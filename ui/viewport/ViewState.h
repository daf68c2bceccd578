#pragma once
// What a view adds to the project's scene, its own and nobody else's: the live turntable's angles
// (View > Turntable, driven by ui/viewport/CameraController) and View > Wireframe. Not part of the
// project and not undoable; ViewportWidget holds it and hands it to its ViewportRenderer, which
// adds it to the scene options of every frame, refinement and still it makes. Picking casts its
// rays under the same model matrix.

#include <glm/mat4x4.hpp>

#include "render/SceneFromProject.h"
#include "render/Turntable.h"

namespace facet {

struct ViewState {
    // The object turns about +Y by objectTurntableDegrees, the environment by
    // environmentTurntableDegrees on top of the project's rotation (render/Turntable.h).
    double objectTurntableDegrees = 0.0;
    double environmentTurntableDegrees = 0.0;
    bool wireframe = false; // the mesh's edges over the view and its stills (RenderScene::wireframe)

    // The matrix the mesh is drawn with: the object turntable's rotation, identity without one.
    glm::dmat4 modelMatrix() const { return turntableModelMatrix(objectTurntableDegrees); }
    // `options` (a project's, SceneController::sceneOptions) with this view's additions.
    SceneOptions appliedTo(SceneOptions options) const
    {
        options.objectTurnDegrees = objectTurntableDegrees;
        options.environmentTurnDegrees = environmentTurntableDegrees;
        options.wireframe = wireframe;
        return options;
    }
    bool operator==(const ViewState&) const = default;
};

} // namespace facet
