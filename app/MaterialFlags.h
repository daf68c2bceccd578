#pragma once
// The material flags of `facet render` and `facet sheet`, one per row of the property registry
// that names a flag (core/material/MaterialProperties.h): --base-color r,g,b, --metallic V,
// --roughness V. Each sets that property of every material of the project, within the row's
// range ("--roughness: 1.5 is outside [0, 1]"). A property that gains a flag in the registry
// gains it here, in both commands, with its help text.

#include <QCommandLineOption>
#include <QCommandLineParser>
#include <QString>

#include <vector>

#include "core/material/Material.h"
#include "core/material/MaterialProperties.h"

namespace facet {

class MaterialFlags {
public:
    MaterialFlags();
    void addTo(QCommandLineParser& parser) const;
    // Applies the flags that are set to each of `materials`, in the registry's order. False with
    // *error naming the flag.
    bool apply(
        const QCommandLineParser& parser, const std::vector<Material*>& materials, QString* error) const;

private:
    struct Flag {
        MaterialProperty property;
        QCommandLineOption option;
    };
    std::vector<Flag> m_flags;
};

} // namespace facet
