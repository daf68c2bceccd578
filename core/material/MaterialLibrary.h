#pragma once
// The project's material library (Project::materials, one of them current): finding a material by
// name or index, and naming new ones. docs/project-format.md, "materials".
//
// Names need not be unique, and Facet does not make them so: a glTF asset's materials may share a
// name (importing keeps the asset's names, so that exporting gives them back), and unnamed ones are
// called "Material N", which a named one may also be called. Lookups by name therefore refuse a
// name that several materials have, and point at the indices.

#include <optional>
#include <string>
#include <string_view>

namespace facet {

struct Project;

// The index of the material `selector` names in `project`, for `facet sheet PROJECT.json#SELECTOR`
// and the like: a selector of decimal digits only is an index (from 0), whatever the names;
// anything else is a name, matched exactly (case-sensitive). A name that more than one material
// has is refused, listing their indices, so that the index picks one. On failure nullopt and
// *error, e.g.
//   findMaterial: no material is named "Steel" (the materials: "Shell", "Visor")
//   findMaterial: 2 materials are named "Trim" (indices 1, 4): name one by its index
//   findMaterial: index 5 is not a material (there are 3, from 0)
//   findMaterial: empty selector (expected a material's name or index)
std::optional<int> findMaterial(const Project& project, std::string_view selector, std::string* error);

// `base` when no material of `project` has that name, else "base 2", "base 3", ... (the first
// free one): for the window's new materials and snapshots kept as materials.
std::string unusedMaterialName(const Project& project, const std::string& base);

} // namespace facet
