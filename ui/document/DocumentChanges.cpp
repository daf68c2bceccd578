#include "ui/document/DocumentChanges.h"

#include "core/project/Project.h"

#include <algorithm>
#include <initializer_list>
#include <utility>

namespace facet {

namespace {

constexpr DocumentChangeKinds kMaterialKinds
    = DocumentChange::MaterialFactors | DocumentChange::MaterialMaps | DocumentChange::Shading;
constexpr DocumentChangeKinds kEnvironmentKinds = DocumentChange::EnvironmentSource
    | DocumentChange::EnvironmentRotation | DocumentChange::EnvironmentIntensity | DocumentChange::IblQuality;
constexpr MapProperties kTextureProperties = MapProperty::Path | MapProperty::ColorSpace;

// Whether two lists hold the same items at the moved positions in another order is checked up to
// this many moved items (a quadratic comparison); beyond, the moves are reported as edits only.
constexpr std::size_t kMaxReorderCheck = 64;

// A field that a description does not know yet (a new member of MaterialMap, Light, ...) still
// reports a change: everything, rather than nothing.
template <typename Flags, typename T> Flags orAll(Flags found, const T& a, const T& b, Flags all)
{
    return !found && !(a == b) ? all : found;
}

MapProperties mapChange(const MaterialMap& a, const MaterialMap& b)
{
    MapProperties changed;
    if (a.path != b.path)
        changed |= MapProperty::Path;
    if (a.colorSpace != b.colorSpace)
        changed |= MapProperty::ColorSpace;
    if (a.factor != b.factor)
        changed |= MapProperty::Factor;
    if (a.channel != b.channel)
        changed |= MapProperty::Channel;
    if (a.invert != b.invert)
        changed |= MapProperty::Invert;
    if (a.flipGreen != b.flipGreen)
        changed |= MapProperty::FlipGreen;
    if (a.uv != b.uv)
        changed |= MapProperty::Uv;
    if (a.texCoord != b.texCoord)
        changed |= MapProperty::TexCoord;
    if (a.sampler != b.sampler)
        changed |= MapProperty::Sampler;
    return orAll(changed, a, b, MapProperties(MapProperty::All));
}

MaterialChange materialChange(const Material& a, const Material& b)
{
    MaterialChange change;
    for (MapSlot slot : kAllMapSlots)
        change.maps[std::size_t(slot)] = mapChange(a.map(slot), b.map(slot));
    MaterialFields& changed = change.properties;
    if (a.name != b.name)
        changed |= MaterialField::Name;
    if (a.ior != b.ior)
        changed |= MaterialField::Ior;
    if (a.emissiveStrength != b.emissiveStrength)
        changed |= MaterialField::EmissiveStrength;
    if (a.alphaMode != b.alphaMode)
        changed |= MaterialField::AlphaMode;
    if (a.alphaCutoff != b.alphaCutoff)
        changed |= MaterialField::AlphaCutoff;
    if (a.doubleSided != b.doubleSided)
        changed |= MaterialField::DoubleSided;
    if (a.unlit != b.unlit)
        changed |= MaterialField::Unlit;
    if (a.anisotropyRotationDegrees != b.anisotropyRotationDegrees)
        changed |= MaterialField::AnisotropyRotation;
    if (a.iridescenceIor != b.iridescenceIor)
        changed |= MaterialField::IridescenceIor;
    if (a.iridescenceThicknessMinimum != b.iridescenceThicknessMinimum)
        changed |= MaterialField::IridescenceThicknessMinimum;
    if (a.shading != b.shading)
        changed |= MaterialField::Shading;
    if (change.isEmpty() && !(a == b))
        return MaterialChange::all();
    return change;
}

LightProperties lightChange(const Light& a, const Light& b)
{
    LightProperties changed;
    if (a.name != b.name)
        changed |= LightProperty::Name;
    if (a.type != b.type)
        changed |= LightProperty::Type;
    if (a.enabled != b.enabled)
        changed |= LightProperty::Enabled;
    if (a.color != b.color)
        changed |= LightProperty::Color;
    if (a.useTemperature != b.useTemperature || a.kelvin != b.kelvin)
        changed |= LightProperty::Temperature;
    if (a.intensity != b.intensity)
        changed |= LightProperty::Intensity;
    if (a.range != b.range)
        changed |= LightProperty::Range;
    if (a.innerConeAngle != b.innerConeAngle || a.outerConeAngle != b.outerConeAngle)
        changed |= LightProperty::Cone;
    if (a.position != b.position)
        changed |= LightProperty::Position;
    if (a.direction != b.direction)
        changed |= LightProperty::Direction;
    return orAll(changed, a, b, LightProperties(LightProperty::All));
}

ViewProperties viewChange(const ViewSettings& a, const ViewSettings& b)
{
    ViewProperties changed;
    if (a.exposureEV != b.exposureEV)
        changed |= ViewProperty::Exposure;
    if (a.toneMapper != b.toneMapper)
        changed |= ViewProperty::ToneMapper;
    if (a.displayEncoding != b.displayEncoding || a.gamma != b.gamma)
        changed |= ViewProperty::DisplayEncoding;
    if (a.ocioDisplay != b.ocioDisplay || a.ocioView != b.ocioView)
        changed |= ViewProperty::Ocio;
    if (a.debugView != b.debugView)
        changed |= ViewProperty::DebugView;
    if (a.msaaSamples != b.msaaSamples)
        changed |= ViewProperty::Msaa;
    if (a.background != b.background || a.backgroundColor != b.backgroundColor
        || a.backgroundBlurRoughness != b.backgroundBlurRoughness)
        changed |= ViewProperty::Background;
    ViewSettings aWithoutMesh = a;
    aWithoutMesh.mesh = b.mesh; // the mesh is kind Mesh
    return orAll(changed, aWithoutMesh, b, ViewProperties(ViewProperty::All));
}

// Whether `shorter` is `longer` with some items left out (greedy matching finds such a
// subsequence whenever one exists); the left-out indices of `longer` go to *extra.
template <typename T>
bool isSubsequence(
    const std::vector<T>& shorter, const std::vector<T>& longer, std::vector<std::size_t>* extra)
{
    std::size_t matched = 0;
    for (std::size_t i = 0; i < longer.size(); ++i) {
        if (matched < shorter.size() && longer[i] == shorter[matched])
            ++matched;
        else
            extra->push_back(i);
    }
    return matched == shorter.size();
}

// How `before` became `after`: items inserted only, removed only, or else the common indices
// compared one by one (with `reordered` when the moved items are the same ones) and the rest
// inserted or removed.
template <typename T, typename Properties, typename Compare>
void compareLists(const std::vector<T>& before, const std::vector<T>& after, Compare compare,
    ListChange* list, std::map<std::size_t, Properties>* edits)
{
    if (before == after)
        return;
    if (after.size() > before.size() && isSubsequence(before, after, &list->inserted))
        return;
    list->inserted.clear();
    if (before.size() > after.size() && isSubsequence(after, before, &list->removed))
        return;
    list->removed.clear();
    const std::size_t common = std::min(before.size(), after.size());
    std::vector<const T*> movedBefore;
    std::vector<const T*> movedAfter;
    for (std::size_t i = 0; i < common; ++i) {
        if (before[i] == after[i])
            continue;
        edits->emplace(i, compare(before[i], after[i]));
        movedBefore.push_back(&before[i]);
        movedAfter.push_back(&after[i]);
    }
    for (std::size_t i = common; i < after.size(); ++i)
        list->inserted.push_back(i);
    for (std::size_t i = common; i < before.size(); ++i)
        list->removed.push_back(i);
    list->reordered = before.size() == after.size() && movedBefore.size() >= 2
        && movedBefore.size() <= kMaxReorderCheck
        && std::is_permutation(movedBefore.begin(), movedBefore.end(), movedAfter.begin(),
            [](const T* a, const T* b) { return *a == *b; });
}

template <typename Properties>
std::string flagNames(Properties flags, std::initializer_list<std::pair<Properties, const char*>> names)
{
    std::string text;
    for (const auto& [flag, name] : names)
        if ((flags & flag) == flag) {
            if (!text.empty())
                text += ',';
            text += name;
        }
    return text;
}

std::string kindNames(DocumentChangeKinds kinds)
{
    if (kinds == DocumentChangeKinds(DocumentChange::WholeProject))
        return "WholeProject";
    if (!kinds)
        return "None";
    std::string text = flagNames<DocumentChangeKinds>(kinds,
        {{DocumentChange::MaterialFactors, "MaterialFactors"}, {DocumentChange::MaterialMaps, "MaterialMaps"},
            {DocumentChange::Shading, "Shading"}, {DocumentChange::EnvironmentSource, "EnvironmentSource"},
            {DocumentChange::EnvironmentRotation, "EnvironmentRotation"},
            {DocumentChange::EnvironmentIntensity, "EnvironmentIntensity"},
            {DocumentChange::IblQuality, "IblQuality"}, {DocumentChange::Lights, "Lights"},
            {DocumentChange::View, "View"}, {DocumentChange::Camera, "Camera"},
            {DocumentChange::Mesh, "Mesh"}, {DocumentChange::CurrentMaterial, "CurrentMaterial"},
            {DocumentChange::Parts, "Parts"}, {DocumentChange::Compare, "Compare"}});
    std::replace(text.begin(), text.end(), ',', '|');
    return text;
}

std::string mapNames(MapProperties changed)
{
    if (changed == MapProperties(MapProperty::All))
        return "all";
    return flagNames<MapProperties>(changed,
        {{MapProperty::Path, "path"}, {MapProperty::ColorSpace, "colorSpace"},
            {MapProperty::Factor, "factor"}, {MapProperty::Channel, "channel"},
            {MapProperty::Invert, "invert"}, {MapProperty::FlipGreen, "flipGreen"}, {MapProperty::Uv, "uv"},
            {MapProperty::TexCoord, "texCoord"}, {MapProperty::Sampler, "sampler"}});
}

std::string materialNames(const MaterialChange& change)
{
    if (change == MaterialChange::all())
        return "all";
    std::string text = flagNames<MaterialFields>(change.properties,
        {{MaterialField::Name, "name"}, {MaterialField::Ior, "ior"},
            {MaterialField::EmissiveStrength, "emissiveStrength"}, {MaterialField::AlphaMode, "alphaMode"},
            {MaterialField::AlphaCutoff, "alphaCutoff"}, {MaterialField::DoubleSided, "doubleSided"},
            {MaterialField::Shading, "shading"}, {MaterialField::Unlit, "unlit"},
            {MaterialField::AnisotropyRotation, "anisotropyRotationDegrees"},
            {MaterialField::IridescenceIor, "iridescenceIor"},
            {MaterialField::IridescenceThicknessMinimum, "iridescenceThicknessMinimum"}});
    for (MapSlot slot : kAllMapSlots)
        if (change.map(slot)) {
            if (!text.empty())
                text += ',';
            text += toString(slot);
            text += '{';
            text += mapNames(change.map(slot));
            text += '}';
        }
    return text;
}

std::string lightNames(LightProperties changed)
{
    if (changed == LightProperties(LightProperty::All))
        return "all";
    return flagNames<LightProperties>(changed,
        {{LightProperty::Name, "name"}, {LightProperty::Type, "type"}, {LightProperty::Enabled, "enabled"},
            {LightProperty::Color, "color"}, {LightProperty::Temperature, "temperature"},
            {LightProperty::Intensity, "intensity"}, {LightProperty::Range, "range"},
            {LightProperty::Cone, "cone"}, {LightProperty::Position, "position"},
            {LightProperty::Direction, "direction"}});
}

std::string viewNames(ViewProperties changed)
{
    if (changed == ViewProperties(ViewProperty::All))
        return "all";
    return flagNames<ViewProperties>(changed,
        {{ViewProperty::Exposure, "exposure"}, {ViewProperty::ToneMapper, "toneMapper"},
            {ViewProperty::DisplayEncoding, "displayEncoding"}, {ViewProperty::Ocio, "ocio"},
            {ViewProperty::DebugView, "debugView"}, {ViewProperty::Msaa, "msaa"},
            {ViewProperty::Background, "background"}});
}

// Strings are built by append: GCC 12's -Wrestrict misfires on `"literal" + std::string`.
std::string indexList(const std::vector<std::size_t>& indices)
{
    std::string text = "[";
    for (std::size_t index : indices) {
        if (text.size() > 1)
            text += ',';
        text += std::to_string(index);
    }
    text += ']';
    return text;
}

template <typename Properties, typename Names>
std::string listDescription(
    const ListChange& list, const std::map<std::size_t, Properties>& edits, Names names)
{
    std::string text;
    for (const auto& [index, changed] : edits) {
        text += ' ';
        text += std::to_string(index);
        text += '{';
        text += names(changed);
        text += '}';
    }
    if (!list.inserted.empty()) {
        text += " inserted";
        text += indexList(list.inserted);
    }
    if (!list.removed.empty()) {
        text += " removed";
        text += indexList(list.removed);
    }
    if (list.reordered)
        text += " reordered";
    return text;
}

} // namespace

// --- MaterialChange, ListChange ---------------------------------------------------------------

MaterialChange MaterialChange::all()
{
    MaterialChange change;
    change.properties = MaterialField::All;
    change.maps.fill(MapProperty::All);
    return change;
}

MaterialChange MaterialChange::ofMap(MapSlot slot, MapProperties changed)
{
    MaterialChange change;
    change.maps[std::size_t(slot)] = changed;
    return change;
}

bool MaterialChange::isEmpty() const
{
    return !properties && std::none_of(maps.begin(), maps.end(), [](MapProperties p) { return bool(p); });
}

DocumentChangeKinds MaterialChange::kinds() const
{
    DocumentChangeKinds kinds;
    if (properties & ~MaterialFields(MaterialField::Shading))
        kinds |= DocumentChange::MaterialFactors;
    if (properties & MaterialField::Shading)
        kinds |= DocumentChange::Shading;
    for (MapProperties changed : maps) {
        if (changed & kTextureProperties)
            kinds |= DocumentChange::MaterialMaps;
        if (changed & ~kTextureProperties)
            kinds |= DocumentChange::MaterialFactors;
    }
    return kinds;
}

MaterialChange& MaterialChange::operator|=(const MaterialChange& other)
{
    properties |= other.properties;
    for (std::size_t slot = 0; slot < maps.size(); ++slot)
        maps[slot] |= other.maps[slot];
    return *this;
}

std::size_t ListChange::firstShifted() const
{
    std::size_t first = DocumentChanges::kNone;
    if (!inserted.empty())
        first = std::min(first, inserted.front());
    if (!removed.empty())
        first = std::min(first, removed.front());
    return first;
}

// --- DocumentChanges ---------------------------------------------------------------------------

DocumentChanges::DocumentChanges(DocumentChangeKinds kinds)
    : m_kinds(kinds)
{
}

DocumentChanges DocumentChanges::ofMaterial(std::size_t index, const MaterialChange& change)
{
    return ofMaterialList({}, {{index, change}});
}

DocumentChanges DocumentChanges::ofMaterialList(
    const ListChange& list, const std::map<std::size_t, MaterialChange>& edits)
{
    DocumentChanges changes;
    changes.m_materialsNamed = true;
    changes.m_materialList = list;
    for (const auto& [index, change] : edits)
        if (!change.isEmpty()) {
            changes.m_materials.emplace(index, change);
            changes.m_kinds |= change.kinds();
        }
    if (!list.inserted.empty() || !list.removed.empty())
        changes.m_kinds |= kMaterialKinds;
    changes.normalize();
    return changes;
}

DocumentChanges DocumentChanges::ofLight(std::size_t index, LightProperties changed)
{
    return ofLightList({}, {{index, changed}});
}

DocumentChanges DocumentChanges::ofLightList(
    const ListChange& list, const std::map<std::size_t, LightProperties>& edits)
{
    DocumentChanges changes;
    changes.m_lightsNamed = true;
    changes.m_lightList = list;
    for (const auto& [index, changed] : edits)
        if (changed)
            changes.m_lights.emplace(index, changed);
    if (!changes.m_lights.empty() || !list.isEmpty())
        changes.m_kinds |= DocumentChange::Lights;
    changes.normalize();
    return changes;
}

DocumentChanges DocumentChanges::ofView(ViewProperties changed)
{
    DocumentChanges changes;
    changes.m_viewNamed = true;
    changes.m_view = changed;
    if (changed)
        changes.m_kinds |= DocumentChange::View;
    changes.normalize();
    return changes;
}

void DocumentChanges::normalize()
{
    if (!(m_kinds & kMaterialKinds) || !m_materialsNamed) {
        m_materialsNamed = false;
        m_materials.clear();
        m_materialList = {};
    }
    if (!(m_kinds & DocumentChange::Lights) || !m_lightsNamed) {
        m_lightsNamed = false;
        m_lights.clear();
        m_lightList = {};
    }
    if (!(m_kinds & DocumentChange::View) || !m_viewNamed) {
        m_viewNamed = false;
        m_view = {};
    }
}

DocumentChanges& DocumentChanges::operator|=(const DocumentChanges& other)
{
    // Per list: taken over when only one side has it; merged index by index when both are in-place
    // edits (their indices name the same positions); otherwise nothing is named any more.
    if (other.m_kinds & kMaterialKinds) {
        if (!(m_kinds & kMaterialKinds)) {
            m_materialsNamed = other.m_materialsNamed;
            m_materials = other.m_materials;
            m_materialList = other.m_materialList;
        } else if (m_materialsNamed && other.m_materialsNamed && m_materialList.firstShifted() == kNone
            && other.m_materialList.firstShifted() == kNone) {
            for (const auto& [index, change] : other.m_materials)
                m_materials[index] |= change;
            m_materialList.reordered = m_materialList.reordered || other.m_materialList.reordered;
        } else {
            m_materialsNamed = false;
        }
    }
    if (other.m_kinds & DocumentChange::Lights) {
        if (!(m_kinds & DocumentChange::Lights)) {
            m_lightsNamed = other.m_lightsNamed;
            m_lights = other.m_lights;
            m_lightList = other.m_lightList;
        } else if (m_lightsNamed && other.m_lightsNamed && m_lightList.firstShifted() == kNone
            && other.m_lightList.firstShifted() == kNone) {
            for (const auto& [index, changed] : other.m_lights)
                m_lights[index] |= changed;
            m_lightList.reordered = m_lightList.reordered || other.m_lightList.reordered;
        } else {
            m_lightsNamed = false;
        }
    }
    if (other.m_kinds & DocumentChange::View) {
        if (!(m_kinds & DocumentChange::View)) {
            m_viewNamed = other.m_viewNamed;
            m_view = other.m_view;
        } else {
            m_viewNamed = m_viewNamed && other.m_viewNamed;
            m_view |= other.m_view;
        }
    }
    m_kinds |= other.m_kinds;
    normalize();
    return *this;
}

MaterialChange DocumentChanges::material(std::size_t index) const
{
    if (!(m_kinds & kMaterialKinds))
        return {};
    if (!m_materialsNamed || index >= m_materialList.firstShifted())
        return MaterialChange::all();
    const auto found = m_materials.find(index);
    return found == m_materials.end() ? MaterialChange {} : found->second;
}

LightProperties DocumentChanges::light(std::size_t index) const
{
    if (!(m_kinds & DocumentChange::Lights))
        return {};
    if (!m_lightsNamed || index >= m_lightList.firstShifted())
        return LightProperty::All;
    const auto found = m_lights.find(index);
    return found == m_lights.end() ? LightProperties() : found->second;
}

ViewProperties DocumentChanges::view() const
{
    if (!(m_kinds & DocumentChange::View))
        return {};
    return m_viewNamed ? m_view : ViewProperties(ViewProperty::All);
}

// --- Comparing two projects --------------------------------------------------------------------

DocumentChanges changesBetween(const Project& before, const Project& after)
{
    DocumentChanges changes;

    ListChange materialList;
    std::map<std::size_t, MaterialChange> materialEdits;
    compareLists(before.materials, after.materials, materialChange, &materialList, &materialEdits);
    changes |= DocumentChanges::ofMaterialList(materialList, materialEdits);

    ListChange lightList;
    std::map<std::size_t, LightProperties> lightEdits;
    compareLists(before.lights, after.lights, lightChange, &lightList, &lightEdits);
    changes |= DocumentChanges::ofLightList(lightList, lightEdits);

    changes |= DocumentChanges::ofView(viewChange(before.view, after.view));

    DocumentChangeKinds kinds;
    if (before.currentMaterial != after.currentMaterial)
        kinds |= DocumentChange::CurrentMaterial;
    if (before.parts != after.parts)
        kinds |= DocumentChange::Parts;
    if (before.compare != after.compare)
        kinds |= DocumentChange::Compare;
    const EnvironmentSettings& ea = before.environment;
    const EnvironmentSettings& eb = after.environment;
    if (ea.source != eb.source)
        kinds |= DocumentChange::EnvironmentSource;
    if (ea.rotationDegrees != eb.rotationDegrees)
        kinds |= DocumentChange::EnvironmentRotation;
    if (ea.intensity != eb.intensity)
        kinds |= DocumentChange::EnvironmentIntensity;
    if (ea.quality != eb.quality || ea.method != eb.method || ea.samples != eb.samples)
        kinds |= DocumentChange::IblQuality;
    if (before.camera != after.camera)
        kinds |= DocumentChange::Camera;
    if (before.view.mesh != after.view.mesh || before.view.keepUnits != after.view.keepUnits)
        kinds |= DocumentChange::Mesh;
    changes |= DocumentChanges(kinds);
    return changes;
}

// --- Questions ---------------------------------------------------------------------------------

bool affectsMaterial(const DocumentChanges& changes, std::size_t index)
{
    return !changes.material(index).isEmpty();
}

bool affectsLight(const DocumentChanges& changes, std::size_t index)
{
    return bool(changes.light(index));
}

bool affectsEnvironment(const DocumentChanges& changes)
{
    return bool(changes & kEnvironmentKinds);
}

std::string describe(const DocumentChanges& changes)
{
    std::string text = kindNames(changes.kinds());
    if (changes & kMaterialKinds) {
        text += "; materials";
        text += changes.namesMaterials()
            ? listDescription(changes.materialList(), changes.materialEdits(), materialNames)
            : std::string(" *");
    }
    if (changes & DocumentChange::Lights) {
        text += "; lights";
        text += changes.namesLights() ? listDescription(changes.lightList(), changes.lightEdits(), lightNames)
                                      : std::string(" *");
    }
    if (changes & DocumentChange::View) {
        text += "; view ";
        text += changes.namesView() ? viewNames(changes.view()) : std::string("*");
    }
    return text;
}

} // namespace facet
