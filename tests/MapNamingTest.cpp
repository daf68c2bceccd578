// Texture file names to material maps (core/material/MapNaming.h): one row per naming convention and slot
// (which channel the slot reads, inverted or not, the normal map's green convention), names that
// must NOT match, a whole folder's assignment (which file wins a slot), and replacing a texture
// set (slots the new set does not fill are cleared back to sensible values). Needs nothing.

#include "core/material/MapNaming.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>
#include <QtTest/QTest>

using namespace facet;

Q_DECLARE_METATYPE(facet::MapSlot)
Q_DECLARE_METATYPE(facet::MapChannel)

namespace {

constexpr int kUnknown = -1; // flipGreen column: the name does not say

QString describe(const MapRead& read)
{
    return QStringLiteral("slot %1 channel %2 invert %3 flip %4")
        .arg(QString::fromLatin1(toString(read.slot)), QString::fromLatin1(toString(read.channel)))
        .arg(read.invert)
        .arg(read.flipGreen ? QString::number(*read.flipGreen) : QStringLiteral("?"));
}

QStringList names(std::initializer_list<const char*> list)
{
    QStringList out;
    for (const char* name : list)
        out.append(QString::fromUtf8(name));
    return out;
}

bool touch(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::WriteOnly);
}

} // namespace

class MapNamingTest : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void channelForSlot_data();
    void channelForSlot();
    void namesThatSayNothing_data();
    void namesThatSayNothing();
    void packedNamesFeedOnlyTheirSlots();
    void folderPicksOneFilePerSlot_data();
    void folderPicksOneFilePerSlot();
    void assignedMapsTakeTheirRead();
    void lobeMapsTurnTheirLobeOn_data();
    void lobeMapsTurnTheirLobeOn();
    void textureSetReplacesTheWholeSet();
};

void MapNamingTest::channelForSlot_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<MapSlot>("slot");
    QTest::addColumn<MapChannel>("channel");
    QTest::addColumn<bool>("invert");
    QTest::addColumn<int>("flipGreen"); // 0, 1 or kUnknown
    QTest::addColumn<bool>("named"); // the name's convention feeds this slot (else the default read)
    QTest::addColumn<QString>("convention");

    using S = MapSlot;
    using C = MapChannel;
    const QString none;
    // Single maps, as Substance, Poly Haven, ambientCG and Poliigon name them.
    QTest::newRow("basecolor") << "wood_basecolor.png" << S::BaseColor << C::Rgb << false << kUnknown << true
                               << none;
    QTest::newRow("base_color") << "wood_base_color.png" << S::BaseColor << C::Rgb << false << kUnknown
                                << true << none;
    QTest::newRow("albedo") << "Wood-Albedo.jpg" << S::BaseColor << C::Rgb << false << kUnknown << true
                            << none;
    QTest::newRow("diffuse") << "wood_diffuse.tga" << S::BaseColor << C::Rgb << false << kUnknown << true
                             << none;
    QTest::newRow("Poly Haven diff 4k")
        << "rock_wall_diff_4k.jpg" << S::BaseColor << C::Rgb << false << kUnknown << true << none;
    QTest::newRow("ambientCG Color") << "Bricks059_1K-JPG_Color.jpg" << S::BaseColor << C::Rgb << false
                                     << kUnknown << true << none;
    QTest::newRow("Poliigon COL") << "WoodFlooring044_COL_4K.jpg" << S::BaseColor << C::Rgb << false
                                  << kUnknown << true << none;
    QTest::newRow("emissive") << "lamp_emissive.png" << S::Emissive << C::Rgb << false << kUnknown << true << none;
    QTest::newRow("Poly Haven emission 4k")
        << "lamp_emission_4k.jpg" << S::Emissive << C::Rgb << false << kUnknown << true << none;
    QTest::newRow("Unreal E") << "T_Crate_E.png" << S::Emissive << C::Rgb << false << kUnknown << true << none;
    QTest::newRow("normal") << "wood_normal.png" << S::Normal << C::Rgb << false << kUnknown << true << none;
    QTest::newRow("nrm") << "wood_NRM.png" << S::Normal << C::Rgb << false << kUnknown << true << none;
    QTest::newRow("normal_gl") << "wood_normal_gl.png" << S::Normal << C::Rgb << false << 0 << true << none;
    QTest::newRow("normal_dx") << "wood_normal_dx.png" << S::Normal << C::Rgb << false << 1 << true << none;
    QTest::newRow("Poly Haven nor_gl")
        << "rock_wall_nor_gl_4k.exr" << S::Normal << C::Rgb << false << 0 << true << none;
    QTest::newRow("Poly Haven nor_dx")
        << "rock_wall_nor_dx_4k.exr" << S::Normal << C::Rgb << false << 1 << true << none;
    QTest::newRow("ambientCG NormalGL")
        << "Bricks059_1K-JPG_NormalGL.jpg" << S::Normal << C::Rgb << false << 0 << true << none;
    QTest::newRow("ambientCG NormalDX")
        << "Bricks059_1K-JPG_NormalDX.jpg" << S::Normal << C::Rgb << false << 1 << true << none;
    QTest::newRow("metallic") << "wood_metallic.png" << S::Metallic << C::R << false << kUnknown << true
                              << none;
    QTest::newRow("metalness") << "wood_metalness.png" << S::Metallic << C::R << false << kUnknown << true
                               << none;
    QTest::newRow("Poly Haven metal")
        << "rock_metal_2k.exr" << S::Metallic << C::R << false << kUnknown << true << none;
    QTest::newRow("roughness") << "wood_roughness.png" << S::Roughness << C::R << false << kUnknown << true
                               << none;
    QTest::newRow("rough") << "wood_rough.exr" << S::Roughness << C::R << false << kUnknown << true << none;
    QTest::newRow("gloss: inverted") << "Wood_GLOSS_4K.jpg" << S::Roughness << C::R << true << kUnknown
                                     << true << none;
    QTest::newRow("smoothness: inverted")
        << "wood_smoothness.png" << S::Roughness << C::R << true << kUnknown << true << none;
    QTest::newRow("ao") << "wood_ao.png" << S::Occlusion << C::R << false << kUnknown << true << none;
    QTest::newRow("occlusion, space")
        << "wood occlusion.png" << S::Occlusion << C::R << false << kUnknown << true << none;
    QTest::newRow("ambientCG AmbientOcclusion") << "Bricks059_1K-JPG_AmbientOcclusion.jpg" << S::Occlusion
                                                << C::R << false << kUnknown << true << none;

    // ORM / ARM: R occlusion, G roughness, B metallic; the other slots read their default.
    const QString orm = QStringLiteral("ORM");
    QTest::newRow("orm occlusion") << "metal_orm.png" << S::Occlusion << C::R << false << kUnknown << true
                                   << orm;
    QTest::newRow("orm roughness") << "metal_orm.png" << S::Roughness << C::G << false << kUnknown << true
                                   << orm;
    QTest::newRow("orm metallic") << "metal_orm.png" << S::Metallic << C::B << false << kUnknown << true
                                  << orm;
    QTest::newRow("orm base colour: default")
        << "metal_orm.png" << S::BaseColor << C::Rgb << false << kUnknown << false << orm;
    QTest::newRow("orm normal: default")
        << "metal_orm.png" << S::Normal << C::Rgb << false << kUnknown << false << orm;
    QTest::newRow("Poly Haven arm occlusion")
        << "rock_wall_arm_4k.jpg" << S::Occlusion << C::R << false << kUnknown << true << orm;
    QTest::newRow("Poly Haven arm roughness")
        << "rock_wall_arm_4k.jpg" << S::Roughness << C::G << false << kUnknown << true << orm;
    QTest::newRow("Poly Haven arm metallic")
        << "rock_wall_arm_4k.jpg" << S::Metallic << C::B << false << kUnknown << true << orm;
    QTest::newRow("occlusionRoughnessMetallic") << "WaterBottle_occlusionRoughnessMetallic.png" << S::Metallic
                                                << C::B << false << kUnknown << true << orm;
    QTest::newRow("OcclusionRoughMetal") << "FlightHelmet_Materials_LensesMat_OcclusionRoughMetal.png"
                                         << S::Occlusion << C::R << false << kUnknown << true << orm;

    // glTF's metallicRoughness texture: G roughness, B metallic; occlusion is not in it.
    const QString gltf = QStringLiteral("glTF metallic-roughness");
    QTest::newRow("metalRoughness roughness")
        << "Default_metalRoughness.jpg" << S::Roughness << C::G << false << kUnknown << true << gltf;
    QTest::newRow("metalRoughness metallic")
        << "Default_metalRoughness.jpg" << S::Metallic << C::B << false << kUnknown << true << gltf;
    QTest::newRow("metalRoughness occlusion: default")
        << "Default_metalRoughness.jpg" << S::Occlusion << C::R << false << kUnknown << false << gltf;
    QTest::newRow("MetallicRoughness roughness")
        << "SciFiHelmet_MetallicRoughness.png" << S::Roughness << C::G << false << kUnknown << true << gltf;
    QTest::newRow("metallicRoughness metallic")
        << "metallicRoughness_2.png" << S::Metallic << C::B << false << kUnknown << true << gltf;
    QTest::newRow("mr roughness") << "helmet_mr.png" << S::Roughness << C::G << false << kUnknown << true
                                  << gltf;
    QTest::newRow("mr metallic") << "helmet_mr.png" << S::Metallic << C::B << false << kUnknown << true
                                 << gltf;

    // Unity HDRP mask map: R metallic, G occlusion, B detail mask, A smoothness (roughness inverted).
    const QString mask = QStringLiteral("Unity mask map");
    QTest::newRow("MaskMap metallic")
        << "Rock_MaskMap.png" << S::Metallic << C::R << false << kUnknown << true << mask;
    QTest::newRow("MaskMap occlusion")
        << "Rock_MaskMap.png" << S::Occlusion << C::G << false << kUnknown << true << mask;
    QTest::newRow("MaskMap roughness")
        << "Rock_MaskMap.png" << S::Roughness << C::A << true << kUnknown << true << mask;
    QTest::newRow("mask_map roughness")
        << "rock_mask_map.tga" << S::Roughness << C::A << true << kUnknown << true << mask;
    // Unity Standard / URP metallic map: R metallic, A smoothness.
    const QString metallicSmoothness = QStringLiteral("Unity metallic-smoothness");
    QTest::newRow("MetallicSmoothness metallic") << "Crate_MetallicSmoothness.png" << S::Metallic << C::R
                                                 << false << kUnknown << true << metallicSmoothness;
    QTest::newRow("MetallicSmoothness roughness") << "Crate_MetallicSmoothness.png" << S::Roughness << C::A
                                                  << true << kUnknown << true << metallicSmoothness;
    QTest::newRow("MetallicSmoothness occlusion: default")
        << "Crate_MetallicSmoothness.png" << S::Occlusion << C::R << false << kUnknown << false
        << metallicSmoothness;

    // KHR_materials_clearcoat's textures: glTF's own names, Substance-style words, and Facet's
    // Unreal export (T_*_CC: R strength, G roughness). A coat normal is not the base's normal.
    QTest::newRow("clearcoat") << "car_clearcoat.png" << S::Clearcoat << C::R << false << kUnknown << true
                               << none;
    QTest::newRow("coat") << "car_coat.png" << S::Clearcoat << C::R << false << kUnknown << true << none;
    QTest::newRow("clear_coat") << "car_clear_coat.png" << S::Clearcoat << C::R << false << kUnknown << true
                                << none;
    QTest::newRow("clearcoatRoughness")
        << "Car_clearcoatRoughness.png" << S::ClearcoatRoughness << C::R << false << kUnknown << true << none;
    QTest::newRow("clearcoat_roughness 2k") << "car_clearcoat_roughness_2k.png" << S::ClearcoatRoughness
                                            << C::R << false << kUnknown << true << none;
    QTest::newRow("coat_roughness") << "car_coat_roughness.png" << S::ClearcoatRoughness << C::R << false
                                    << kUnknown << true << none;
    QTest::newRow("clearcoatNormal") << "Car_clearcoatNormal.png" << S::ClearcoatNormal << C::Rgb << false
                                     << kUnknown << true << none;
    QTest::newRow("coat_normal") << "car_coat_normal.png" << S::ClearcoatNormal << C::Rgb << false << kUnknown
                                 << true << none;
    QTest::newRow("coat_normal is not the base normal")
        << "car_coat_normal.png" << S::Normal << C::Rgb << false << kUnknown << false << none;
    QTest::newRow("clearcoat_roughness is not the base roughness")
        << "car_clearcoat_roughness.png" << S::Roughness << C::R << false << kUnknown << false << none;
    // KHR_materials_sheen's textures: glTF's names and Substance-style words; a sheen colour is
    // not the base colour, a sheen roughness not the base's roughness.
    QTest::newRow("sheen") << "sofa_sheen.png" << S::SheenColor << C::Rgb << false << kUnknown << true
                           << none;
    QTest::newRow("sheenColor") << "Sofa_sheenColor.png" << S::SheenColor << C::Rgb << false << kUnknown
                                << true << none;
    QTest::newRow("sheen_color 4k") << "sofa_sheen_color_4k.png" << S::SheenColor << C::Rgb << false
                                    << kUnknown << true << none;
    QTest::newRow("sheenRoughness") << "Sofa_sheenRoughness.png" << S::SheenRoughness << C::R << false
                                    << kUnknown << true << none;
    QTest::newRow("sheen_roughness") << "sofa_sheen_roughness.png" << S::SheenRoughness << C::R << false
                                     << kUnknown << true << none;
    QTest::newRow("sheen_color is not the base colour")
        << "sofa_sheen_color.png" << S::BaseColor << C::Rgb << false << kUnknown << false << none;
    QTest::newRow("sheen_roughness is not the base roughness")
        << "sofa_sheen_roughness.png" << S::Roughness << C::R << false << kUnknown << false << none;
    // KHR_materials_specular's colour: glTF's name and words; a bare "specular" (a specular-
    // glossiness set's F0 map, metals' colour included) is neither it nor the base colour.
    QTest::newRow("specularColor") << "Lens_specularColor.png" << S::SpecularColor << C::Rgb << false
                                   << kUnknown << true << none;
    QTest::newRow("specular_color 2k")
        << "lens_specular_color_2k.png" << S::SpecularColor << C::Rgb << false << kUnknown << true << none;
    QTest::newRow("specular is not the specular colour")
        << "crate_specular.png" << S::SpecularColor << C::Rgb << false << kUnknown << false << none;
    QTest::newRow("specular is not the base colour")
        << "crate_specular.png" << S::BaseColor << C::Rgb << false << kUnknown << false << none;
    const QString clearCoat = QStringLiteral("clear coat");
    QTest::newRow("Unreal CC strength")
        << "T_Car_CC.png" << S::Clearcoat << C::R << false << kUnknown << true << clearCoat;
    QTest::newRow("Unreal CC roughness")
        << "T_Car_CC.png" << S::ClearcoatRoughness << C::G << false << kUnknown << true << clearCoat;

    // Unreal: T_<name>_<code>; normal maps are DirectX.
    QTest::newRow("Unreal BC") << "T_Crate_BC.png" << S::BaseColor << C::Rgb << false << kUnknown << true
                               << none;
    QTest::newRow("Unreal D") << "T_Crate_D.png" << S::BaseColor << C::Rgb << false << kUnknown << true
                              << none;
    QTest::newRow("Unreal N: DirectX")
        << "T_Crate_N.png" << S::Normal << C::Rgb << false << 1 << true << none;
    QTest::newRow("Unreal R") << "T_Crate_R.png" << S::Roughness << C::R << false << kUnknown << true << none;
    QTest::newRow("Unreal M") << "T_Crate_M.png" << S::Metallic << C::R << false << kUnknown << true << none;
    QTest::newRow("Unreal MT") << "T_Crate_Worn_MT.tga" << S::Metallic << C::R << false << kUnknown << true
                               << none;
    QTest::newRow("Unreal AO") << "T_Crate_AO.png" << S::Occlusion << C::R << false << kUnknown << true
                               << none;
    QTest::newRow("Unreal O") << "T_Crate_O.png" << S::Occlusion << C::R << false << kUnknown << true << none;
    QTest::newRow("Unreal ORM roughness")
        << "T_Crate_ORM.png" << S::Roughness << C::G << false << kUnknown << true << orm;
    const QString mra = QStringLiteral("MRA");
    QTest::newRow("Unreal MRA metallic")
        << "T_Crate_MRA.png" << S::Metallic << C::R << false << kUnknown << true << mra;
    QTest::newRow("Unreal MRA roughness")
        << "T_Crate_MRA.png" << S::Roughness << C::G << false << kUnknown << true << mra;
    QTest::newRow("Unreal MRA occlusion")
        << "T_Crate_MRA.png" << S::Occlusion << C::B << false << kUnknown << true << mra;
    const QString rma = QStringLiteral("RMA");
    QTest::newRow("Unreal RMA roughness")
        << "T_Temple_RMA.png" << S::Roughness << C::R << false << kUnknown << true << rma;
    QTest::newRow("Unreal RMA metallic")
        << "T_Temple_RMA.png" << S::Metallic << C::G << false << kUnknown << true << rma;
    QTest::newRow("Unreal RMA occlusion")
        << "T_Temple_RMA.png" << S::Occlusion << C::B << false << kUnknown << true << rma;

    // A file chosen for a slot its name does not feed reads the default: R for a scalar slot (a
    // greyscale file has the same value in every channel), RGB for base colour and normal.
    QTest::newRow("roughness file on metallic")
        << "wood_roughness.png" << S::Metallic << C::R << false << kUnknown << false << none;
    QTest::newRow("unnamed file on roughness")
        << "scan.png" << S::Roughness << C::R << false << kUnknown << false << none;
    QTest::newRow("unnamed file on normal")
        << "scan.png" << S::Normal << C::Rgb << false << kUnknown << false << none;
}

void MapNamingTest::channelForSlot()
{
    QFETCH(QString, file);
    QFETCH(MapSlot, slot);
    QFETCH(MapChannel, channel);
    QFETCH(bool, invert);
    QFETCH(int, flipGreen);
    QFETCH(bool, named);
    QFETCH(QString, convention);

    const MapRead expected {
        slot, channel, invert, flipGreen == kUnknown ? std::nullopt : std::optional<bool>(flipGreen == 1)};
    const MapRead read = mapReadFor(slot, QStringLiteral("/textures/") + file);
    QVERIFY2(
        read == expected, qPrintable(describe(read) + QStringLiteral(" expected ") + describe(expected)));

    const TextureNaming naming = textureNaming(file);
    QCOMPARE(naming.convention, convention);
    const bool feedsSlot = std::any_of(
        naming.reads.begin(), naming.reads.end(), [&](const MapRead& r) { return r.slot == slot; });
    QCOMPARE(feedsSlot, named);
}

void MapNamingTest::namesThatSayNothing_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("no suffix") << "wood.png";
    QTest::newRow("suffix inside a word") << "woodao.png";
    QTest::newRow("arm inside a word") << "farm.png";
    QTest::newRow("arm at the start of a word") << "armor.png";
    QTest::newRow("mr at the start") << "mr_smith_portrait.png";
    QTest::newRow("resolution only") << "wood_4k.png";
    QTest::newRow("plural") << "normals.png";
    QTest::newRow("map words not last") << "normal_roughness_notes.txt";
    QTest::newRow("roughness not last") << "roughness_map_preview.jpg";
    QTest::newRow("Unreal code without T_") << "rock_d.png";
    QTest::newRow("Unreal N without T_") << "photo_n.png";
    QTest::newRow("T_ with no name") << "T_N.png";
    QTest::newRow("T_ without code") << "T_Rock.png";
    QTest::newRow("height (no slot)") << "rock_height.png";
    QTest::newRow("displacement (no slot)") << "rock_disp_4k.png";
    QTest::newRow("mask alone is not a mask map") << "rock_mask.png";
}

void MapNamingTest::namesThatSayNothing()
{
    QFETCH(QString, file);
    const TextureNaming naming = textureNaming(QStringLiteral("/textures/") + file);
    QVERIFY2(
        !naming.recognised(), qPrintable(naming.reads.empty() ? QString() : describe(naming.reads.front())));
    QVERIFY(naming.convention.isEmpty());
    for (MapSlot slot : kAllMapSlots) {
        const MapRead read = mapReadFor(slot, file);
        QCOMPARE(read.channel, isScalarSlot(slot) ? MapChannel::R : MapChannel::Rgb);
        QVERIFY(!read.invert);
        QVERIFY(!read.flipGreen.has_value());
    }
}

void MapNamingTest::packedNamesFeedOnlyTheirSlots()
{
    // "armor_basecolor" is a base colour, not an ARM texture; "T_Crate_ORM" is ORM, not Unreal's "M".
    const TextureNaming armor = textureNaming(QStringLiteral("armor_basecolor.png"));
    QCOMPARE(armor.reads.size(), std::size_t(1));
    QCOMPARE(armor.reads[0].slot, MapSlot::BaseColor);
    QVERIFY(armor.convention.isEmpty());
    const TextureNaming orm = textureNaming(QStringLiteral("T_Crate_ORM.png"));
    QCOMPARE(orm.reads.size(), std::size_t(3));
    QCOMPARE(orm.convention, QStringLiteral("ORM"));
    // "metallic_smoothness" is Unity's packed map, not a smoothness map.
    QCOMPARE(textureNaming(QStringLiteral("crate_metallic_smoothness.png")).reads.size(), std::size_t(2));
}

void MapNamingTest::folderPicksOneFilePerSlot_data()
{
    QTest::addColumn<QStringList>("files");
    QTest::addColumn<QStringList>("expected"); // "<slot>=<file>:<channel>[!]" (! inverted, ^ flip green)
    QTest::addColumn<QStringList>("unmatched");
    QTest::addColumn<QStringList>("notImages");

    QTest::newRow("separate files") << names({"wood_basecolor.png", "wood_normal.png", "wood_roughness.png",
        "wood_ao.png", "wood_metallic.png", "readme.txt"})
                                    << names({"baseColor=wood_basecolor.png:rgb",
                                           "normal=wood_normal.png:rgb", "metallic=wood_metallic.png:r",
                                           "roughness=wood_roughness.png:r", "occlusion=wood_ao.png:r"})
                                    << names({}) << names({"readme.txt"});
    QTest::newRow("ORM and a separate roughness: the separate file wins")
        << names({"metal_orm.png", "metal_roughness.png"})
        << names({"metallic=metal_orm.png:b", "roughness=metal_roughness.png:r", "occlusion=metal_orm.png:r"})
        << names({}) << names({});
    QTest::newRow("Poly Haven: OpenGL normal over DirectX, rough and ao over the ARM")
        << names({"rock_diff_4k.jpg", "rock_nor_dx_4k.exr", "rock_nor_gl_4k.exr", "rock_rough_4k.exr",
               "rock_arm_4k.jpg", "rock_ao_4k.jpg", "rock_disp_4k.png"})
        << names({"baseColor=rock_diff_4k.jpg:rgb", "normal=rock_nor_gl_4k.exr:rgb",
               "metallic=rock_arm_4k.jpg:b", "roughness=rock_rough_4k.exr:r", "occlusion=rock_ao_4k.jpg:r"})
        << names({"rock_disp_4k.png", "rock_nor_dx_4k.exr"}) << names({});
    QTest::newRow("Unity HDRP set") << names({"Rock_BaseColor.png", "Rock_Normal.png", "Rock_MaskMap.png"})
                                    << names({"baseColor=Rock_BaseColor.png:rgb",
                                           "normal=Rock_Normal.png:rgb", "metallic=Rock_MaskMap.png:r",
                                           "roughness=Rock_MaskMap.png:a!", "occlusion=Rock_MaskMap.png:g"})
                                    << names({}) << names({});
    QTest::newRow("Unreal set: DirectX normal, MRA")
        << names({"T_Crate_BC.png", "T_Crate_N.png", "T_Crate_MRA.png"})
        << names({"baseColor=T_Crate_BC.png:rgb", "normal=T_Crate_N.png:rgb^", "metallic=T_Crate_MRA.png:r",
               "roughness=T_Crate_MRA.png:g", "occlusion=T_Crate_MRA.png:b"})
        << names({}) << names({});
    QTest::newRow("two packed files: the first in name order, the other unused")
        << names({"b_orm.png", "a_MaskMap.png"})
        << names({"metallic=a_MaskMap.png:r", "roughness=a_MaskMap.png:a!", "occlusion=a_MaskMap.png:g"})
        << names({"b_orm.png"}) << names({});
    QTest::newRow("nothing by name") << names({"scan.png", "notes.txt"}) << names({}) << names({"scan.png"})
                                     << names({"notes.txt"});
}

void MapNamingTest::folderPicksOneFilePerSlot()
{
    QFETCH(QStringList, files);
    QFETCH(QStringList, expected);
    QFETCH(QStringList, unmatched);
    QFETCH(QStringList, notImages);
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    for (const QString& file : files)
        QVERIFY(touch(dir.filePath(file)));

    const MapNamingResult result = assignMapsByName({dir.path()});
    QStringList got;
    for (const MapAssignment& a : result.assignments) {
        QString entry = QStringLiteral("%1=%2:%3")
                            .arg(QString::fromLatin1(toString(a.slot)), QFileInfo(a.path).fileName(),
                                QString::fromLatin1(toString(a.channel)));
        if (a.invert)
            entry += u'!';
        if (a.flipGreen)
            entry += u'^';
        got.append(entry);
    }
    QCOMPARE(got, expected);
    const auto names = [](const QStringList& paths) {
        QStringList out;
        for (const QString& path : paths)
            out.append(QFileInfo(path).fileName());
        out.sort();
        return out;
    };
    QCOMPARE(names(result.unmatched), unmatched);
    QCOMPARE(names(result.notImages), notImages);
}

void MapNamingTest::assignedMapsTakeTheirRead()
{
    // A roughness map that was a Unity smoothness channel, replaced by a plain roughness file: the
    // invert goes with the old file; the DirectX flip of a normal likewise.
    Material material;
    MaterialMap& smoothness = material.map(MapSlot::Roughness);
    smoothness.path = "/old/a_MaskMap.png";
    smoothness.channel = MapChannel::A;
    smoothness.invert = true;
    material.map(MapSlot::Normal).path = "/old/T_a_N.png";
    material.map(MapSlot::Normal).flipGreen = true;
    material.setFactor(MapSlot::Metallic, 0.25);
    const MapNamingResult result
        = assignMapsByName({QStringLiteral("/new/b_roughness.png"), QStringLiteral("/new/b_normal_gl.png")});
    const Material after = withAssignedMaps(material, result.assignments);
    const MaterialMap& roughness = after.map(MapSlot::Roughness);
    QCOMPARE(roughness.path, std::string("/new/b_roughness.png"));
    QCOMPARE(roughness.channel, MapChannel::R);
    QVERIFY(!roughness.invert);
    QCOMPARE(roughness.factor.x, 1.0);
    QVERIFY(!after.map(MapSlot::Normal).flipGreen);
    // Slots it does not name are untouched by withAssignedMaps.
    QCOMPARE(after.map(MapSlot::Metallic), material.map(MapSlot::Metallic));
    std::string problem;
    QVERIFY2(after.validate(&problem), problem.c_str());
}

// A layered lobe's map turns the lobe on as painted: a sheen colour map with a white factor (the
// default black would hide it), a sheen roughness map alone a white sheen of that roughness; and a
// coat's roughness alone a full coat. What the lobe had stays otherwise.
void MapNamingTest::lobeMapsTurnTheirLobeOn_data()
{
    QTest::addColumn<QString>("file");
    QTest::addColumn<bool>("sheen");
    QTest::addColumn<bool>("coat");
    QTest::addColumn<double>("sheenRoughness");
    QTest::newRow("sheen colour") << "/t/sofa_sheen.png" << true << false << 0.0;
    QTest::newRow("sheen roughness alone") << "/t/sofa_sheen_roughness.png" << true << false << 1.0;
    QTest::newRow("coat roughness alone") << "/t/car_coat_roughness.png" << false << true << 0.0;
    QTest::newRow("base colour: no lobe") << "/t/sofa_basecolor.png" << false << false << 0.0;
}

void MapNamingTest::lobeMapsTurnTheirLobeOn()
{
    QFETCH(QString, file);
    QFETCH(bool, sheen);
    QFETCH(bool, coat);
    QFETCH(double, sheenRoughness);
    const MapNamingResult result = assignMapsByName({file});
    QCOMPARE(result.assignments.size(), std::size_t(1));
    const Material after = withAssignedMaps(Material {}, result.assignments);
    QCOMPARE(after.hasSheen(), sheen);
    QCOMPARE(after.hasClearcoat(), coat);
    QCOMPARE(after.sheenRoughness(), sheenRoughness);
    if (sheen)
        QCOMPARE(after.sheenColor(), glm::dvec3(1.0));
    std::string problem;
    QVERIFY2(after.validate(&problem), problem.c_str());
}

void MapNamingTest::textureSetReplacesTheWholeSet()
{
    // The previous set: five maps, factors at 1 (as an assignment leaves them), a UV scale of 4.
    const MapNamingResult previous = assignMapsByName({QStringLiteral("/a/old_basecolor.png"),
        QStringLiteral("/a/old_normal.png"), QStringLiteral("/a/old_metallic.png"),
        QStringLiteral("/a/old_roughness.png"), QStringLiteral("/a/old_ao.png")});
    QCOMPARE(previous.assignments.size(), std::size_t(5));
    Material material = withAssignedMaps(Material {}, previous.assignments);
    for (MaterialMap& map : material.maps)
        map.uv.scale = glm::dvec2(4.0);
    material.map(MapSlot::Occlusion).factor = glm::dvec4(0.5); // a strength the user chose

    // The new set has a base colour and an ORM: normal loses its texture and goes back to its default.
    const MapNamingResult next
        = assignMapsByName({QStringLiteral("/b/new_basecolor.png"), QStringLiteral("/b/new_orm.png")});
    std::vector<MapSlot> cleared;
    const Material after = withTextureSet(material, next.assignments, &cleared);
    QCOMPARE(cleared, std::vector<MapSlot> {MapSlot::Normal});
    const auto defaults = Material::defaultMaps();
    MaterialMap expectedNormal = defaults[std::size_t(MapSlot::Normal)];
    expectedNormal.uv.scale = glm::dvec2(4.0);
    QCOMPARE(after.map(MapSlot::Normal), expectedNormal);
    QCOMPARE(after.map(MapSlot::Metallic).path, std::string("/b/new_orm.png"));
    QCOMPARE(after.map(MapSlot::Metallic).channel, MapChannel::B);
    QCOMPARE(after.map(MapSlot::Occlusion).channel, MapChannel::R);
    QCOMPARE(after.map(MapSlot::Occlusion).factor.x, 0.5); // an assigned slot keeps its strength

    // A set with only a normal map: metallic and roughness go back to 0 and 0.5 (a factor of 1
    // left over would make a rough white metal), base colour to 0.8 grey; UVs stay.
    cleared.clear();
    const Material normalOnly
        = withTextureSet(after, assignMapsByName({QStringLiteral("/c/x_normal.png")}).assignments, &cleared);
    QCOMPARE(cleared,
        (std::vector<MapSlot> {
            MapSlot::BaseColor, MapSlot::Metallic, MapSlot::Roughness, MapSlot::Occlusion}));
    QCOMPARE(normalOnly.metallic(), 0.0);
    QCOMPARE(normalOnly.roughness(), 0.5);
    QCOMPARE(normalOnly.baseColorFactor(), glm::dvec4(0.8, 0.8, 0.8, 1.0));
    for (MapSlot slot : kAllMapSlots) {
        QCOMPARE(normalOnly.map(slot).hasTexture(), slot == MapSlot::Normal);
        QCOMPARE(normalOnly.map(slot).uv.scale, glm::dvec2(4.0));
    }
    std::string problem;
    QVERIFY2(normalOnly.validate(&problem), problem.c_str());

    // A slot that had no texture keeps the value the user gave it.
    Material untextured;
    untextured.setFactor(MapSlot::Roughness, 0.3);
    cleared.clear();
    const Material kept = withTextureSet(
        untextured, assignMapsByName({QStringLiteral("/c/x_normal.png")}).assignments, &cleared);
    QVERIFY(cleared.empty());
    QCOMPARE(kept.roughness(), 0.3);
}

QTEST_APPLESS_MAIN(MapNamingTest)
#include "MapNamingTest.moc"
