#pragma once
// Materials as objects of a project (issue 30): adding, duplicating and deleting one keeps every
// reference to the others pointing at the same material: the mesh parts (MeshPart::material),
// the current material and the A/B comparison's B (CompareLayout::insertMaterial,
// removeMaterial). The window's Materials dock makes each an undo step (ui/MaterialsDock.h);
// docs/app.md, "Materials".

#include <optional>
#include <string>

#include "core/Project.h"

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

} // namespace facet
