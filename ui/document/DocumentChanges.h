#pragma once
// What an edit of the Document changed, so that observers redo only what depends on it
// (docs/architecture.md, "Skipping work"; docs/app.md, "Change events"). After Tiled's
// change events (src/tiled/changeevents.h): an event names the objects that changed and a mask of
// their properties, and a mask left at "all" means "assume everything changed".
//
// A DocumentChanges value has two levels:
// - kinds (DocumentChange flags): what sort of thing changed, for observers that only need that
//   (a dock that shows lights asks `changes & DocumentChange::Lights`);
// - detail: WHICH materials (by index) and which map slots of them, with the properties of each
//   (MaterialField, MapProperty); which lights, with their properties (LightProperty), and
//   whether lights or materials were inserted, removed or reordered (ListChange); which view
//   settings (ViewProperty). A view that shows material 2 asks affectsMaterial(changes, 2), a
//   map cache asks changes.map(2, MapSlot::Roughness) & MapProperty::Path.
//
// changesBetween(before, after) is the one place that works a description out (undo, redo and
// every edit go through it). A description made from kinds alone (DocumentChange::WholeProject
// for New/Open, DocumentChange::MaterialMaps for "files changed on disk") names nothing: every
// question about those kinds answers "changed" (all properties, every index).
//
// Indices are those of the project AFTER the change; removed ones (ListChange::removed) are those
// of the project before it.

#include "core/material/Material.h"

#include <QFlags>

#include <array>
#include <cstddef>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace facet {

struct Project;

enum class DocumentChange : unsigned {
    None = 0,
    // The three material kinds say what sort of material change happened; the detail says which
    // materials (all three when materials are added, removed or reordered).
    MaterialFactors = 1u << 0, // factors, IOR, name, alpha, sidedness, per-map channel/invert/flipGreen/UV
    MaterialMaps = 1u << 1, // a map's texture path or colour space (reload that map only)
    Shading = 1u << 2, // Material::shading (BRDF terms, coupling: another shader variant)
    EnvironmentSource = 1u << 3, // environment.source (load an image, rerun or fetch the IBL)
    EnvironmentRotation = 1u << 4, // environment.rotationDegrees (a uniform)
    EnvironmentIntensity = 1u << 5, // environment.intensity (a uniform)
    IblQuality = 1u << 6, // environment.quality (rerun or fetch the IBL), .method, .samples (refine anew)
    Lights = 1u << 7, // the punctual lights (added, removed, reordered, edited)
    View = 1u << 8, // view settings other than the mesh (exposure, tone mapper, background, MSAA)
    Camera = 1u << 9, // the camera (orbit, pan, dolly, frame, fly)
    Mesh = 1u << 10, // view.mesh (load another mesh)
    CurrentMaterial = 1u << 11, // which material the docks edit (Project::currentMaterial)
    Parts = 1u << 12, // which material each mesh part shows, and which parts are drawn
    Compare = 1u << 13, // the compare layout (Project::compare: mode, cells, A/B, wedge)
    // A different project altogether (New, Open, recovery): observers reload everything.
    WholeProject = (1u << 14) - 1u,
};
Q_DECLARE_FLAGS(DocumentChangeKinds, DocumentChange)
Q_DECLARE_OPERATORS_FOR_FLAGS(DocumentChangeKinds)

// What changed in one map slot of a material (MaterialMap's fields).
enum class MapProperty : unsigned {
    Path = 1u << 0, // the texture file: kind MaterialMaps
    ColorSpace = 1u << 1, // how the file's numbers are decoded: kind MaterialMaps
    Factor = 1u << 2, // this and the rest: kind MaterialFactors
    Channel = 1u << 3,
    Invert = 1u << 4,
    FlipGreen = 1u << 5,
    Uv = 1u << 6,
    TexCoord = 1u << 7, // which UV set the map reads
    Sampler = 1u << 8, // wraps and filters
    All = (1u << 9) - 1u,
};
Q_DECLARE_FLAGS(MapProperties, MapProperty)
Q_DECLARE_OPERATORS_FOR_FLAGS(MapProperties)

// What changed in a material besides its maps (Material's fields).
enum class MaterialField : unsigned {
    Name = 1u << 0, // kind MaterialFactors; not drawn
    Ior = 1u << 1,
    EmissiveStrength = 1u << 2,
    AlphaMode = 1u << 3,
    AlphaCutoff = 1u << 4,
    DoubleSided = 1u << 5,
    Shading = 1u << 6, // Material::shading: kind Shading
    Unlit = 1u << 7,
    AnisotropyRotation = 1u << 8, // KHR_materials_anisotropy's rotation (its strength is a map's factor)
    IridescenceIor = 1u << 9, // KHR_materials_iridescence's film index
    IridescenceThicknessMinimum = 1u << 10, // its thickness texture's 0 (the maximum is a map's factor)
    // (The layered lobes' factors are their maps' factors: the map changes say them.)
    All = (1u << 11) - 1u,
};
Q_DECLARE_FLAGS(MaterialFields, MaterialField)
Q_DECLARE_OPERATORS_FOR_FLAGS(MaterialFields)

// What changed in one light (Light's fields; pairs that only mean something together are one).
enum class LightProperty : unsigned {
    Name = 1u << 0, // not drawn
    Type = 1u << 1,
    Enabled = 1u << 2,
    Color = 1u << 3,
    Temperature = 1u << 4, // useTemperature, kelvin
    Intensity = 1u << 5,
    Range = 1u << 6,
    Cone = 1u << 7, // innerConeAngle, outerConeAngle
    Position = 1u << 8,
    Direction = 1u << 9,
    All = (1u << 10) - 1u,
};
Q_DECLARE_FLAGS(LightProperties, LightProperty)
Q_DECLARE_OPERATORS_FOR_FLAGS(LightProperties)

// What changed in the view settings (ViewSettings' fields but the mesh, which is kind Mesh).
enum class ViewProperty : unsigned {
    Exposure = 1u << 0,
    ToneMapper = 1u << 1,
    DisplayEncoding = 1u << 2, // displayEncoding, gamma
    Ocio = 1u << 3, // ocioDisplay, ocioView
    DebugView = 1u << 4,
    Msaa = 1u << 5,
    Background = 1u << 6, // background, backgroundColor, backgroundBlurRoughness
    All = (1u << 7) - 1u,
};
Q_DECLARE_FLAGS(ViewProperties, ViewProperty)
Q_DECLARE_OPERATORS_FOR_FLAGS(ViewProperties)

// What changed in one material: its own properties and each map slot's.
struct MaterialChange {
    MaterialFields properties;
    std::array<MapProperties, kMapSlotCount> maps {};

    static MaterialChange all(); // every property of every slot (a new or shifted material)
    static MaterialChange ofMap(MapSlot slot, MapProperties changed);
    MapProperties map(MapSlot slot) const { return maps[std::size_t(slot)]; }
    bool isEmpty() const;
    DocumentChangeKinds kinds() const; // MaterialFactors, MaterialMaps, Shading as documented above
    MaterialChange& operator|=(const MaterialChange& other);
    bool operator==(const MaterialChange&) const = default;
};

// How a list (materials, lights) changed as a list, beyond its items' in-place edits.
struct ListChange {
    std::vector<std::size_t> inserted; // indices in the list after, ascending
    std::vector<std::size_t> removed; // indices in the list before, ascending
    // The same items in another order (the moved indices are in-place edits too); checked when at
    // most 64 items moved, beyond that the moves are reported as edits only.
    bool reordered = false;

    bool isEmpty() const { return inserted.empty() && removed.empty() && !reordered; }
    // The first index of the list after whose item may be another one than the index held
    // before (an insertion or removal shifts every later item); max() when none moved.
    std::size_t firstShifted() const;
    bool operator==(const ListChange&) const = default;
};

class DocumentChanges {
public:
    static constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();

    DocumentChanges() = default;
    // Kinds alone (flag-style, as observers and Document emit them): every question about those
    // kinds answers "changed".
    // Implicit, so that `Q_EMIT changed(DocumentChange::Camera)` and `changes == DocumentChange::X`
    // read as they did when a change was a flag set.
    DocumentChanges(DocumentChange kind)
        : DocumentChanges(DocumentChangeKinds(kind))
    {
    }
    DocumentChanges(DocumentChangeKinds kinds);

    // Detailed descriptions (changesBetween builds with these; tests write expectations with them).
    // A list change may come with in-place edits of the items it did not insert (an edit that
    // replaced the whole list: the common indices compared one by one, the rest inserted or
    // removed). Material list insertions and removals report all three material kinds.
    static DocumentChanges ofMaterial(std::size_t index, const MaterialChange& change);
    static DocumentChanges ofMaterialList(
        const ListChange& list, const std::map<std::size_t, MaterialChange>& edits = {});
    static DocumentChanges ofLight(std::size_t index, LightProperties changed);
    static DocumentChanges ofLightList(
        const ListChange& list, const std::map<std::size_t, LightProperties>& edits = {});
    static DocumentChanges ofView(ViewProperties changed);

    // --- Kinds (the flag API: `changes & DocumentChange::Lights`, testFlag, `|`)
    DocumentChangeKinds kinds() const { return m_kinds; }
    bool testFlag(DocumentChange kind) const { return m_kinds.testFlag(kind); }
    DocumentChangeKinds operator&(DocumentChange kind) const { return m_kinds & kind; }
    DocumentChangeKinds operator&(DocumentChangeKinds kinds) const { return m_kinds & kinds; }
    DocumentChangeKinds operator&(const DocumentChanges& other) const { return m_kinds & other.m_kinds; }
    bool isEmpty() const { return !m_kinds; }
    // Both changes, as one (a view that draws once for several edits collects them). Detail
    // that cannot be combined exactly (two list changes: their indices refer to different lists)
    // becomes "names nothing" for that list, never less than what changed.
    DocumentChanges& operator|=(const DocumentChanges& other);
    friend DocumentChanges operator|(DocumentChanges a, const DocumentChanges& b) { return a |= b; }
    bool operator==(const DocumentChanges&) const = default;

    // --- Detail
    // Whether the material kinds come with the materials they concern (false: every material
    // may have changed). Likewise lights and view.
    bool namesMaterials() const { return m_materialsNamed; }
    bool namesLights() const { return m_lightsNamed; }
    bool namesView() const { return m_viewNamed; }
    // In-place edits by index (empty unless named).
    const std::map<std::size_t, MaterialChange>& materialEdits() const { return m_materials; }
    const ListChange& materialList() const { return m_materialList; }
    const std::map<std::size_t, LightProperties>& lightEdits() const { return m_lights; }
    const ListChange& lightList() const { return m_lightList; }

    // What changed in material `index` (all: not named, or another material now sits there).
    MaterialChange material(std::size_t index) const;
    MapProperties map(std::size_t materialIndex, MapSlot slot) const
    {
        return material(materialIndex).map(slot);
    }
    // What changed in light `index` (all: not named, or another light now sits there).
    LightProperties light(std::size_t index) const;
    ViewProperties view() const;

private:
    void normalize(); // detail only where its kinds are and it is named; none elsewhere

    DocumentChangeKinds m_kinds;
    bool m_materialsNamed = false;
    std::map<std::size_t, MaterialChange> m_materials;
    ListChange m_materialList;
    bool m_lightsNamed = false;
    std::map<std::size_t, LightProperties> m_lights;
    ListChange m_lightList;
    bool m_viewNamed = false;
    ViewProperties m_view;
};

// The change that turns `before` into `after` (empty when they are equal), with its detail.
DocumentChanges changesBetween(const Project& before, const Project& after);

// Questions a view asks of a change (a compare view showing materials A and B under several
// environments asks them per cell). Each answers true whenever the change may concern it.
// Material `index` itself changed (values, or another material at that index); its name alone
// counts (a list shows names); a view that draws it also ignores MaterialField::Name.
bool affectsMaterial(const DocumentChanges& changes, std::size_t index);
// Light `index` (of the lights after the change) changed, or the list around it did.
bool affectsLight(const DocumentChanges& changes, std::size_t index);
// Any of the environment's settings (source, rotation, intensity, IBL quality).
bool affectsEnvironment(const DocumentChanges& changes);

// One line for logs and test failures, e.g. "MaterialMaps|Lights; materials 2{roughness{path}};
// lights removed[1]" ("*" where a kind names nothing, e.g. "WholeProject; materials *; ...").
std::string describe(const DocumentChanges& changes);

} // namespace facet
