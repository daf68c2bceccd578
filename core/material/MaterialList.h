#pragma once
// Materials as objects of a project (issue 30): adding, duplicating and deleting one keeps every
// reference to the others pointing at the same material: the mesh parts (MeshPart::material),
// the current material and the A/B comparison's B (CompareLayout::insertMaterial,
// removeMaterial). The window's Materials dock makes each an undo step (ui/docks/MaterialsDock.h);
// docs/app.md, "Materials".

#include <optional>
#include <string>

#include "core/project/Project.h"

namespace facet {

// `base` if no material of `project` is called so, else "base 2", "base 3", ... (the first free).
std::string uniqueMaterialName(const Project& project, const std::string& base);

// `project` with `material` inserted at `index` (clamped to [0, size]) under a name no other
// material has (uniqueMaterialName of its own), made current. nullopt with *problem when the
// project already holds Project::kMaxMaterials.
std::optional<Project> withMaterialInserted(
    Project project, int index, Material material, std::string* problem = nullptr);

// A copy of material `index` ("<name> copy", made unique) right after it, made current.
std::optional<Project> withMaterialDuplicated(
    const Project& project, int index, std::string* problem = nullptr);

// `project` without material `index`. The parts that showed it show the material before it (the
// first when it was the first), which becomes current; a B that showed it keeps it as a snapshot.
// nullopt with *problem for the last material (a project has at least one) or an index out of
// range.
std::optional<Project> withMaterialRemoved(Project project, int index, std::string* problem = nullptr);

// One map's copy pasted into another slot (the Texture Maps dock's Copy Map / Paste Map): the
// file and how it is read (channel, UV transform, texture coordinates, sampler) and, between
// slots of one kind (colour: base colour, emissive, sheen colour; normal; scalar: metallic,
// roughness, occlusion, ...), its factor, colour space, invert and green flip. Across kinds the
// target keeps its factor and takes its own default colour space, and what the target cannot have
// is left out: a normal, emissive or sheen colour map reads "rgb" (readsRgbOnly), a scalar one a
// single channel ("r" for a copied "rgb"),
// invert only between scalar slots, the DirectX flip only between normal maps. The result
// passes Material::validate.
MaterialMap pastedMap(MapSlot from, const MaterialMap& copied, MapSlot to, const MaterialMap& target);
// The copied factor for `to` (Paste Value), only between slots of one kind; nullopt otherwise.
std::optional<glm::dvec4> pastedFactor(MapSlot from, const MaterialMap& copied, MapSlot to);

} // namespace facet
