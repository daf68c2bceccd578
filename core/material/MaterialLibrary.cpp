#include "core/material/MaterialLibrary.h"

#include <charconv>
#include <string>
#include <vector>

#include "core/project/Project.h"

namespace facet {

namespace {
// Enough names for a person to see the spelling; a big glTF asset has hundreds.
constexpr std::size_t kNamesListed = 8;

bool isIndex(std::string_view selector)
{
    if (selector.empty())
        return false;
    for (char c : selector)
        if (c < '0' || c > '9')
            return false;
    return true;
}
} // namespace

std::optional<int> findMaterial(const Project& project, std::string_view selector, std::string* error)
{
    const auto failed = [&](const std::string& problem) {
        if (error)
            *error = "findMaterial: " + problem;
        return std::nullopt;
    };
    const std::size_t count = project.materials.size();
    if (selector.empty())
        return failed("empty selector (expected a material's name or index)");
    if (isIndex(selector)) {
        std::size_t index = 0;
        const auto [end, problem]
            = std::from_chars(selector.data(), selector.data() + selector.size(), index);
        if (problem != std::errc() || end != selector.data() + selector.size() || index >= count)
            return failed("index " + std::string(selector) + " is not a material (there are "
                + std::to_string(count) + ", from 0)");
        return int(index);
    }
    std::vector<std::size_t> matches;
    for (std::size_t i = 0; i < count; ++i)
        if (project.materials[i].name == selector)
            matches.push_back(i);
    if (matches.size() == 1)
        return int(matches.front());
    if (matches.empty()) {
        std::string names;
        for (std::size_t i = 0; i < count && i < kNamesListed; ++i)
            names += (i == 0 ? "\"" : ", \"") + project.materials[i].name + "\"";
        if (count > kNamesListed)
            names += " and " + std::to_string(count - kNamesListed) + " more";
        return failed(
            "no material is named \"" + std::string(selector) + "\" (the materials: " + names + ")");
    }
    std::string indices;
    for (std::size_t i : matches)
        indices += (indices.empty() ? "" : ", ") + std::to_string(i);
    return failed(std::to_string(matches.size()) + " materials are named \"" + std::string(selector)
        + "\" (indices " + indices + "): name one by its index");
}

std::string unusedMaterialName(const Project& project, const std::string& base)
{
    const auto taken = [&](const std::string& name) {
        for (const Material& material : project.materials)
            if (material.name == name)
                return true;
        return false;
    };
    if (!taken(base))
        return base;
    // At most materials.size() + 1 candidates: one of them is free.
    for (std::size_t n = 2;; ++n)
        if (const std::string name = base + " " + std::to_string(n); !taken(name))
            return name;
}

} // namespace facet
