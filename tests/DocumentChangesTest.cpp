// Change descriptions (ui/document/DocumentChanges.h): changesBetween names exactly what an edit changed
// (which material and map slot, which light, which view setting, and list insertions, removals
// and reorders), one row per kind of edit; the questions views ask (affectsMaterial,
// affectsLight, affectsEnvironment, map()) answer from it; a description of kinds alone
// (New/Open, files changed on disk) answers "changed" to everything of those kinds; and two
// changes combine without losing any. changesBetween is pure: this test is built with
// ui/document/DocumentChanges.cpp alone and needs no widgets and no display.

#include "ui/document/DocumentChanges.h"

#include "core/project/Project.h"

#include <QtTest/QTest>

#include <functional>
#include <string>
#include <utility>
#include <vector>

using namespace facet;

namespace facet {
// QCOMPARE prints both descriptions when they differ.
char* toString(const DocumentChanges& changes)
{
    return QTest::toString(describe(changes).c_str());
}
} // namespace facet

namespace {

// Three materials (the third names a file in every slot), three lights, three parts.
Project baseProject()
{
    Project project = Project::defaultProject();
    Material plain = project.materials[0];
    Material blue = plain;
    blue.name = "Blue";
    Material textured = plain;
    textured.name = "Textured";
    for (MapSlot slot : kAllMapSlots)
        textured.map(slot).path = std::string("/maps/") + toString(slot) + ".png";
    project.materials = {plain, blue, textured};
    Light key = Light::defaultDirectional();
    key.name = "Key";
    Light fill = key;
    fill.name = "Fill";
    fill.intensity = 5.0;
    Light rim = key;
    rim.name = "Rim";
    rim.color = {1.0, 0.5, 0.2};
    project.lights = {key, fill, rim};
    project.parts = {{"a", 0, true}, {"b", 1, true}, {"c", 2, true}};
    return project;
}

struct Row {
    std::string name;
    std::function<void(Project&)> edit;
    DocumentChanges expected;
};

DocumentChanges material(std::size_t index, MaterialFields changed)
{
    MaterialChange change;
    change.properties = changed;
    return DocumentChanges::ofMaterial(index, change);
}

DocumentChanges map(std::size_t index, MapSlot slot, MapProperties changed)
{
    return DocumentChanges::ofMaterial(index, MaterialChange::ofMap(slot, changed));
}

DocumentChanges light(std::size_t index, LightProperties changed)
{
    return DocumentChanges::ofLight(index, changed);
}

ListChange inserted(std::vector<std::size_t> indices)
{
    return ListChange {std::move(indices), {}, false};
}

ListChange removed(std::vector<std::size_t> indices)
{
    return ListChange {{}, std::move(indices), false};
}

const ListChange kReordered {{}, {}, true};

// What the Lights dock's Duplicate does: the copy goes after the original. (A new vector: GCC 12
// at -O3 misreads vector::insert here as out of bounds.)
void duplicateFirstLight(Project& p)
{
    std::vector<Light> lights {p.lights[0]};
    lights.insert(lights.end(), p.lights.begin(), p.lights.end());
    p.lights = std::move(lights);
}

std::vector<Row> rows()
{
    std::vector<Row> table;
    const auto add
        = [&table](std::string name, std::function<void(Project&)> edit, DocumentChanges expected) {
              table.push_back(Row {std::move(name), std::move(edit), std::move(expected)});
          };

    // --- Each material field (material 1), each alone.
    add(
        "material name", [](Project& p) { p.materials[1].name = "Red"; }, material(1, MaterialField::Name));
    add(
        "material ior", [](Project& p) { p.materials[1].ior = 1.7; }, material(1, MaterialField::Ior));
    add(
        "material emissive strength", [](Project& p) { p.materials[1].emissiveStrength = 3.0; },
        material(1, MaterialField::EmissiveStrength));
    add(
        "material alpha mode", [](Project& p) { p.materials[1].alphaMode = AlphaMode::Mask; },
        material(1, MaterialField::AlphaMode));
    add(
        "material alpha cutoff", [](Project& p) { p.materials[1].alphaCutoff = 0.25; },
        material(1, MaterialField::AlphaCutoff));
    add(
        "material double-sided", [](Project& p) { p.materials[1].doubleSided = false; },
        material(1, MaterialField::DoubleSided));
    add(
        "material unlit", [](Project& p) { p.materials[1].unlit = true; }, material(1, MaterialField::Unlit));
    add(
        "material anisotropy rotation", [](Project& p) { p.materials[1].anisotropyRotationDegrees = 45.0; },
        material(1, MaterialField::AnisotropyRotation));
    add(
        "material anisotropy", [](Project& p) { p.materials[1].setFactor(MapSlot::Anisotropy, 0.5); },
        map(1, MapSlot::Anisotropy, MapProperty::Factor));
    add(
        "material iridescence ior", [](Project& p) { p.materials[1].iridescenceIor = 1.8; },
        material(1, MaterialField::IridescenceIor));
    add(
        "material iridescence thickness minimum",
        [](Project& p) { p.materials[1].iridescenceThicknessMinimum = 250.0; },
        material(1, MaterialField::IridescenceThicknessMinimum));
    add(
        "material iridescence thickness (the map's factor)",
        [](Project& p) { p.materials[1].setFactor(MapSlot::IridescenceThickness, 650.0); },
        map(1, MapSlot::IridescenceThickness, MapProperty::Factor));
    add(
        "material clearcoat", [](Project& p) { p.materials[1].setFactor(MapSlot::Clearcoat, 0.5); },
        map(1, MapSlot::Clearcoat, MapProperty::Factor));
    add(
        "material clearcoat roughness",
        [](Project& p) { p.materials[1].setFactor(MapSlot::ClearcoatRoughness, 0.2); },
        map(1, MapSlot::ClearcoatRoughness, MapProperty::Factor));
    add(
        "material 0 clearcoat normal flip green",
        [](Project& p) { p.materials[0].map(MapSlot::ClearcoatNormal).flipGreen = true; },
        map(0, MapSlot::ClearcoatNormal, MapProperty::FlipGreen));
    add(
        "material shading", [](Project& p) { p.materials[1].shading.multiScatter = false; },
        material(1, MaterialField::Shading));

    // --- Each map slot's path, colour space and channel, of material 0 (no files) and of
    // material 2 (a file in every slot).
    for (std::size_t m : {std::size_t(0), std::size_t(2)})
        for (MapSlot slot : kAllMapSlots) {
            const std::string where = "material " + std::to_string(m) + " " + toString(slot);
            add(
                where + " path", [m, slot](Project& p) { p.materials[m].map(slot).path = "/other/file.png"; },
                map(m, slot, MapProperty::Path));
            add(
                where + " colour space",
                [m, slot](Project& p) {
                    ColorEncoding& space = p.materials[m].map(slot).colorSpace;
                    space = space == ColorEncoding::SRGB ? ColorEncoding::Linear : ColorEncoding::SRGB;
                },
                map(m, slot, MapProperty::ColorSpace));
            add(
                where + " channel",
                [m, slot](Project& p) {
                    MapChannel& channel = p.materials[m].map(slot).channel;
                    channel = channel == MapChannel::R ? MapChannel::G : MapChannel::R;
                },
                map(m, slot, MapProperty::Channel));
        }
    // The other per-map fields (one slot each).
    add(
        "material 2 roughness factor", [](Project& p) { p.materials[2].setFactor(MapSlot::Roughness, 0.9); },
        map(2, MapSlot::Roughness, MapProperty::Factor));
    add(
        "material 2 metallic invert", [](Project& p) { p.materials[2].map(MapSlot::Metallic).invert = true; },
        map(2, MapSlot::Metallic, MapProperty::Invert));
    add(
        "material 0 normal flip green",
        [](Project& p) { p.materials[0].map(MapSlot::Normal).flipGreen = true; },
        map(0, MapSlot::Normal, MapProperty::FlipGreen));
    add(
        "material 0 base colour uv",
        [](Project& p) {
            p.materials[0].map(MapSlot::BaseColor).uv.scale = {2, 2};
        },
        map(0, MapSlot::BaseColor, MapProperty::Uv));
    // Two slots of one material, one edit: one material named, both slots in it.
    {
        MaterialChange both = MaterialChange::ofMap(MapSlot::Normal, MapProperty::Path);
        both |= MaterialChange::ofMap(MapSlot::Roughness, MapProperty::Factor);
        add(
            "material 2 normal path and roughness factor",
            [](Project& p) {
                p.materials[2].map(MapSlot::Normal).path = "/other/normal.png";
                p.materials[2].setFactor(MapSlot::Roughness, 0.1);
            },
            DocumentChanges::ofMaterial(2, both));
    }

    // --- The material list.
    add(
        "material appended", [](Project& p) { p.materials.push_back(Material {}); },
        DocumentChanges::ofMaterialList(inserted({3})));
    add(
        "material inserted first", [](Project& p) { p.materials.insert(p.materials.begin(), Material {}); },
        DocumentChanges::ofMaterialList(inserted({0})));
    add(
        "material 1 removed", [](Project& p) { p.materials.erase(p.materials.begin() + 1); },
        DocumentChanges::ofMaterialList(removed({1})));
    // Materials 0 and 1 differ in their names only.
    add(
        "materials 0 and 1 swapped", [](Project& p) { std::swap(p.materials[0], p.materials[1]); },
        DocumentChanges::ofMaterialList(kReordered,
            {{0, MaterialChange {MaterialField::Name, {}}}, {1, MaterialChange {MaterialField::Name, {}}}}));
    add(
        "materials replaced by two others",
        [](Project& p) {
            p.materials.pop_back();
            for (Material& m : p.materials)
                m.ior = 1.6;
        },
        DocumentChanges::ofMaterialList(removed({2}),
            {{0, MaterialChange {MaterialField::Ior, {}}}, {1, MaterialChange {MaterialField::Ior, {}}}}));

    // --- Each light field (light 1), each alone.
    const std::vector<std::pair<const char*, std::pair<std::function<void(Light&)>, LightProperty>>>
        lightFields = {{"name", {[](Light& l) { l.name = "Back"; }, LightProperty::Name}},
            {"type", {[](Light& l) { l.type = LightType::Spot; }, LightProperty::Type}},
            {"enabled", {[](Light& l) { l.enabled = false; }, LightProperty::Enabled}},
            {"color",
                {[](Light& l) {
                     l.color = {0.2, 0.4, 1.0};
                 },
                    LightProperty::Color}},
            {"use temperature", {[](Light& l) { l.useTemperature = true; }, LightProperty::Temperature}},
            {"kelvin", {[](Light& l) { l.kelvin = 3200.0; }, LightProperty::Temperature}},
            {"intensity", {[](Light& l) { l.intensity = 12.0; }, LightProperty::Intensity}},
            {"range", {[](Light& l) { l.range = 4.0; }, LightProperty::Range}},
            {"inner cone", {[](Light& l) { l.innerConeAngle = 0.1; }, LightProperty::Cone}},
            {"outer cone", {[](Light& l) { l.outerConeAngle = 0.5; }, LightProperty::Cone}},
            {"position",
                {[](Light& l) {
                     l.position = {1, 2, 3};
                 },
                    LightProperty::Position}},
            {"direction",
                {[](Light& l) {
                     l.direction = {0, -1, 0};
                 },
                    LightProperty::Direction}}};
    for (const auto& [field, edit] : lightFields) {
        const auto change = edit.first;
        add(
            std::string("light 1 ") + field, [change](Project& p) { change(p.lights[1]); },
            light(1, edit.second));
    }
    // --- The light list.
    add(
        "light appended", [](Project& p) { p.lights.push_back(Light::defaultDirectional()); },
        DocumentChanges::ofLightList(inserted({3})));
    // The Lights dock's Duplicate inserts the copy after the original.
    add(
        "light 0 duplicated", [](Project& p) { duplicateFirstLight(p); },
        DocumentChanges::ofLightList(inserted({1})));
    add(
        "light 1 removed", [](Project& p) { p.lights.erase(p.lights.begin() + 1); },
        DocumentChanges::ofLightList(removed({1})));
    add(
        "every light removed", [](Project& p) { p.lights.clear(); },
        DocumentChanges::ofLightList(removed({0, 1, 2})));
    // Key and Fill differ in name and intensity.
    add(
        "lights 0 and 1 swapped", [](Project& p) { std::swap(p.lights[0], p.lights[1]); },
        DocumentChanges::ofLightList(kReordered,
            {{0, LightProperty::Name | LightProperty::Intensity},
                {1, LightProperty::Name | LightProperty::Intensity}}));
    add(
        "lights replaced by two others",
        [](Project& p) {
            p.lights.pop_back();
            for (Light& l : p.lights)
                l.color = {0.5, 0.5, 0.5};
        },
        DocumentChanges::ofLightList(removed({2}), {{0, LightProperty::Color}, {1, LightProperty::Color}}));

    // --- The environment.
    add(
        "environment source", [](Project& p) { p.environment.source = "sky"; },
        DocumentChange::EnvironmentSource);
    add(
        "environment rotation", [](Project& p) { p.environment.rotationDegrees = 90; },
        DocumentChange::EnvironmentRotation);
    add(
        "environment intensity", [](Project& p) { p.environment.intensity = 2; },
        DocumentChange::EnvironmentIntensity);
    add(
        "IBL quality", [](Project& p) { p.environment.quality = IblQuality::Draft; },
        DocumentChange::IblQuality);
    add(
        "IBL method", [](Project& p) { p.environment.method = IblMethod::Fis; }, DocumentChange::IblQuality);
    add(
        "IBL samples", [](Project& p) { p.environment.samples = 64; }, DocumentChange::IblQuality);

    // --- Each view field; the mesh is a kind of its own.
    add(
        "view exposure", [](Project& p) { p.view.exposureEV = 1; },
        DocumentChanges::ofView(ViewProperty::Exposure));
    add(
        "view tone mapper", [](Project& p) { p.view.toneMapper = ToneMapper::Aces; },
        DocumentChanges::ofView(ViewProperty::ToneMapper));
    add(
        "view display encoding", [](Project& p) { p.view.displayEncoding = DisplayEncoding::Gamma; },
        DocumentChanges::ofView(ViewProperty::DisplayEncoding));
    add(
        "view gamma", [](Project& p) { p.view.gamma = 2.4; },
        DocumentChanges::ofView(ViewProperty::DisplayEncoding));
    add(
        "view OCIO display", [](Project& p) { p.view.ocioDisplay = "sRGB"; },
        DocumentChanges::ofView(ViewProperty::Ocio));
    add(
        "view OCIO view", [](Project& p) { p.view.ocioView = "ACES"; },
        DocumentChanges::ofView(ViewProperty::Ocio));
    add(
        "view debug view", [](Project& p) { p.view.debugView = DebugView::ShadingNormal; },
        DocumentChanges::ofView(ViewProperty::DebugView));
    add(
        "view MSAA", [](Project& p) { p.view.msaaSamples = 8; }, DocumentChanges::ofView(ViewProperty::Msaa));
    add(
        "view background mode", [](Project& p) { p.view.background = BackgroundMode::Color; },
        DocumentChanges::ofView(ViewProperty::Background));
    add(
        "view background colour",
        [](Project& p) {
            p.view.backgroundColor = {1, 0, 0};
        },
        DocumentChanges::ofView(ViewProperty::Background));
    add(
        "view background blur", [](Project& p) { p.view.backgroundBlurRoughness = 0.2; },
        DocumentChanges::ofView(ViewProperty::Background));
    add(
        "mesh", [](Project& p) { p.view.mesh = "cube"; }, DocumentChange::Mesh);
    add(
        "mesh and exposure",
        [](Project& p) {
            p.view.mesh = "cube";
            p.view.exposureEV = 1;
        },
        DocumentChanges(DocumentChange::Mesh) | DocumentChanges::ofView(ViewProperty::Exposure));

    // --- The rest.
    add(
        "camera", [](Project& p) { p.camera.position.x = 1; }, DocumentChange::Camera);
    add(
        "part 1's material", [](Project& p) { p.parts[1].material = 2; }, DocumentChange::Parts);
    add(
        "part 2 hidden", [](Project& p) { p.parts[2].visible = false; }, DocumentChange::Parts);
    add(
        "current material", [](Project& p) { p.currentMaterial = 2; }, DocumentChange::CurrentMaterial);
    add(
        "compare mode", [](Project& p) { p.compare.mode = CompareMode::Wedge; }, DocumentChange::Compare);
    add(
        "A/B split", [](Project& p) { p.compare.ab.split = 0.25; }, DocumentChange::Compare);
    add(
        "several at once",
        [](Project& p) {
            p.materials[2].map(MapSlot::Roughness).path = "/other/rough.png";
            p.lights[0].intensity = 9.0;
            p.environment.rotationDegrees = 30;
            p.view.exposureEV = -1;
            p.camera.position.y = 2;
        },
        map(2, MapSlot::Roughness, MapProperty::Path) | light(0, LightProperty::Intensity)
            | DocumentChanges::ofView(ViewProperty::Exposure)
            | DocumentChanges(DocumentChange::EnvironmentRotation | DocumentChange::Camera));
    add(
        "nothing", [](Project&) {}, DocumentChanges());
    return table;
}

} // namespace

Q_DECLARE_METATYPE(facet::DocumentChanges)

class DocumentChangesTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void changesBetweenNamesWhatChanged_data();
    void changesBetweenNamesWhatChanged();
    void undoNamesTheSameThings();
    void kindsOfEachEdit();
    void questions_data();
    void questions();
    void kindsAloneNameEverything();
    void combining();
    void flagApiStillWorks();
    void describeWords();
};

void DocumentChangesTest::changesBetweenNamesWhatChanged_data()
{
    QTest::addColumn<int>("row");
    const std::vector<Row> table = rows();
    for (std::size_t i = 0; i < table.size(); ++i)
        QTest::newRow(table[i].name.c_str()) << int(i);
}

void DocumentChangesTest::changesBetweenNamesWhatChanged()
{
    QFETCH(int, row);
    const Row r = rows()[std::size_t(row)];
    const Project before = baseProject();
    Project after = before;
    r.edit(after);
    QCOMPARE(changesBetween(before, after), r.expected);
}

void DocumentChangesTest::undoNamesTheSameThings()
{
    // Undo compares the other way: the same materials, slots, properties; insertions become
    // removals of the same indices.
    const Project before = baseProject();
    for (const Row& r : rows()) {
        Project after = before;
        r.edit(after);
        const DocumentChanges undo = changesBetween(after, before);
        QVERIFY2(undo.kinds() == r.expected.kinds(), r.name.c_str());
        QVERIFY2(undo.materialEdits() == r.expected.materialEdits(), r.name.c_str());
        QVERIFY2(undo.lightEdits() == r.expected.lightEdits(), r.name.c_str());
        QVERIFY2(undo.view() == r.expected.view(), r.name.c_str());
        QVERIFY2(undo.materialList().inserted == r.expected.materialList().removed, r.name.c_str());
        QVERIFY2(undo.lightList().removed == r.expected.lightList().inserted, r.name.c_str());
    }
}

void DocumentChangesTest::kindsOfEachEdit()
{
    // The kinds observers filter on: a factor is not a texture, a texture is not a shader.
    const auto kinds = [](std::function<void(Project&)> edit) {
        const Project before = baseProject();
        Project after = before;
        edit(after);
        return changesBetween(before, after).kinds();
    };
    QCOMPARE(kinds([](Project& p) { p.materials[0].setFactor(MapSlot::Roughness, 0.9); }),
        DocumentChangeKinds(DocumentChange::MaterialFactors));
    QCOMPARE(kinds([](Project& p) { p.materials[0].name = "x"; }),
        DocumentChangeKinds(DocumentChange::MaterialFactors));
    QCOMPARE(kinds([](Project& p) { p.materials[2].map(MapSlot::Normal).path = "/n.png"; }),
        DocumentChangeKinds(DocumentChange::MaterialMaps));
    QCOMPARE(
        kinds([](Project& p) { p.materials[2].map(MapSlot::BaseColor).colorSpace = ColorEncoding::Linear; }),
        DocumentChangeKinds(DocumentChange::MaterialMaps));
    QCOMPARE(kinds([](Project& p) { p.materials[1].shading.multiScatter = false; }),
        DocumentChangeKinds(DocumentChange::Shading));
    QCOMPARE(kinds([](Project& p) { p.materials.pop_back(); }),
        DocumentChange::MaterialFactors | DocumentChange::MaterialMaps | DocumentChange::Shading);
    QCOMPARE(kinds([](Project& p) { std::swap(p.materials[0], p.materials[1]); }),
        DocumentChangeKinds(DocumentChange::MaterialFactors));
    QCOMPARE(kinds([](Project& p) { p.lights.pop_back(); }), DocumentChangeKinds(DocumentChange::Lights));
    QCOMPARE(kinds([](Project& p) { p.view.debugView = DebugView::ShadingNormal; }),
        DocumentChangeKinds(DocumentChange::View));
}

void DocumentChangesTest::questions_data()
{
    QTest::addColumn<DocumentChanges>("changes");
    QTest::addColumn<QList<bool>>("materials"); // affectsMaterial(0..3)
    QTest::addColumn<QList<bool>>("lights"); // affectsLight(0..3)
    QTest::addColumn<bool>("environment");

    const auto between = [](std::function<void(Project&)> edit) {
        const Project before = baseProject();
        Project after = before;
        edit(after);
        return changesBetween(before, after);
    };
    QTest::newRow("material 2 roughness map")
        << between([](Project& p) { p.materials[2].map(MapSlot::Roughness).path = "/r.png"; })
        << QList<bool> {false, false, true, false} << QList<bool> {false, false, false, false} << false;
    QTest::newRow("material 0 name") << between([](Project& p) { p.materials[0].name = "x"; })
                                     << QList<bool> {true, false, false, false}
                                     << QList<bool> {false, false, false, false} << false;
    // Removing material 1 shifts material 2 to index 1: both indices now hold another material.
    QTest::newRow("material 1 removed")
        << between([](Project& p) { p.materials.erase(p.materials.begin() + 1); })
        << QList<bool> {false, true, true, true} << QList<bool> {false, false, false, false} << false;
    QTest::newRow("material appended")
        << between([](Project& p) { p.materials.push_back(Material {}); })
        << QList<bool> {false, false, false, true} << QList<bool> {false, false, false, false} << false;
    QTest::newRow("light 2 colour") << between([](Project& p) {
        p.lights[2].color = {0, 1, 0};
    }) << QList<bool> {false, false, false, false}
                                    << QList<bool> {false, false, true, false} << false;
    QTest::newRow("light 0 duplicated")
        << between([](Project& p) { duplicateFirstLight(p); }) << QList<bool> {false, false, false, false}
        << QList<bool> {false, true, true, true} << false;
    QTest::newRow("last light removed")
        << between([](Project& p) { p.lights.pop_back(); }) << QList<bool> {false, false, false, false}
        << QList<bool> {false, false, true, true} << false;
    QTest::newRow("lights 0 and 2 swapped")
        << between([](Project& p) { std::swap(p.lights[0], p.lights[2]); })
        << QList<bool> {false, false, false, false} << QList<bool> {true, false, true, false} << false;
    QTest::newRow("environment rotation")
        << between([](Project& p) { p.environment.rotationDegrees = 10; })
        << QList<bool> {false, false, false, false} << QList<bool> {false, false, false, false} << true;
    QTest::newRow("environment source")
        << between([](Project& p) { p.environment.source = "sky"; })
        << QList<bool> {false, false, false, false} << QList<bool> {false, false, false, false} << true;
    QTest::newRow("IBL quality") << between([](Project& p) { p.environment.quality = IblQuality::High; })
                                 << QList<bool> {false, false, false, false}
                                 << QList<bool> {false, false, false, false} << true;
    QTest::newRow("exposure") << between([](Project& p) { p.view.exposureEV = 2; })
                              << QList<bool> {false, false, false, false}
                              << QList<bool> {false, false, false, false} << false;
    QTest::newRow("current material")
        << DocumentChanges(DocumentChange::CurrentMaterial) << QList<bool> {false, false, false, false}
        << QList<bool> {false, false, false, false} << false;
    QTest::newRow("files changed on disk")
        << DocumentChanges(DocumentChange::MaterialMaps) << QList<bool> {true, true, true, true}
        << QList<bool> {false, false, false, false} << false;
    QTest::newRow("whole project") << DocumentChanges(DocumentChange::WholeProject)
                                   << QList<bool> {true, true, true, true}
                                   << QList<bool> {true, true, true, true} << true;
}

void DocumentChangesTest::questions()
{
    QFETCH(DocumentChanges, changes);
    QFETCH(QList<bool>, materials);
    QFETCH(QList<bool>, lights);
    QFETCH(bool, environment);
    for (qsizetype i = 0; i < materials.size(); ++i)
        QVERIFY2(affectsMaterial(changes, std::size_t(i)) == materials[i],
            qPrintable(QStringLiteral("material %1").arg(i)));
    for (qsizetype i = 0; i < lights.size(); ++i)
        QVERIFY2(affectsLight(changes, std::size_t(i)) == lights[i],
            qPrintable(QStringLiteral("light %1").arg(i)));
    QCOMPARE(affectsEnvironment(changes), environment);
}

void DocumentChangesTest::kindsAloneNameEverything()
{
    // New, Open, recovery: every index, every property.
    const DocumentChanges whole(DocumentChange::WholeProject);
    QVERIFY(!whole.namesMaterials());
    QVERIFY(!whole.namesLights());
    QVERIFY(!whole.namesView());
    QCOMPARE(whole.material(7), MaterialChange::all());
    QCOMPARE(whole.map(0, MapSlot::Normal), MapProperties(MapProperty::All));
    QCOMPARE(whole.light(5), LightProperties(LightProperty::All));
    QCOMPARE(whole.view(), ViewProperties(ViewProperty::All));

    // Files changed on disk: every map of every material, nothing else.
    const DocumentChanges onDisk(DocumentChange::MaterialMaps);
    QCOMPARE(onDisk.map(3, MapSlot::Roughness), MapProperties(MapProperty::All));
    QCOMPARE(onDisk.light(0), LightProperties());
    QCOMPARE(onDisk.view(), ViewProperties());

    // A detailed change answers exactly, and nothing for what it does not name.
    const DocumentChanges detailed = map(1, MapSlot::Normal, MapProperty::Path);
    QVERIFY(detailed.namesMaterials());
    QCOMPARE(detailed.map(1, MapSlot::Normal), MapProperties(MapProperty::Path));
    QCOMPARE(detailed.map(1, MapSlot::BaseColor), MapProperties());
    QCOMPARE(detailed.map(0, MapSlot::Normal), MapProperties());
    QCOMPARE(detailed.light(0), LightProperties());
    QCOMPARE(detailed.view(), ViewProperties());
}

void DocumentChangesTest::combining()
{
    // In-place edits of one list merge index by index (a view drawing once for several edits).
    DocumentChanges both = map(0, MapSlot::Roughness, MapProperty::Factor);
    both |= map(0, MapSlot::Normal, MapProperty::Path);
    both |= map(2, MapSlot::Normal, MapProperty::Channel);
    MaterialChange zero = MaterialChange::ofMap(MapSlot::Roughness, MapProperty::Factor);
    zero |= MaterialChange::ofMap(MapSlot::Normal, MapProperty::Path);
    QCOMPARE(both,
        DocumentChanges::ofMaterialList(
            {}, {{0, zero}, {2, MaterialChange::ofMap(MapSlot::Normal, MapProperty::Channel)}}));
    QCOMPARE(both.kinds(), DocumentChange::MaterialFactors | DocumentChange::MaterialMaps);

    // Two list changes: their indices refer to different lists, so nothing is named any more
    // (never less than what changed).
    DocumentChanges lists = DocumentChanges::ofLightList(inserted({3}));
    lists |= DocumentChanges::ofLightList(removed({0}));
    QVERIFY(!lists.namesLights());
    QCOMPARE(lists.light(1), LightProperties(LightProperty::All));
    // An edit and a list change likewise.
    DocumentChanges mixed = light(0, LightProperty::Color);
    mixed |= DocumentChanges::ofLightList(removed({2}));
    QVERIFY(!mixed.namesLights());
    // Kinds alone absorb detail.
    DocumentChanges absorbed = map(2, MapSlot::Normal, MapProperty::Path);
    absorbed |= DocumentChange::MaterialMaps;
    QVERIFY(!absorbed.namesMaterials());
    QCOMPARE(absorbed, DocumentChanges(DocumentChange::MaterialMaps));
    // Different domains keep each their own detail.
    DocumentChanges domains = map(2, MapSlot::Normal, MapProperty::Path);
    domains |= DocumentChanges::ofLightList(removed({2}));
    domains |= DocumentChanges::ofView(ViewProperty::Msaa);
    QCOMPARE(domains.map(2, MapSlot::Normal), MapProperties(MapProperty::Path));
    QCOMPARE(domains.lightList().removed, std::vector<std::size_t> {2});
    QCOMPARE(domains.view(), ViewProperties(ViewProperty::Msaa));
    // Nothing combined with nothing.
    QCOMPARE(DocumentChanges() | DocumentChanges(), DocumentChanges());
}

void DocumentChangesTest::flagApiStillWorks()
{
    // The docks filter on kinds as they did when a change was a flag set.
    const DocumentChanges changes = map(2, MapSlot::Normal, MapProperty::Path) | DocumentChange::Camera;
    QVERIFY(changes.testFlag(DocumentChange::MaterialMaps));
    QVERIFY(changes & DocumentChange::Camera);
    QVERIFY(!(changes & DocumentChange::Lights));
    QVERIFY(changes & (DocumentChanges(DocumentChange::MaterialFactors) | DocumentChange::MaterialMaps));
    QVERIFY(!(changes & (DocumentChanges(DocumentChange::MaterialFactors) | DocumentChange::View)));
    QVERIFY(DocumentChanges().isEmpty());
    QCOMPARE(
        DocumentChanges(DocumentChange::CurrentMaterial), DocumentChanges(DocumentChange::CurrentMaterial));
    // changesBetween's description of a selection alone equals the flag-style one the Document
    // emits for it.
    Project after = baseProject();
    after.currentMaterial = 1;
    QCOMPARE(changesBetween(baseProject(), after), DocumentChanges(DocumentChange::CurrentMaterial));
}

void DocumentChangesTest::describeWords()
{
    const auto words
        = [](const DocumentChanges& changes) { return QString::fromStdString(describe(changes)); };
    QCOMPARE(words(map(2, MapSlot::Roughness, MapProperty::Path)),
        QStringLiteral("MaterialMaps; materials 2{roughness{path}}"));
    QCOMPARE(
        words(DocumentChanges::ofLightList(inserted({1})) | DocumentChanges::ofView(ViewProperty::Exposure)),
        QStringLiteral("Lights|View; lights inserted[1]; view exposure"));
    QCOMPARE(words(DocumentChanges(DocumentChange::WholeProject)),
        QStringLiteral("WholeProject; materials *; lights *; view *"));
    QCOMPARE(words(DocumentChanges()), QStringLiteral("None"));
}

QTEST_APPLESS_MAIN(DocumentChangesTest)
#include "DocumentChangesTest.moc"
