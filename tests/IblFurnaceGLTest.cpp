// The white furnace of every BRDF composition through the real GPU path: `uniform:1.0`, a white
// (or gold-like) material, docs/architecture.md's reference view, drawn as `facet render --reference-view`
// draws it (IblPrecompute with the default preset, its DFG table of the material's visibility term,
// Renderer), against the CPU truth at the centre pixel, a pixel near the silhouette and over the
// interior (relative RMSE, core/image/ImageMetrics).
//
// The truth: for a uniform environment of radiance 1 the outgoing radiance is exactly the BRDF's
// directional albedo at the pixel's n.v (the sphere is convex), which core/shading/MaterialBrdf's
// directionalAlbedo() integrates with the ground truth's BRDF and albedo table
// (GroundTruthSettings' 64 x 64 x 2048), deterministically to ~1e-4. It is the integral
// `facet render --spp N` estimates, without its noise, so the bounds can be tight. Every
// composition's split sum is exact in a furnace (fresnel_mix's diffuse weights integrate its
// base, (1 - F0) W(n.v), since issue 10; they stood in for it before, 0.8-1.3% RMSE off here), so
// every row is held to the ground truth.
//
// Which rows see the table's variant: a white metal WITH multi-scatter compensation reflects
// (A + B) (1 + (1 - E) / E) = 1 whatever table is bound (E = A + B cancels), so those rows hold
// the compensation, not the table. Single-scattering metals, gold-like metals (F0 < 1 does not
// cancel) and dielectrics depend on it: with the correlated table forced on every variant (the
// defect of issue 8) nine uncorrelated and LearnOpenGL rows fail, e.g. LearnOpenGL metal r 0.6
// +3.45% at the centre, +21% near the edge, 11.1% RMSE (docs/ibl.md lists them all).

#include "core/image/ImageMetrics.h"
#include "core/project/Project.h"
#include "core/shading/DfgTable.h"
#include "core/shading/GroundTruth.h"
#include "core/shading/MaterialBrdf.h"
#include "core/shading/ReferenceView.h"
#include "core/support/Parallel.h"

#include "ReferenceViewRenderer.h"
#include "TestSupport.h"

#include <QtTest/QTest>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <tuple>

using namespace facet;

namespace {

// 64 x 64 as the `facet render` measurement in docs/ibl.md: the near-edge pixel (the first
// interior pixel of the middle row) is then (6, 32), n.v = 0.34.
constexpr int kSize = 64;
// Samples of the directional-albedo integral per pixel: Hammersley points, cosine and VNDF
// strategies combined; converged to ~1e-4 (docs/energy.md), far below every bound.
constexpr int kAlbedoSamples = 2048;

struct Row {
    const char* name;
    BrdfComposition composition;
    Visibility visibility;
    Distribution distribution;
    bool multiScatter;
    DielectricCoupling coupling;
    double metallic;
    double roughness;
    double pixelBound; // relative error of the centre and near-edge pixels
    double rmseBound; // interior relative RMSE
    const char* why;
    glm::dvec3 baseColor {1.0}; // white: the furnace proper
};

ShadingModel modelOf(const Row& row)
{
    ShadingModel model;
    model.composition = row.composition;
    model.visibility = row.visibility;
    model.distribution = row.distribution;
    model.multiScatter = row.multiScatter;
    model.coupling = row.coupling;
    return model;
}

struct PixelInfo {
    int x = 0;
    int y = 0;
    double NoV = 0.0;
};

// The analytic n.v of an interior pixel of the reference view.
PixelInfo pixelInfo(int x, int y)
{
    const glm::dvec3 d = referenceview::rayDirection(x, y, kSize, kSize);
    const glm::dvec3 n = *referenceview::intersectSphere(d);
    return {x, y, glm::dot(n, -d)};
}

// Bounds: the error measured on Mesa llvmpipe (printed by this test; docs/ibl.md, "White furnace
// per composition") with headroom, and what the error is made of.
// White metal, multi-scatter on: the GPU gives (A + B) M = 1 whatever the table; the truth's
// compensation from its own 64^2 x 2048 table is within 0.03% of 1 (measured 0.02%).
constexpr const char* kCompensated = "compensated white metal: 1 by construction, truth within 0.03% of 1";
// White metal, single scattering: the split sum is exact in a furnace, so what is left is the
// bilinear lookup of the 32^2 table at grazing n.v and high roughness (E is curved there) and its
// 1024 samples; measured up to 0.52% (edge, r 1) and 0.27% RMSE.
constexpr const char* kTable = "32^2 x 1024 table, bilinear at grazing n.v; measured <= 0.52% / 0.27% RMSE";
// A white dielectric under fresnel_mix: its diffuse weight (1 - F0) W(n.v) is exact in a furnace;
// what is left is the GPU irradiance map of the uniform environment (the default preset sums 8^2
// source texels a face), which reads about 0.4% above pi at the centre's normal, and the table.
constexpr const char* kIrradiance = "GPU irradiance map of the uniform environment, +0.39% at the centre";
// The energy-preserving coupling is exact in a furnace (E_s + 1 - E_s = 1): against the ground
// truth, with the same irradiance error.
constexpr const char* kCoupled = "exact in a furnace; GPU irradiance +0.36% at the centre";
// Beckmann uses the GGX table (GGX VNDF sampling, GGX D, the material's V) and GGX prefiltered
// lobes: the split sum shades it as GGX. Its ground truth pairs D_Beckmann with the GGX Smith V,
// which is not energy conserving (albedo 1.18 at n.v 1, r 0.6, compensated). Measured 15-17% at
// the centre and 10-16% RMSE: the bounds hold the approximation where it is, they do not bless it.
constexpr const char* kBeckmann = "GGX table for a Beckmann D: a documented approximation, measured 1-17%";
const glm::dvec3 kGold(1.0, 0.78, 0.34);
using enum BrdfComposition;
using enum Visibility;
using enum Distribution;
using enum DielectricCoupling;
const Row kRows[] = {
    // name, composition, V, D, multi-scatter, coupling, metallic, roughness, pixel bound, RMSE bound,
    // why
    {"gltf-metal-ms-r0.6", Gltf, SmithGGXCorrelated, GGX, true, FresnelMix, 1.0, 0.6, 0.003, 0.002,
        kCompensated},
    {"gltf-metal-ss-r0.3", Gltf, SmithGGXCorrelated, GGX, false, FresnelMix, 1.0, 0.3, 0.008, 0.004,
        kTable},
    {"gltf-metal-ss-r0.6", Gltf, SmithGGXCorrelated, GGX, false, FresnelMix, 1.0, 0.6, 0.008, 0.004,
        kTable},
    {"gltf-metal-ss-r1.0", Gltf, SmithGGXCorrelated, GGX, false, FresnelMix, 1.0, 1.0, 0.008, 0.004,
        kTable},
    {"gltf-dielectric-ms-r0.6", Gltf, SmithGGXCorrelated, GGX, true, FresnelMix, 0.0, 0.6, 0.006, 0.003,
        kIrradiance},
    {"gltf-dielectric-ss-r0.6", Gltf, SmithGGXCorrelated, GGX, false, FresnelMix, 0.0, 0.6, 0.006, 0.003,
        kIrradiance},
    {"gltf-dielectric-energy-preserving-r0.6", Gltf, SmithGGXCorrelated, GGX, true, EnergyPreserving, 0.0,
        0.6, 0.006, 0.003, kCoupled},
    {"uncorrelated-metal-ms-r0.6", Gltf, SmithGGXUncorrelated, GGX, true, FresnelMix, 1.0, 0.6, 0.003,
        0.002, kCompensated},
    {"uncorrelated-metal-ss-r0.3", Gltf, SmithGGXUncorrelated, GGX, false, FresnelMix, 1.0, 0.3, 0.008,
        0.004, kTable},
    {"uncorrelated-metal-ss-r0.6", Gltf, SmithGGXUncorrelated, GGX, false, FresnelMix, 1.0, 0.6, 0.008,
        0.004, kTable},
    {"uncorrelated-metal-ss-r1.0", Gltf, SmithGGXUncorrelated, GGX, false, FresnelMix, 1.0, 1.0, 0.008,
        0.004, kTable},
    {"uncorrelated-dielectric-ss-r0.6", Gltf, SmithGGXUncorrelated, GGX, false, FresnelMix, 0.0, 0.6,
         0.006, 0.003, kIrradiance},
    {"learnopengl-metal-ms-r0.6", LearnOpenGL, SchlickGGX, GGX, true, FresnelMix, 1.0, 0.6, 0.003, 0.002,
        kCompensated},
    {"learnopengl-metal-ss-r0.3", LearnOpenGL, SchlickGGX, GGX, false, FresnelMix, 1.0, 0.3, 0.008, 0.004,
        kTable},
    {"learnopengl-metal-ss-r0.6", LearnOpenGL, SchlickGGX, GGX, false, FresnelMix, 1.0, 0.6, 0.008, 0.004,
        kTable},
    {"learnopengl-metal-ss-r1.0", LearnOpenGL, SchlickGGX, GGX, false, FresnelMix, 1.0, 1.0, 0.008, 0.004,
        kTable},
    {"learnopengl-dielectric-ms-r0.6", LearnOpenGL, SchlickGGX, GGX, true, FresnelMix, 0.0, 0.6, 0.006,
         0.003, kIrradiance},
    {"learnopengl-dielectric-ss-r0.6", LearnOpenGL, SchlickGGX, GGX, false, FresnelMix, 0.0, 0.6, 0.006,
         0.003, kIrradiance},
    {"learnopengl-dielectric-energy-preserving-r0.6", LearnOpenGL, SchlickGGX, GGX, true, EnergyPreserving,
        0.0, 0.6, 0.006, 0.003, kCoupled},
    // A gold-like metal, multi-scatter on (the default model): F0 < 1 does not cancel the table
    // in (F0 A + B)(1 + F0 (1 - E) / E), so these rows see the variant with compensation on.
    {"gltf-gold-ms-r0.6", Gltf, SmithGGXCorrelated, GGX, true, FresnelMix, 1.0, 0.6, 0.008, 0.004, kTable,
        kGold},
    {"uncorrelated-gold-ms-r0.6", Gltf, SmithGGXUncorrelated, GGX, true, FresnelMix, 1.0, 0.6, 0.008,
        0.004, kTable, kGold},
    {"learnopengl-gold-ms-r0.6", LearnOpenGL, SchlickGGX, GGX, true, FresnelMix, 1.0, 0.6, 0.008, 0.004,
        kTable, kGold},
    {"beckmann-metal-ms-r0.6", Gltf, SmithGGXCorrelated, Beckmann, true, FresnelMix, 1.0, 0.6, 0.17,
        0.115, kBeckmann},
    {"beckmann-metal-ss-r0.3", Gltf, SmithGGXCorrelated, Beckmann, false, FresnelMix, 1.0, 0.3, 0.012,
        0.013, kBeckmann},
    {"beckmann-metal-ss-r0.6", Gltf, SmithGGXCorrelated, Beckmann, false, FresnelMix, 1.0, 0.6, 0.17,
        0.115, kBeckmann},
    {"beckmann-metal-ss-r1.0", Gltf, SmithGGXCorrelated, Beckmann, false, FresnelMix, 1.0, 1.0, 0.185,
        0.18, kBeckmann},
};

Project furnaceProject(const Row& row)
{
    Project project = Project::defaultProject();
    project.environment.source = "uniform:1.0";
    project.environment.quality = IblQuality::Default;
    project.environment.method = IblMethod::SplitSum; // the split sum's furnace (fis has its own test)
    project.view.mesh = "sphere";
    project.view.debugView = DebugView::None;
    project.lights.clear();
    project.material().setBaseColor(row.baseColor);
    project.material().setFactor(MapSlot::Metallic, row.metallic);
    project.material().setFactor(MapSlot::Roughness, row.roughness);
    project.material().shading = modelOf(row);
    return project;
}

// The worst channel's relative error.
double relativeError(const glm::vec4& actual, const glm::vec4& expected)
{
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(double(actual[c]) - double(expected[c])) / double(expected[c]));
    return worst;
}

} // namespace

class IblFurnaceGLTest : public QObject {
    Q_OBJECT
public:
    static void initMain() { facet::test::forgetDisplayServer(); }

private Q_SLOTS:
    void initTestCase();
    void furnace_data();
    void furnace();

private:
    facet::test::ReferenceViewRenderer m_gpu;
};

void IblFurnaceGLTest::initTestCase()
{
    std::string error;
    QVERIFY2(m_gpu.initialize(&error), error.c_str());
}

void IblFurnaceGLTest::furnace_data()
{
    QTest::addColumn<int>("row");
    for (std::size_t i = 0; i < std::size(kRows); ++i)
        QTest::newRow(kRows[i].name) << int(i);
}

void IblFurnaceGLTest::furnace()
{
    QFETCH(int, row);
    const Row& r = kRows[row];
    const Project project = furnaceProject(r);
    std::string error;
    const std::optional<Image> gpu = m_gpu.render(project, "default", kSize, &error);
    QVERIFY2(gpu, error.c_str());

    // The truth per interior pixel (background pixels: the environment, 1).
    const ShadingModel model = modelOf(r);
    const GroundTruthSettings truthSettings;
    const std::shared_ptr<const DfgTable> albedo
        = albedoTable(truthSettings.albedoTableSize, truthSettings.albedoTableSamples, model.visibility);
    const MaterialBrdf truthBrdf(model, *albedo);
    MaterialInfo info;
    info.baseColor = r.baseColor;
    info.metallic = r.metallic;
    info.perceptualRoughness = r.roughness;
    info.ior = project.material().ior;
    Image truth(kSize, kSize, glm::vec4(1.0f));
    parallelFor(std::size_t(kSize), [&](std::size_t imageRow) { // rows are disjoint outputs
        const int y = int(imageRow);
        for (int x = 0; x < kSize; ++x) {
            if (!referenceview::isInteriorSpherePixel(x, y, kSize, kSize))
                continue;
            const double NoV = pixelInfo(x, y).NoV;
            truth.at(x, y) = glm::vec4(glm::vec3(directionalAlbedo(truthBrdf, info, NoV, kAlbedoSamples)), 1.0f);
        }
    });

    int edgeX = 0;
    while (!referenceview::isInteriorSpherePixel(edgeX, kSize / 2, kSize, kSize))
        ++edgeX;
    const PixelInfo centre = pixelInfo(kSize / 2, kSize / 2);
    const PixelInfo edge = pixelInfo(edgeX, kSize / 2);
    // Printed: the blue channel (for gold the one furthest from 1, where the table matters most).
    auto value = [](const Image& image, const PixelInfo& p) { return double(image.at(p.x, p.y).b); };
    const double centreError = relativeError(gpu->at(centre.x, centre.y), truth.at(centre.x, centre.y));
    const double edgeError = relativeError(gpu->at(edge.x, edge.y), truth.at(edge.x, edge.y));
    const double rmse = relativeRmse(*gpu, truth);
    std::printf(
        "  %-46s centre (n.v %.3f) gpu %.4f truth %.4f %+.2f%% | edge (n.v %.3f) gpu %.4f truth %.4f %+.2f%% | "
        "RMSE %.2f%%\n",
        r.name, centre.NoV, value(*gpu, centre), value(truth, centre),
        100.0 * (value(*gpu, centre) / value(truth, centre) - 1.0), edge.NoV, value(*gpu, edge), value(truth, edge),
        100.0 * (value(*gpu, edge) / value(truth, edge) - 1.0), 100.0 * rmse);
    const QString where = QStringLiteral("(%1)").arg(QString::fromUtf8(r.why));
    QVERIFY2(centreError < r.pixelBound,
        qPrintable(QStringLiteral("centre: relative error %1 >= %2 %3")
                       .arg(centreError)
                       .arg(r.pixelBound)
                       .arg(where)));
    QVERIFY2(edgeError < r.pixelBound,
        qPrintable(QStringLiteral("near edge: relative error %1 >= %2 %3")
                       .arg(edgeError)
                       .arg(r.pixelBound)
                       .arg(where)));
    QVERIFY2(std::isfinite(rmse) && rmse < r.rmseBound,
        qPrintable(
            QStringLiteral("interior relative RMSE %1 >= %2 %3").arg(rmse).arg(r.rmseBound).arg(where)));
}

QTEST_GUILESS_MAIN(IblFurnaceGLTest)
#include "IblFurnaceGLTest.moc"
