#include "IblMethodCase.h"

#include <cmath>
#include <cstdio>

#include "core/material/Material.h"
#include "core/project/Light.h"
#include "core/shading/GroundTruth.h"

namespace facet::test {

Project iblMethodCaseProject(const IblMethodCase& c, IblMethod method, int samples)
{
    Project project = Project::defaultProject();
    project.environment.source = c.environment;
    project.environment.rotationDegrees = c.rotationDegrees;
    project.environment.method = method;
    project.environment.samples = method == IblMethod::SplitSum ? 0 : samples;
    project.view.mesh = "sphere";
    project.view.debugView = DebugView::None;
    project.lights.clear();
    if (c.light) {
        Light sun;
        sun.type = LightType::Directional;
        sun.intensity = 2.0;
        sun.direction = {-0.5, -0.6, -0.6};
        project.lights.push_back(sun);
    }
    Material& m = project.material();
    m.setBaseColor(c.baseColor);
    m.setFactor(MapSlot::Metallic, c.metallic);
    m.setFactor(MapSlot::Roughness, c.roughness);
    m.shading.composition = c.composition;
    m.shading.visibility = c.visibility;
    m.shading.distribution = c.distribution;
    m.shading.fresnel = c.fresnel;
    m.shading.coupling = c.coupling;
    m.shading.multiScatter = c.multiScatter;
    m.setFactor(MapSlot::Clearcoat, c.clearcoat);
    m.setFactor(MapSlot::ClearcoatRoughness, c.clearcoatRoughness);
    m.setSheen(c.sheenColor, c.sheenRoughness);
    m.setSpecular(c.specular, c.specularColor);
    m.setAnisotropy(c.anisotropy, c.anisotropyRotationDegrees);
    m.setIridescence(c.iridescence, c.iridescenceIor, m.iridescenceThicknessMinimum, c.iridescenceThickness);
    return project;
}

std::optional<Image> groundTruthImage(
    const Project& project, int size, int samplesPerPixel, std::uint64_t seed, std::string* error)
{
    std::string warning;
    const auto scene = groundTruthSceneFromProject(project, error, &warning);
    if (!scene)
        return std::nullopt;
    GroundTruthSettings settings;
    settings.width = size;
    settings.height = size;
    settings.samplesPerPixel = samplesPerPixel;
    settings.seed = seed;
    return renderGroundTruth(*scene, settings);
}

std::string firstUnusablePixel(const Image& image)
{
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                const float v = image.at(x, y)[c];
                if (!std::isfinite(v) || v < 0.0f) {
                    char text[96];
                    std::snprintf(text, sizeof text, "(%d, %d): %g", x, y, double(v));
                    return text;
                }
            }
    return {};
}

} // namespace facet::test
