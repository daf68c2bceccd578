// core/material/MaterialList: adding, duplicating and deleting a project's materials keeps every reference
// to the others (parts, the current material, A/B's B) on the same material. One row per edit
// and position; the last material and the limit are refused.

#include <QtTest/QTest>

#include "core/material/MaterialList.h"

using namespace facet;

namespace {

// a + b, appended (GCC 12's -Wrestrict misreads operator+ on strings at -O3).
std::string joined(std::string a, const std::string& b)
{
    a.append(b);
    return a;
}

// Materials A, B, C, D; parts showing D, C, B, A, B; current C; B (A/B) showing D.
Project fourMaterials()
{
    Project project;
    project.materials.clear();
    for (const char* name : {"A", "B", "C", "D"}) {
        Material material;
        material.name = name;
        project.materials.push_back(material);
    }
    project.parts = {{"p0", 3, true}, {"p1", 2, true}, {"p2", 1, false}, {"p3", 0, true}, {"p4", 1, true}};
    project.currentMaterial = 2;
    project.compare.ab.source = BSource::Material;
    project.compare.ab.material = 3;
    return project;
}

// The material names each part shows, then the current one's, then B's.
std::vector<std::string> shown(const Project& project)
{
    std::vector<std::string> names;
    for (std::size_t p = 0; p < project.parts.size(); ++p)
        names.push_back(project.materials[std::size_t(project.materialOfPart(p))].name);
    names.push_back(joined("current ", project.material().name));
    names.push_back(joined("B ", project.compare.ab.materialB(project).name));
    return names;
}

using Names = std::vector<std::string>;

} // namespace

class MaterialListTest : public QObject {
    Q_OBJECT

private Q_SLOTS:
    // Copy Map / Paste Map between every pair of kinds: what goes, what the target keeps, and a
    // result Material::validate accepts.
    void pasteAMap_data()
    {
        QTest::addColumn<int>("from");
        QTest::addColumn<int>("to");
        QTest::addColumn<bool>("factorCopied");
        QTest::addColumn<int>("channel"); // MapChannel the result reads
        QTest::addColumn<bool>("invert");
        QTest::addColumn<bool>("flipGreen");
        QTest::addColumn<int>("colorSpace"); // ColorEncoding
        const auto row = [](const char* name, MapSlot from, MapSlot to, bool factor, MapChannel channel,
                             bool invert, bool flip, ColorEncoding space) {
            QTest::newRow(name) << int(from) << int(to) << factor << int(channel) << invert << flip
                                << int(space);
        };
        // The copied maps (copiedMap below): roughness reads G inverted; normal flips green; base
        // colour reads rgb as linear (set by hand); emissive rgb sRGB.
        row("roughness -> metallic: all of it", MapSlot::Roughness, MapSlot::Metallic, true, MapChannel::G,
            true, false, ColorEncoding::Linear);
        row("roughness -> base colour", MapSlot::Roughness, MapSlot::BaseColor, false, MapChannel::G, false,
            false, ColorEncoding::SRGB);
        row("roughness -> normal", MapSlot::Roughness, MapSlot::Normal, false, MapChannel::Rgb, false, false,
            ColorEncoding::Linear);
        row("roughness -> emissive", MapSlot::Roughness, MapSlot::Emissive, false, MapChannel::Rgb, false,
            false, ColorEncoding::SRGB);
        row("normal -> normal: the flip too", MapSlot::Normal, MapSlot::Normal, true, MapChannel::Rgb, false,
            true, ColorEncoding::Linear);
        row("normal -> occlusion", MapSlot::Normal, MapSlot::Occlusion, false, MapChannel::R, false, false,
            ColorEncoding::Linear);
        row("base colour -> emissive: one kind", MapSlot::BaseColor, MapSlot::Emissive, true, MapChannel::Rgb,
            false, false, ColorEncoding::Linear);
        row("base colour -> roughness", MapSlot::BaseColor, MapSlot::Roughness, false, MapChannel::R, false,
            false, ColorEncoding::Linear);
        row("emissive -> base colour", MapSlot::Emissive, MapSlot::BaseColor, true, MapChannel::Rgb, false,
            false, ColorEncoding::SRGB);
    }

    void pasteAMap()
    {
        QFETCH(int, from);
        QFETCH(int, to);
        QFETCH(bool, factorCopied);
        QFETCH(int, channel);
        QFETCH(bool, invert);
        QFETCH(bool, flipGreen);
        QFETCH(int, colorSpace);
        Material source;
        MaterialMap& roughness = source.map(MapSlot::Roughness);
        roughness.path = "/maps/orm.png";
        roughness.factor = glm::dvec4(0.3);
        roughness.channel = MapChannel::G;
        roughness.invert = true;
        source.map(MapSlot::Normal).path = "/maps/normal.png";
        source.map(MapSlot::Normal).factor = glm::dvec4(2.5);
        source.map(MapSlot::Normal).flipGreen = true;
        source.map(MapSlot::BaseColor).path = "/maps/albedo.exr";
        source.map(MapSlot::BaseColor).colorSpace = ColorEncoding::Linear;
        source.map(MapSlot::BaseColor).factor = glm::dvec4(0.9, 0.5, 0.2, 1.0);
        source.map(MapSlot::Emissive).path = "/maps/glow.png";
        source.map(MapSlot::Emissive).factor = glm::dvec4(1.0, 0.8, 0.1, 1.0);
        for (MapSlot slot : kAllMapSlots) {
            source.map(slot).uv.rotationDegrees = 30.0;
            source.map(slot).texCoord = 1;
        }
        const MapSlot fromSlot = MapSlot(from);
        const MapSlot toSlot = MapSlot(to);
        Material target; // the defaults
        const MaterialMap& copied = source.map(fromSlot);
        const MaterialMap pasted = pastedMap(fromSlot, copied, toSlot, target.map(toSlot));
        QCOMPARE(pasted.path, copied.path);
        QCOMPARE(pasted.uv.rotationDegrees, 30.0);
        QCOMPARE(pasted.texCoord, 1);
        QCOMPARE(pasted.factor == copied.factor, factorCopied);
        if (!factorCopied)
            QVERIFY(pasted.factor == target.map(toSlot).factor);
        QCOMPARE(int(pasted.channel), channel);
        QCOMPARE(pasted.invert, invert);
        QCOMPARE(pasted.flipGreen, flipGreen);
        QCOMPARE(int(pasted.colorSpace), colorSpace);
        target.map(toSlot) = pasted;
        std::string problem;
        QVERIFY2(target.validate(&problem), problem.c_str());
        // Paste Value: only within one kind.
        const std::optional<glm::dvec4> factor = pastedFactor(fromSlot, copied, toSlot);
        QCOMPARE(factor.has_value(), factorCopied);
    }

    void uniqueNames()
    {
        const Project project = fourMaterials();
        QCOMPARE(uniqueMaterialName(project, "E"), std::string("E"));
        QCOMPARE(uniqueMaterialName(project, "A"), std::string("A 2"));
        Project more = project;
        more.materials[1].name = "A 2";
        QCOMPARE(uniqueMaterialName(more, "A"), std::string("A 3"));
        QCOMPARE(uniqueMaterialName(project, ""), std::string("Material"));
    }

    void insert_data()
    {
        QTest::addColumn<int>("index");
        QTest::addColumn<int>("current");
        QTest::newRow("first") << 0 << 0;
        QTest::newRow("middle") << 2 << 2;
        QTest::newRow("last") << 4 << 4;
        QTest::newRow("past the end: last") << 9 << 4;
        QTest::newRow("before the start: first") << -3 << 0;
    }
    void insert()
    {
        QFETCH(int, index);
        QFETCH(int, current);
        const Project before = fourMaterials();
        const Material added = before.materials.front(); // "A", taken: made unique
        std::string problem;
        const std::optional<Project> after = withMaterialInserted(before, index, added, &problem);
        QVERIFY2(after, problem.c_str());
        QCOMPARE(after->materials.size(), std::size_t(5));
        QCOMPARE(after->currentMaterial, current);
        QCOMPARE(after->material().name, std::string("A 2"));
        // Every part, and B, shows what it showed.
        Names expected = shown(before);
        expected[5] = "current A 2";
        QCOMPARE(shown(*after), expected);
        QCOMPARE(after->parts[2].visible, false);
        std::string invalid;
        QVERIFY2(after->validate(&invalid), invalid.c_str());
    }

    void duplicate_data()
    {
        QTest::addColumn<int>("index");
        QTest::newRow("first") << 0;
        QTest::newRow("current") << 2;
        QTest::newRow("last") << 3;
    }
    void duplicate()
    {
        QFETCH(int, index);
        Project before = fourMaterials();
        before.materials[std::size_t(index)].setFactor(MapSlot::Roughness, 0.37);
        const std::optional<Project> after = withMaterialDuplicated(before, index);
        QVERIFY(after);
        QCOMPARE(after->currentMaterial, index + 1);
        const Material& copy = after->material();
        QCOMPARE(copy.name, joined(before.materials[std::size_t(index)].name, " copy"));
        QCOMPARE(copy.roughness(), 0.37);
        Material renamed = copy;
        renamed.name = before.materials[std::size_t(index)].name;
        QVERIFY(renamed == before.materials[std::size_t(index)]); // the same in all but its name
        Names expected = shown(before);
        expected[5] = joined("current ", copy.name);
        QCOMPARE(shown(*after), expected);
        // Twice: "copy 2".
        const std::optional<Project> again = withMaterialDuplicated(*after, index);
        QVERIFY(again);
        QCOMPARE(again->material().name, joined(before.materials[std::size_t(index)].name, " copy 2"));
    }

    void remove_data()
    {
        QTest::addColumn<int>("index");
        QTest::addColumn<Names>("expected"); // parts p0..p4, current, B
        // Before: D C B A B, current C, B shows D.
        QTest::newRow("first (A): its part shows the new first, B")
            << 0 << Names {"D", "C", "B", "B", "B", "current C", "B D"};
        QTest::newRow("B: its parts show A") << 1 << Names {"D", "C", "A", "A", "A", "current C", "B D"};
        QTest::newRow("the current (C): B becomes current")
            << 2 << Names {"D", "B", "B", "A", "B", "current B", "B D"};
        QTest::newRow("D, which B shows: B keeps it as a snapshot")
            << 3 << Names {"C", "C", "B", "A", "B", "current C", "B D"};
    }
    void remove()
    {
        QFETCH(int, index);
        QFETCH(Names, expected);
        const Project before = fourMaterials();
        std::string problem;
        const std::optional<Project> after = withMaterialRemoved(before, index, &problem);
        QVERIFY2(after, problem.c_str());
        QCOMPARE(after->materials.size(), std::size_t(3));
        QCOMPARE(shown(*after), expected);
        QCOMPARE(after->compare.ab.source, index == 3 ? BSource::Snapshot : BSource::Material);
        std::string invalid;
        QVERIFY2(after->validate(&invalid), invalid.c_str());
    }

    void refusals()
    {
        std::string problem;
        Project one;
        one.materials = {Material {}};
        one.materials[0].name = "Only";
        QVERIFY(!withMaterialRemoved(one, 0, &problem));
        QCOMPARE(problem, std::string("a project has at least one material: 'Only' stays"));
        QVERIFY(!withMaterialRemoved(fourMaterials(), 4, &problem));
        QCOMPARE(problem, std::string("there is no material 4"));
        QVERIFY(!withMaterialRemoved(fourMaterials(), -1, &problem));
        QVERIFY(!withMaterialDuplicated(fourMaterials(), 7, &problem));
        Project full = fourMaterials();
        full.materials.resize(std::size_t(Project::kMaxMaterials));
        QVERIFY(!withMaterialInserted(full, 0, Material {}, &problem));
        QCOMPARE(problem, std::string("a project holds at most 4096 materials"));
    }
};

QTEST_GUILESS_MAIN(MaterialListTest)
#include "MaterialListTest.moc"
