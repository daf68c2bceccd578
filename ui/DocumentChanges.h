#pragma once
// What an edit of the Document changed, by kind, so that observers redo only what depends on it
// (DESIGN.md, "Skip what the scene does not need"): a roughness slider reports MaterialFactors and
// the viewport sets uniforms; it does not reload textures or rerun the IBL precompute.

#include <QFlags>

namespace facet {

struct Project;

enum class DocumentChange : unsigned {
    None = 0,
    // The three material kinds below are reported for a change of ANY of the project's materials
    // (and all three when materials are added or removed).
    MaterialFactors = 1u << 0, // factors, IOR, name, alpha, sidedness, per-map channel/invert/flipGreen/UV
    MaterialMaps = 1u << 1, // a map's texture path or colour space (reload that map only)
    Shading = 1u << 2, // Material::shading (BRDF terms, coupling: another shader variant)
    EnvironmentSource = 1u << 3, // environment.source (load an image, rerun or fetch the IBL)
    EnvironmentRotation = 1u << 4, // environment.rotationDegrees (a uniform)
    EnvironmentIntensity = 1u << 5, // environment.intensity (a uniform)
    IblQuality = 1u << 6, // environment.quality (rerun or fetch the IBL)
    Lights = 1u << 7, // the punctual lights (added, removed, edited)
    View = 1u << 8, // view settings other than the mesh (exposure, tone mapper, background, MSAA)
    Camera = 1u << 9, // the camera (orbit, pan, dolly, frame, fly)
    Mesh = 1u << 10, // view.mesh (load another mesh)
    CurrentMaterial = 1u << 11, // which material the docks edit (Project::currentMaterial)
    Parts = 1u << 12, // which material each mesh part shows, and which parts are drawn
    Compare = 1u << 13, // the compare layout (Project::compare: mode, cells, A/B, wedge)
    // A different project altogether (New, Open, recovery): observers reload everything.
    WholeProject = (1u << 14) - 1u,
};
Q_DECLARE_FLAGS(DocumentChanges, DocumentChange)
Q_DECLARE_OPERATORS_FOR_FLAGS(DocumentChanges)

// The kinds of change that turn `before` into `after` (None when they are equal).
DocumentChanges changesBetween(const Project& before, const Project& after);

} // namespace facet
