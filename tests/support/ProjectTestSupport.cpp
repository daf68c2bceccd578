#include "ProjectTestSupport.h"

#include <QDir>
#include <QFile>
#include <QString>

namespace facet::test {

QByteArray readAll(const QString& path)
{
    QFile file(path);
    return file.open(QIODevice::ReadOnly) ? file.readAll() : QByteArray();
}

Project everythingChanged(const QString& root)
{
    const auto under
        = [&](const char* relative) { return QDir(root).filePath(QLatin1String(relative)).toStdString(); };
    Project p;
    Material& m = p.material();
    m.name = "Worn brass \"test\" \u00e9";
    m.ior = 1.7;
    m.shading.composition = BrdfComposition::LearnOpenGL;
    m.shading.distribution = Distribution::Beckmann;
    m.shading.visibility = Visibility::SchlickGGX;
    m.shading.fresnel = Fresnel::Dielectric;
    m.shading.coupling = DielectricCoupling::EnergyPreserving;
    m.shading.multiScatter = false;
    MaterialMap& base = m.map(MapSlot::BaseColor);
    base.path = under("textures/albedo.png");
    base.factor = {0.9, 0.6, 0.3, 0.75};
    base.channel = MapChannel::R;
    base.colorSpace = ColorEncoding::Linear;
    base.uv = {{2.0, 3.0}, {0.25, -0.5}, 30.0};
    MaterialMap& normal = m.map(MapSlot::Normal);
    normal.path = under("textures/normal.png");
    normal.factor = glm::dvec4(0.6);
    normal.colorSpace = ColorEncoding::SRGB;
    normal.flipGreen = true;
    normal.uv.rotationDegrees = -45.0;
    MaterialMap& metallic = m.map(MapSlot::Metallic);
    metallic.path = under("textures/orm.png");
    metallic.factor = glm::dvec4(0.8);
    metallic.channel = MapChannel::A;
    metallic.invert = true;
    MaterialMap& roughness = m.map(MapSlot::Roughness);
    roughness.path = under("textures/orm.png");
    roughness.factor = glm::dvec4(0.3);
    roughness.channel = MapChannel::R;
    roughness.colorSpace = ColorEncoding::SRGB;
    roughness.uv.offset = {0.1, 0.2};
    MaterialMap& occlusion = m.map(MapSlot::Occlusion);
    occlusion.path = under("textures/orm.png");
    occlusion.factor = glm::dvec4(0.5);
    occlusion.channel = MapChannel::B;
    occlusion.invert = true;
    occlusion.uv.scale = {-1.0, 1.0};
    occlusion.texCoord = 1;
    occlusion.sampler = {TextureWrap::ClampToEdge, TextureWrap::MirroredRepeat, TextureFilter::Nearest,
        TextureFilter::NearestMipmapLinear};
    MaterialMap& emissive = m.map(MapSlot::Emissive);
    emissive.path = under("textures/emission.png");
    emissive.factor = {0.2, 0.4, 0.6, 1.0}; // emissive alpha is not stored: it stays 1
    emissive.colorSpace = ColorEncoding::Linear;
    emissive.uv.offset = {0.5, 0.0};
    m.emissiveStrength = 12.5;
    m.setClearcoat(0.75, 0.125);
    m.map(MapSlot::Clearcoat).path = under("textures/coat.png");
    m.map(MapSlot::ClearcoatRoughness).path = under("textures/coat.png");
    m.map(MapSlot::ClearcoatRoughness).invert = true;
    MaterialMap& coatNormal = m.map(MapSlot::ClearcoatNormal);
    coatNormal.path = under("textures/coat_normal.png");
    coatNormal.factor = glm::dvec4(0.5);
    coatNormal.flipGreen = true;
    m.setSheen(glm::dvec3(0.9, 0.5, 0.25), 0.375);
    m.map(MapSlot::SheenColor).path = under("textures/velvet.png");
    m.map(MapSlot::SheenColor).uv.scale = {3.0, 3.0};
    m.map(MapSlot::SheenRoughness).path = under("textures/velvet.png");
    m.map(MapSlot::SheenRoughness).texCoord = 1;
    m.setSpecular(0.625, glm::dvec3(2.5, 1.0, 0.75));
    m.map(MapSlot::SpecularColor).path = under("textures/tint.png");
    m.map(MapSlot::Specular).path = under("textures/tint.png");
    m.map(MapSlot::Specular).uv.rotationDegrees = 30.0;
    m.setAnisotropy(0.75, -40.0);
    m.map(MapSlot::Anisotropy).path = under("textures/brushed.png");
    m.setIridescence(0.875, 1.75, 150.0, 625.0);
    m.map(MapSlot::Iridescence).path = under("textures/film.png");
    m.map(MapSlot::IridescenceThickness).path = under("textures/film.png");
    m.map(MapSlot::IridescenceThickness).invert = true;
    m.alphaMode = AlphaMode::Mask;
    m.alphaCutoff = 0.25;
    m.doubleSided = false;

    p.environment.source = under("hdri/room.exr");
    p.environment.rotationDegrees = 123.5;
    p.environment.intensity = 0.125;
    p.environment.quality = IblQuality::High;
    p.environment.method = IblMethod::Reference;
    p.environment.samples = 48;

    Light sun;
    sun.name = "Sun";
    sun.type = LightType::Directional;
    sun.enabled = false;
    sun.color = {1.0, 0.9, 0.8};
    sun.intensity = 100000.0;
    sun.direction = {0.3, -1.0, 0.2};
    sun.position = {1.0, 2.0, 3.0};
    sun.range = 5.0;
    sun.innerConeAngle = 0.1;
    sun.outerConeAngle = 0.3;
    Light spot;
    spot.name = "Spot";
    spot.type = LightType::Spot;
    spot.useTemperature = true;
    spot.kelvin = 3200.0;
    spot.intensity = 800.0;
    spot.range = 12.0;
    spot.innerConeAngle = 0.25;
    spot.outerConeAngle = 0.5;
    spot.position = {-2.0, 3.0, 4.0};
    spot.direction = {0.5, -0.5, -1.0};
    Light point;
    point.name = "Point";
    point.type = LightType::Point;
    point.intensity = 0.0;
    point.position = {0.0, -1.5, 0.0};
    p.lights = {sun, spot, point};

    p.camera.position = {1.0, 2.0, 5.0};
    p.camera.target = {0.0, 0.5, 0.0};
    p.camera.up = {0.0, 0.0, 1.0};
    p.camera.verticalFovDegrees = 30.0;
    p.camera.nearPlane = 0.2;
    p.camera.farPlane = 50.0;

    ViewSettings& v = p.view;
    v.exposureEV = -1.5;
    v.toneMapper = ToneMapper::AgX;
    v.displayEncoding = DisplayEncoding::Gamma;
    v.gamma = 2.4;
    v.ocioDisplay = "sRGB - Display";
    v.ocioView = "ACES 1.0 - SDR Video";
    v.debugView = DebugView::ShadingNormal;
    v.mesh = under("meshes/bunny.glb");
    v.msaaSamples = 8;
    v.background = BackgroundMode::Color;
    v.backgroundColor = {0.1, 0.2, 0.3};
    v.backgroundBlurRoughness = 0.7;
    v.texelDensityTarget = 1024.0;

    // Version 3: the compare layout (tests/CompareLayoutTest.cpp covers each field).
    CompareLayout& c = p.compare;
    c.ab.snapshot = m; // before the push_back below, which moves the materials
    Material second = m;
    second.name = "Second";
    second.setFactor(MapSlot::Metallic, 1.0);
    p.materials.push_back(second);
    c.mode = CompareMode::Wedge;
    c.environments.cells = EnvironmentGrid::defaultCells(under("hdri/room.exr"));
    c.environments.cells[1].rotationFollowsAll = false;
    c.environments.cells[1].rotationDegrees = 45.0;
    c.environments.cells[2].exposureFollowsAll = false;
    c.environments.cells[2].exposureOffsetEV = -2.5;
    c.environments.unlinkCamera(3, p.camera);
    c.environments.cells[3].camera.position = {3.0, 0.0, 0.0};
    c.environments.linkedCameras = false;
    c.ab.source = BSource::Material;
    c.ab.material = 1;
    c.ab.preset = "gold";
    c.ab.split = 0.25;
    c.ab.layout = ABLayout::SideBySide;
    c.wedge.rows
        = WedgeAxis {WedgeParameter::Environment, {}, {under("hdri/room.exr"), "sky", "uniform:0.5"}};
    c.wedge.columns = WedgeAxis {WedgeParameter::Exposure, {-1.0, 0.0, 1.5}, {}};
    return p;
}

} // namespace facet::test
