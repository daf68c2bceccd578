// The material's texture maps on the GPU against their CPU twin (core/shading/MaterialInputs.h), one row
// per map input and feature (Magnum's per-feature golden rows): each map alone, all five
// together, the clear coat's three (alone, packed, over a base normal map, off), a packed texture feeding
// three slots, every channel, inversion, colour space, normal strength, the DirectX green flip, the UV
// transform, the UV set, each wrap mode and the nearest filter, and each kind of file in its own GPU format
// (8-bit grey and grey + alpha, 16-bit PNG, float EXR). Each row is a project with texture files on disk,
// rendered the way `facet render --reference-view` renders it (core/project/ProjectAssets loads the maps,
// render/SceneFromProject builds the scene, render/FrameRenderer draws and reads back the RGBA16F target) by
// a fresh Renderer, so every map is uploaded in the row's first frame, as after opening a project.
//
// The GPU writes the inputs through debug views (base-color, metallic, roughness, occlusion,
// shading-normal, and clearcoat, clearcoat-roughness, clearcoat-normal for rows with a coat,
// sheen-color, sheen-roughness for rows with a sheen, specular, specular-color for rows with a
// specular layer, anisotropy, anisotropy-direction for anisotropic rows). The CPU
// evaluates the same inputs from the texture coordinate, the geometric normal and the tangent that the GPU
// interpolated (the uv, geometric-normal and tangent debug views), so the comparison isolates the material
// inputs from the tessellation.

#include "core/image/Image.h"
#include "core/project/Project.h"
#include "core/project/ProjectAssets.h"
#include "core/shading/MaterialInputs.h"
#include "core/shading/ReferenceView.h"

#include "MaterialMapRows.h"
#include "ReferenceViewRenderer.h"
#include "TestSupport.h"

#include <QTemporaryDir>
#include <QtTest/QTest>

#include <OpenImageIO/imageio.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

using namespace facet;
using facet::test::file;
using facet::test::kMapTextureSize;
using facet::test::materialMapRows;
using facet::test::useMap;
using facet::test::useNormal;
using facet::test::wave;
using facet::test::writeDeep;
using facet::test::writePng;

namespace {

constexpr int kRenderSize = 96;

// The views compared, and what each shows of the CPU twin's MaterialInfo (its clearcoatNormal
// set as the shader sets it: the coat's normal map's, or the geometric normal).
struct ViewCheck {
    const char* view;
    std::function<glm::dvec3(const MaterialInfo&, const glm::dvec3& shadingNormal)> expected;
    // A layered lobe's view: compared only for rows with the lobe or its maps (each costs a frame).
    MaterialLobe lobe = MaterialLobe::Core;
};
const std::vector<ViewCheck>& viewChecks()
{
    static const std::vector<ViewCheck> checks = {
        {"base-color", [](const MaterialInfo& m, const glm::dvec3&) { return m.baseColor; }},
        {"metallic", [](const MaterialInfo& m, const glm::dvec3&) { return glm::dvec3(m.metallic); }},
        // The view shows the roughness used in shading, after the clamp to the minimum.
        {"roughness",
            [](const MaterialInfo& m, const glm::dvec3&) {
                return glm::dvec3(std::max(m.perceptualRoughness, Material::kMinPerceptualRoughness));
            }},
        {"occlusion", [](const MaterialInfo& m, const glm::dvec3&) { return glm::dvec3(m.occlusion); }},
        {"shading-normal", [](const MaterialInfo&, const glm::dvec3& n) { return n * 0.5 + 0.5; }},
        {"emissive", [](const MaterialInfo& m, const glm::dvec3&) { return m.emissive; }},
        {"alpha", [](const MaterialInfo& m, const glm::dvec3&) { return glm::dvec3(m.alpha); }},
        {"clearcoat", [](const MaterialInfo& m, const glm::dvec3&) { return glm::dvec3(m.clearcoat); },
            MaterialLobe::Clearcoat},
        {"clearcoat-roughness",
            [](const MaterialInfo& m, const glm::dvec3&) { return glm::dvec3(m.clearcoatRoughness); },
            MaterialLobe::Clearcoat},
        {"clearcoat-normal",
            [](const MaterialInfo& m, const glm::dvec3&) { return m.clearcoatNormal * 0.5 + 0.5; },
            MaterialLobe::Clearcoat},
        {"sheen-color", [](const MaterialInfo& m, const glm::dvec3&) { return m.sheenColor; },
            MaterialLobe::Sheen},
        {"sheen-roughness",
            [](const MaterialInfo& m, const glm::dvec3&) { return glm::dvec3(m.sheenRoughness); },
            MaterialLobe::Sheen},
        {"specular", [](const MaterialInfo& m, const glm::dvec3&) { return glm::dvec3(m.specular); },
            MaterialLobe::Specular},
        {"specular-color", [](const MaterialInfo& m, const glm::dvec3&) { return m.specularColor; },
            MaterialLobe::Specular},
        {"anisotropy", [](const MaterialInfo& m, const glm::dvec3&) { return glm::dvec3(m.anisotropy); },
            MaterialLobe::Anisotropy},
        {"anisotropy-direction",
            [](const MaterialInfo& m, const glm::dvec3&) { return m.anisotropyDirection * 0.5 + 0.5; },
            MaterialLobe::Anisotropy},
        {"iridescence", [](const MaterialInfo& m, const glm::dvec3&) { return glm::dvec3(m.iridescence); },
            MaterialLobe::Iridescence},
        // The film's thickness / 1000 nm (0 without a film).
        {"iridescence-thickness",
            [](const MaterialInfo& m, const glm::dvec3&) {
                return glm::dvec3(m.iridescence > 0.0 ? m.iridescenceThickness / 1000.0 : 0.0);
            },
            MaterialLobe::Iridescence},
    };
    return checks;
}

glm::dvec3 rgb(const Image& image, int x, int y)
{
    return glm::dvec3(glm::vec3(image.at(x, y)));
}

} // namespace

class MaterialMapsGLTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { facet::test::forgetDisplayServer(); }

private Q_SLOTS:
    void initTestCase();
    void matchesCpuTwin_data();
    void matchesCpuTwin();
    void outOfRangeMapsMakeNoEnergy_data();
    void outOfRangeMapsMakeNoEnergy();

private:
    std::optional<Image> render(const Project& project, const std::string& view, std::string* error);

    QTemporaryDir m_folder;
    facet::test::ReferenceViewRenderer m_gpu;
    // What the GPU interpolated, per pixel (constant for the sphere): texture coordinate,
    // geometric normal (0.5 n + 0.5), tangent (0.5 t + 0.5, from a normal-mapped variant).
    std::optional<Image> m_uv;
    std::optional<Image> m_geometricNormal;
    std::optional<Image> m_tangent;
    std::vector<glm::ivec2> m_pixels; // the pixels compared
};

std::optional<Image> MaterialMapsGLTest::render(const Project& project, const std::string& view, std::string* error)
{
    Project p = project;
    p.view.debugView = debugViewFromString(view).value();
    return m_gpu.renderAsCommand(p, "draft", kRenderSize, error);
}

void MaterialMapsGLTest::initTestCase()
{
    // Trilinear everywhere: this table checks what reaches the shader (maps, channels, spaces,
    // transforms), against a twin that reads level 0; software rasterisers otherwise read the
    // nearer mip level (render/TextureFiltering.h), a whole level away from the twin where the
    // sphere turns away.
    qputenv("FACET_TEXTURE_MIPS", "trilinear");
    QVERIFY(m_folder.isValid());
    const QString folder = m_folder.path();
    // basecolor: three independent smooth signals; packed: four distinct ones (one per channel);
    // grey: one channel; normal: a tangent-space normal tilted both ways, encoded 0.5 n + 0.5.
    QVERIFY(writePng(file(folder, "basecolor.png"), 3, [](int x, int y) {
        return glm::dvec4(0.5 + 0.4 * wave(x), 0.5 + 0.4 * wave(y), 0.5 + 0.4 * wave(x + y, 1.0), 1.0);
    }));
    QVERIFY(writePng(file(folder, "packed.png"), 4, [](int x, int y) {
        return glm::dvec4(0.5 + 0.45 * wave(x), 0.5 + 0.45 * wave(y, 0.7), 0.5 + 0.45 * wave(x - y, 2.0),
                          0.5 + 0.45 * wave(x, 1.9));
    }));
    // direction: a unit direction field turning smoothly (RG = d x 0.5 + 0.5) and a strength in B, as
    // KHR_materials_anisotropy's texture holds them (a direction near zero length would turn on a
    // filtering difference, which no real direction map has).
    QVERIFY(writePng(file(folder, "direction.png"), 3, [](int x, int y) {
        const double angle = 1.5 * wave(x) + wave(y, 0.7);
        return glm::dvec4(
            0.5 + 0.5 * std::cos(angle), 0.5 + 0.5 * std::sin(angle), 0.5 + 0.45 * wave(x + y, 1.3), 1.0);
    }));
    QVERIFY(writePng(file(folder, "grey.png"), 1, [](int x, int y) {
        return glm::dvec4(0.5 + 0.45 * wave(x + y, 0.3));
    }));
    QVERIFY(writePng(file(folder, "normal.png"), 3, [](int x, int y) {
        const glm::dvec3 n = glm::normalize(glm::dvec3(0.35 * wave(x), 0.35 * wave(y, 1.2), 1.0));
        return glm::dvec4(n * 0.5 + 0.5, 1.0);
    }));
    // Grey + alpha (two channels), 16-bit, float.
    QVERIFY(writePng(file(folder, "greyalpha.png"), 2, [](int x, int y) {
        return glm::dvec4(0.5 + 0.45 * wave(x - y, 0.9), 0.5 + 0.45 * wave(y, 2.5), 0.0, 0.0);
    }));
    QVERIFY(writeDeep(file(folder, "normal16.png"), 3, OIIO::TypeDesc::UINT16, [](int x, int y) {
        const glm::dvec3 n = glm::normalize(glm::dvec3(0.35 * wave(x, 0.4), 0.35 * wave(y, 1.6), 1.0));
        return glm::dvec4(n * 0.5 + 0.5, 1.0);
    }));
    QVERIFY(writeDeep(file(folder, "basecolor16.png"), 3, OIIO::TypeDesc::UINT16, [](int x, int y) {
        return glm::dvec4(0.5 + 0.4 * wave(y), 0.5 + 0.4 * wave(x, 0.5), 0.5 + 0.4 * wave(x - y), 1.0);
    }));
    QVERIFY(writeDeep(file(folder, "packed.exr"), 4, OIIO::TypeDesc::FLOAT, [](int x, int y) {
        return glm::dvec4(0.6 + 0.35 * wave(x, 0.2), 0.5 + 0.45 * wave(y, 1.1), 0.4 + 0.3 * wave(x + y, 0.6),
                          0.5 + 0.45 * wave(x, 2.2));
    }));

    std::string error;
    QVERIFY2(m_gpu.initialize(&error), error.c_str());

    Project project = Project::defaultProject();
    project.environment.source = "uniform:0.5";
    project.lights.clear();
    m_uv = render(project, "uv", &error);
    QVERIFY2(m_uv, error.c_str());
    m_geometricNormal = render(project, "geometric-normal", &error);
    QVERIFY2(m_geometricNormal, error.c_str());
    useNormal(project.material(), folder);
    m_tangent = render(project, "tangent", &error);
    QVERIFY2(m_tangent, error.c_str());

    // Interior sphere pixels, away from the silhouette (margin 2), from grazing angles (n.v > 0.4)
    // and from the poles (|n.y| < 0.8): there the sphere's u changes fast across a pixel and the
    // GPU reads coarser mip levels than the CPU twin's level 0. Pixels next to the UV seam
    // (u jumps from 1 to 0) are left out too: the GPU picks the mip level from UV derivatives over
    // 2 x 2 pixels, which across the seam say "the whole texture in one pixel".
    const auto nearSeam = [this](int x, int y) {
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                if (std::abs(m_uv->at(x + dx, y + dy).x - m_uv->at(x, y).x) > 0.5f)
                    return true;
        return false;
    };
    for (int y = 0; y < kRenderSize; ++y)
        for (int x = 0; x < kRenderSize; ++x) {
            if (!referenceview::isInteriorSpherePixel(x, y, kRenderSize, kRenderSize, 2) || nearSeam(x, y))
                continue;
            const glm::dvec3 d = referenceview::rayDirection(x, y, kRenderSize, kRenderSize);
            const glm::dvec3 n = *referenceview::intersectSphere(d);
            if (glm::dot(n, -d) > 0.4 && std::abs(n.y) < 0.8)
                m_pixels.emplace_back(x, y);
        }
    QVERIFY2(m_pixels.size() > 2000, qPrintable(QStringLiteral("%1 pixels compared").arg(m_pixels.size())));

    // The inputs are what they claim: uv in [0, 1], unit normals facing the camera, unit tangents
    // perpendicular to them (a broken view would make every row below meaningless).
    for (const glm::ivec2& p : m_pixels) {
        const glm::dvec3 uv = rgb(*m_uv, p.x, p.y);
        QVERIFY(uv.x >= 0.0 && uv.x <= 1.0 && uv.y >= 0.0 && uv.y <= 1.0 && uv.z == 0.0);
        const glm::dvec3 ng = rgb(*m_geometricNormal, p.x, p.y) * 2.0 - 1.0;
        const glm::dvec3 t = rgb(*m_tangent, p.x, p.y) * 2.0 - 1.0;
        QVERIFY(std::abs(glm::length(ng) - 1.0) < 0.01 && ng.z > 0.0);
        QVERIFY(std::abs(glm::length(t) - 1.0) < 0.01 && std::abs(glm::dot(t, ng)) < 0.01);
    }
}


void MaterialMapsGLTest::matchesCpuTwin_data()
{
    QTest::addColumn<int>("row");
    for (std::size_t i = 0; i < materialMapRows().size(); ++i)
        QTest::newRow(materialMapRows()[i].name) << int(i);
}

void MaterialMapsGLTest::matchesCpuTwin()
{
    QFETCH(int, row);
    Project project = Project::defaultProject();
    project.environment.source = "uniform:0.5";
    project.lights.clear();
    // Factors other than 1, so that "the factor multiplies the texture" is checked too.
    Material& material = project.material();
    material.setBaseColor(glm::dvec3(0.9, 0.8, 1.0));
    material.setFactor(MapSlot::Metallic, 0.8);
    material.setFactor(MapSlot::Roughness, 0.9);
    materialMapRows()[std::size_t(row)].setup(material, m_folder.path());
    std::string error;
    QVERIFY2(material.validate(&error), error.c_str());

    // The CPU twin reads the same files through the same loader.
    const auto assets = loadProjectAssets(project, &error);
    QVERIFY2(assets, error.c_str());
    MaterialMapImages images {};
    for (MapSlot slot : kAllMapSlots)
        images[std::size_t(slot)] = assets->maps[0][std::size_t(slot)].image.get();

    // A lobe's views only for rows with the lobe or its maps.
    const auto involves = [&](MaterialLobe lobe) {
        if (lobe == MaterialLobe::Core || material.hasLobe(lobe))
            return true;
        for (MapSlot slot : kAllMapSlots)
            if (lobeOf(slot) == lobe && material.map(slot).hasTexture())
                return true;
        return false;
    };
    for (const ViewCheck& check : viewChecks()) {
        if (!involves(check.lobe))
            continue;
        const auto gpu = render(project, check.view, &error);
        QVERIFY2(gpu, error.c_str());
        double maxError = 0.0;
        double sumError = 0.0;
        glm::ivec2 worst {0};
        glm::dvec3 worstExpected {0.0}, worstActual {0.0};
        glm::dvec2 worstUv {0.0};
        for (const glm::ivec2& p : m_pixels) {
            const glm::dvec2 uv(rgb(*m_uv, p.x, p.y));
            const glm::dvec3 ng = glm::normalize(rgb(*m_geometricNormal, p.x, p.y) * 2.0 - 1.0);
            const glm::dvec3 t = rgb(*m_tangent, p.x, p.y) * 2.0 - 1.0;
            MaterialInfo info = materialInputs(material, images, uv);
            const auto mapped = [&](MapSlot slot) {
                const MapImage* image = images[std::size_t(slot)];
                if (!image || !material.usesSlot(slot))
                    return ng;
                const MaterialMap& map = material.map(slot);
                const glm::dvec4 texel = sampleMap(map, *image, TexCoords {uv, uv});
                // The sphere's tangents all have handedness +1 (core/mesh/MeshPrimitives).
                return shadingNormal(ng, glm::dvec4(t, 1.0), texel, map.factor.x, map.flipGreen);
            };
            const glm::dvec3 n = mapped(MapSlot::Normal);
            info.clearcoatNormal = mapped(MapSlot::ClearcoatNormal);
            // The reference view shades the analytic sphere, whose tangent the GPU takes analytically too.
            if (info.anisotropy > 0.0)
                info.anisotropyDirection = surfaceAnisotropyDirection(
                    ng, referenceview::sphereTangent(ng), info.anisotropyTangentDirection);
            const glm::dvec3 expected = check.expected(info, n);
            const glm::dvec3 actual = rgb(*gpu, p.x, p.y);

            const glm::dvec3 d = glm::abs(actual - expected);
            const double e = std::max({d.x, d.y, d.z});
            if (!(e <= maxError)) {
                maxError = std::isfinite(e) ? e : INFINITY;
                worst = p;
                worstExpected = expected;
                worstActual = actual;
                worstUv = uv;
            }
            sumError += e;
        }
        const double meanError = sumError / double(m_pixels.size());
        // Bounds: the GPU filters trilinearly (llvmpipe: 8-bit bilinear weights) and picks coarser
        // mip levels toward the masked-out limb, where the twin reads level 0; its sRGB decode and
        // the RGBA16F target round by ~5e-4. Measured over every row on llvmpipe (Mesa 22.3):
        // max 0.012, mean 0.0025, both base colour with UV scale 2 x 3 (more minification); the
        // emissive rows scale the same errors by up to 2. A map bound to the wrong unit or not at
        // all is off by 0.1 to 1 (the texture-unit defect of issue 8 measured max 0.78, mean 0.56).
        const double kMaxBound = materialMapRows()[std::size_t(row)].maxBound;
        constexpr double kMeanBound = 0.005;
        std::printf(
            "  %-22s %-15s max %.5f (at %d,%d, uv %.4f %.4f: GPU %.4f %.4f %.4f, twin %.4f %.4f %.4f), "
            "mean %.6f\n",
            materialMapRows()[std::size_t(row)].name, check.view, maxError, worst.x, worst.y, worstUv.x,
            worstUv.y, worstActual.x, worstActual.y, worstActual.z, worstExpected.x, worstExpected.y,
            worstExpected.z, meanError);
        QVERIFY2(maxError <= kMaxBound && meanError <= kMeanBound,
                 qPrintable(QStringLiteral("%1 view: max %2 (pixel %3,%4), mean %5 against the CPU twin")
                                .arg(QLatin1String(check.view))
                                .arg(maxError)
                                .arg(worst.x)
                                .arg(worst.y)
                                .arg(meanError)));
    }
}

void MaterialMapsGLTest::outOfRangeMapsMakeNoEnergy_data()
{
    QTest::addColumn<int>("slot");
    QTest::addColumn<float>("value"); // every texel of a float EXR
    QTest::addColumn<float>("clamped"); // the in-range value it must render as
    QTest::addColumn<double>("metallic");
    QTest::newRow("occlusion 5") << int(MapSlot::Occlusion) << 5.0f << 1.0f << 0.0;
    QTest::newRow("occlusion 65504") << int(MapSlot::Occlusion) << 65504.0f << 1.0f << 0.0;
    QTest::newRow("occlusion +inf") << int(MapSlot::Occlusion) << INFINITY << 1.0f << 0.0;
    QTest::newRow("occlusion 5, metal") << int(MapSlot::Occlusion) << 5.0f << 1.0f << 1.0;
    QTest::newRow("occlusion -3") << int(MapSlot::Occlusion) << -3.0f << 0.0f << 0.0;
    QTest::newRow("base colour 5") << int(MapSlot::BaseColor) << 5.0f << 1.0f << 0.0;
    QTest::newRow("base colour 5, metal") << int(MapSlot::BaseColor) << 5.0f << 1.0f << 1.0;
}

// Issue 29, "Energy from nothing": occlusion maps were not clamped to [0, 1] (nor was a float
// base colour above 1), so a float EXR of 5.0 made a white furnace sphere reflect 5x its light,
// and 65504 or Inf absurd values. A white (base colour 1) sphere under a uniform environment of
// radiance 1: a map beyond [0, 1] renders exactly as the same map at its bound (within the
// RGBA16F target's rounding), on the GPU and in the CPU twin's inputs, and no pixel reflects more
// than its light but for the glTF fresnel_mix's grazing gain (docs/energy.md: at most 2.5% on
// the interior pixels compared here, measured 1.0244 for the white dielectric).
void MaterialMapsGLTest::outOfRangeMapsMakeNoEnergy()
{
    QFETCH(int, slot);
    QFETCH(float, value);
    QFETCH(float, clamped);
    QFETCH(double, metallic);
    const auto renderWith = [&](float texel, std::string* error) -> std::optional<Image> {
        const QString path
            = m_folder.filePath(QStringLiteral("range-%1-%2.exr").arg(slot).arg(double(texel)));
        if (!writeDeep(
                path, 3, OIIO::TypeDesc::FLOAT, [texel](int, int) { return glm::dvec4(double(texel)); }))
            return std::nullopt;
        Project project = Project::defaultProject();
        project.environment.source = "uniform:1";
        project.lights.clear();
        Material& material = project.material();
        material.setBaseColor(glm::dvec3(1.0));
        material.setFactor(MapSlot::Metallic, metallic);
        material.setFactor(MapSlot::Roughness, 0.5);
        useMap(material, MapSlot(slot), path,
            MapSlot(slot) == MapSlot::BaseColor ? MapChannel::Rgb : MapChannel::R, ColorEncoding::Linear);
        const auto assets = loadProjectAssets(project, error);
        if (!assets)
            return std::nullopt;
        MaterialMapImages images {};
        for (MapSlot each : kAllMapSlots)
            images[std::size_t(each)] = assets->maps[0][std::size_t(each)].image.get();
        const MaterialInfo info = materialInputs(material, images, glm::dvec2(0.5));
        if (!(info.occlusion >= 0.0 && info.occlusion <= 1.0)
            || !glm::all(glm::lessThanEqual(info.baseColor, glm::dvec3(1.0)))) {
            *error = "the CPU twin's occlusion or base colour is outside [0, 1]";
            return std::nullopt;
        }
        return render(project, "none", error);
    };
    std::string error;
    const auto gpu = renderWith(value, &error);
    QVERIFY2(gpu, error.c_str());
    const auto bound = renderWith(clamped, &error);
    QVERIFY2(bound, error.c_str());
    double brightest = 0.0;
    double largestDifference = 0.0;
    for (const glm::ivec2& p : m_pixels) {
        const glm::dvec3 c = rgb(*gpu, p.x, p.y);
        brightest = std::max({brightest, c.r, c.g, c.b});
        const glm::dvec3 d = glm::abs(c - rgb(*bound, p.x, p.y));
        largestDifference = std::max({largestDifference, d.r, d.g, d.b});
    }
    std::printf("  %-22s brightest %.4f, largest difference to the map at %g: %.5f\n",
        QTest::currentDataTag(), brightest, double(clamped), largestDifference);
    QVERIFY2(largestDifference <= 1e-3,
        qPrintable(QStringLiteral("differs from the map at its bound by %1").arg(largestDifference)));
    QVERIFY2(brightest <= 1.025, qPrintable(QStringLiteral("a pixel reflects %1x the light").arg(brightest)));
}

QTEST_GUILESS_MAIN(MaterialMapsGLTest)
#include "MaterialMapsGLTest.moc"
