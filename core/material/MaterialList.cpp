// Adding, duplicating and deleting a project's materials (core/material/MaterialList.h).

#include "core/material/MaterialList.h"

#include <algorithm>

namespace facet {

namespace {

bool nameTaken(const Project& project, const std::string& name)
{
    return std::any_of(project.materials.begin(), project.materials.end(),
        [&name](const Material& material) { return material.name == name; });
}

bool fail(std::string* problem, const std::string& text)
{
    if (problem)
        *problem = text;
    return false;
}

} // namespace

std::string uniqueMaterialName(const Project& project, const std::string& base)
{
    const std::string stem = base.empty() ? std::string("Material") : base;
    std::string name = stem;
    for (int n = 2; nameTaken(project, name); ++n)
        name = stem + " " + std::to_string(n);
    return name;
}

std::optional<Project> withMaterialInserted(
    Project project, int index, Material material, std::string* problem)
{
    if (project.materials.size() >= std::size_t(Project::kMaxMaterials)) {
        fail(problem, "a project holds at most " + std::to_string(Project::kMaxMaterials) + " materials");
        return std::nullopt;
    }
    index = std::clamp(index, 0, int(project.materials.size()));
    material.name = uniqueMaterialName(project, material.name);
    project.materials.insert(project.materials.begin() + index, std::move(material));
    for (MeshPart& part : project.parts)
        if (part.material >= index)
            ++part.material;
    project.compare.insertMaterial(index);
    project.currentMaterial = index;
    return project;
}

std::optional<Project> withMaterialDuplicated(const Project& project, int index, std::string* problem)
{
    if (index < 0 || std::size_t(index) >= project.materials.size()) {
        fail(problem, "there is no material " + std::to_string(index));
        return std::nullopt;
    }
    Material copy = project.materials[std::size_t(index)];
    copy.name += " copy";
    return withMaterialInserted(project, index + 1, std::move(copy), problem);
}

std::optional<Project> withMaterialRemoved(Project project, int index, std::string* problem)
{
    if (index < 0 || std::size_t(index) >= project.materials.size()) {
        fail(problem, "there is no material " + std::to_string(index));
        return std::nullopt;
    }
    if (project.materials.size() == 1) {
        fail(problem, "a project has at least one material: '" + project.materials.front().name + "' stays");
        return std::nullopt;
    }
    const Material removed = project.materials[std::size_t(index)];
    project.materials.erase(project.materials.begin() + index);
    const int replacement = std::max(index - 1, 0);
    for (MeshPart& part : project.parts) {
        if (part.material == index)
            part.material = replacement;
        else if (part.material > index)
            --part.material;
    }
    project.compare.removeMaterial(index, removed);
    if (project.currentMaterial == index)
        project.currentMaterial = replacement;
    else if (project.currentMaterial > index)
        --project.currentMaterial;
    return project;
}

namespace {

enum class SlotKind { Color, Normal, Scalar };

SlotKind kindOf(MapSlot slot)
{
    return isColorSlot(slot) ? SlotKind::Color : isNormalSlot(slot) ? SlotKind::Normal : SlotKind::Scalar;
}

} // namespace

MaterialMap pastedMap(MapSlot from, const MaterialMap& copied, MapSlot to, const MaterialMap& target)
{
    MaterialMap map = copied;
    if (kindOf(from) != kindOf(to)) {
        map.factor = target.factor;
        map.colorSpace = Material::defaultMaps()[std::size_t(to)].colorSpace;
        map.invert = false; // only between scalar slots, which are one kind
        map.flipGreen = false; // only between normal maps
    }
    // Within a kind too: base colour may read one channel, emissive and the sheen's colour not.
    if (readsRgbOnly(to))
        map.channel = MapChannel::Rgb;
    else if (isScalarSlot(to) && map.channel == MapChannel::Rgb)
        map.channel = MapChannel::R;
    return map;
}

std::optional<glm::dvec4> pastedFactor(MapSlot from, const MaterialMap& copied, MapSlot to)
{
    if (kindOf(from) != kindOf(to))
        return std::nullopt;
    return copied.factor;
}

} // namespace facet
