#include "ui/DocumentChanges.h"

#include "core/Project.h"

#include <algorithm>

namespace facet {

namespace {

// Whether a map's texture must be (re)loaded: the file or how its numbers are decoded.
bool sameTexture(const MaterialMap& a, const MaterialMap& b)
{
    return a.path == b.path && a.colorSpace == b.colorSpace;
}

DocumentChanges materialChanges(const Material& a, const Material& b)
{
    DocumentChanges changes;
    for (MapSlot slot : kAllMapSlots) {
        if (!sameTexture(a.map(slot), b.map(slot)))
            changes |= DocumentChange::MaterialMaps;
        MaterialMap aRest = a.map(slot);
        MaterialMap bRest = b.map(slot);
        aRest.path = bRest.path;
        aRest.colorSpace = bRest.colorSpace;
        if (aRest != bRest)
            changes |= DocumentChange::MaterialFactors;
    }
    if (a.name != b.name || a.ior != b.ior || a.emissiveStrength != b.emissiveStrength || a.alphaMode != b.alphaMode
        || a.alphaCutoff != b.alphaCutoff || a.doubleSided != b.doubleSided)
        changes |= DocumentChange::MaterialFactors;
    if (a.shading != b.shading)
        changes |= DocumentChange::Shading;
    return changes;
}

} // namespace

DocumentChanges changesBetween(const Project& before, const Project& after)
{
    DocumentChanges changes;
    if (before.materials.size() != after.materials.size())
        changes |= DocumentChange::MaterialFactors | DocumentChange::MaterialMaps | DocumentChange::Shading;
    for (std::size_t m = 0; m < std::min(before.materials.size(), after.materials.size()); ++m)
        changes |= materialChanges(before.materials[m], after.materials[m]);
    if (before.currentMaterial != after.currentMaterial)
        changes |= DocumentChange::CurrentMaterial;
    if (before.parts != after.parts)
        changes |= DocumentChange::Parts;
    if (before.compare != after.compare)
        changes |= DocumentChange::Compare;

    const EnvironmentSettings& ea = before.environment;
    const EnvironmentSettings& eb = after.environment;
    if (ea.source != eb.source)
        changes |= DocumentChange::EnvironmentSource;
    if (ea.rotationDegrees != eb.rotationDegrees)
        changes |= DocumentChange::EnvironmentRotation;
    if (ea.intensity != eb.intensity)
        changes |= DocumentChange::EnvironmentIntensity;
    if (ea.quality != eb.quality)
        changes |= DocumentChange::IblQuality;

    if (before.lights != after.lights)
        changes |= DocumentChange::Lights;
    if (before.camera != after.camera)
        changes |= DocumentChange::Camera;
    if (before.view.mesh != after.view.mesh)
        changes |= DocumentChange::Mesh;
    ViewSettings va = before.view;
    va.mesh = after.view.mesh;
    if (va != after.view)
        changes |= DocumentChange::View;
    return changes;
}

} // namespace facet
