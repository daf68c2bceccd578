#pragma once
// Reading a material's JSON object into a Material, for core/project/Project.cpp's project reader (the
// public pair, materialToJson / materialFromJson, is declared in core/project/Project.h). Internal to core/.

#include "core/json/JsonReader.h"
#include "core/material/Material.h"

#include <QJsonObject>

#include <string>

namespace facet {

// Reads `object` (at JSON path `path`) into `material`: known keys over its values, relative
// texture paths resolved against `baseDir`; problems and unknown keys into `messages`.
void readMaterial(jsonsupport::Messages& messages, const QJsonObject& object, const std::string& path,
    const std::string& baseDir, Material& material);

} // namespace facet
