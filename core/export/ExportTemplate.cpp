#include "core/export/ExportTemplate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>

#include "core/json/JsonReader.h"
#include "core/project/Project.h" // json::checkFormat, json::readObjectFile

namespace facet {

using namespace jsonsupport;

namespace {

constexpr std::array<std::pair<TextureFileFormat, const char*>, 4> kFormats = {{
    {TextureFileFormat::Png, "png"},
    {TextureFileFormat::Tga, "tga"},
    {TextureFileFormat::Tiff, "tiff"},
    {TextureFileFormat::Exr, "exr"},
}};

constexpr std::array<std::pair<ColorEncoding, const char*>, 2> kColorSpaces = {{
    {ColorEncoding::SRGB, "srgb"},
    {ColorEncoding::Linear, "linear"},
}};

constexpr std::array<const char*, 4> kTokens = {"material", "map", "size", "template"};

// The source names for messages: "baseColor.r, baseColor.g, ..." (not "constant": a number is).
std::string sourceList()
{
    std::string list;
    for (const ExportSource& source : exportSources())
        list += (list.empty() ? "" : ", ") + toString(source);
    return list;
}

// Unknown keys are errors in a template: a misspelt "colourSpace" would otherwise quietly write
// linear files where sRGB was meant.
void refuseUnknownKeys(Messages& messages, ObjectReader& reader)
{
    const std::size_t before = messages.warnings.size();
    reader.warnAboutUnknownKeys();
    if (messages.warnings.size() > before) {
        std::string warning = messages.warnings[before];
        const std::string suffix = ", ignored";
        if (warning.size() > suffix.size() && warning.ends_with(suffix))
            warning.resize(warning.size() - suffix.size());
        messages.failWith(warning);
    }
    messages.warnings.resize(before);
}

bool checkPattern(const std::string& pattern, std::string* problem)
{
    std::string ignored;
    if (!expandFileName(pattern, "m", "m", "1", "t", &ignored, problem))
        return false;
    if (pattern.empty())
        return fail("is empty", problem);
    if (pattern.find('/') != std::string::npos || pattern.find('\\') != std::string::npos)
        return fail(
            "\"" + pattern + "\" holds a folder separator: a file name is a name, not a path", problem);
    return true;
}

std::optional<ExportChannel> readChannel(const QJsonValue& value, const std::string& path, Messages& messages)
{
    ExportChannel channel;
    if (value.isDouble()) {
        const double constant = value.toDouble();
        if (!(constant >= 0.0 && constant <= 1.0)) {
            messages.fail(path, "the constant " + jsonsupport::number(constant) + " is outside [0, 1]");
            return std::nullopt;
        }
        channel.constant = constant;
        return channel;
    }
    std::string sourceName;
    if (value.isString()) {
        sourceName = ss(value.toString());
    } else if (value.isObject()) {
        ObjectReader reader(messages, value.toObject(), path);
        reader.string("source", sourceName);
        reader.boolean("invert", channel.invert);
        refuseUnknownKeys(messages, reader);
        if (messages.failed())
            return std::nullopt;
        if (sourceName.empty()) {
            messages.fail(path + ".source", "is missing");
            return std::nullopt;
        }
    } else {
        messages.fail(path,
            std::string("expected a source name, a constant or {\"source\", \"invert\"}, got ")
                + typeName(value));
        return std::nullopt;
    }
    const std::optional<ExportSource> source = exportSourceFromString(sourceName);
    if (!source) {
        messages.fail(path, "\"" + sourceName + "\" is not a source (" + sourceList() + ", or a number)");
        return std::nullopt;
    }
    channel.source = source;
    return channel;
}

std::optional<ExportOutput> readOutput(
    const QJsonValue& value, const std::string& path, const std::string& templatePattern, Messages& messages)
{
    if (!value.isObject()) {
        messages.fail(path, std::string("expected an object, got ") + typeName(value));
        return std::nullopt;
    }
    ObjectReader reader(messages, value.toObject(), path);
    ExportOutput output;
    reader.string("map", output.map);
    reader.string("fileName", output.fileName);
    reader.enumeration("colorSpace", output.colorSpace, kColorSpaces);
    reader.integer("bitDepth", output.bitDepth);
    reader.enumeration("fileFormat", output.fileFormat, kFormats);
    reader.boolean("optional", output.optional);
    const std::optional<QJsonArray> channels = reader.array("channels");
    refuseUnknownKeys(messages, reader);
    if (messages.failed())
        return std::nullopt;
    if (output.map.empty()) {
        messages.fail(path + ".map", "is missing (the {map} token's value, e.g. \"BaseColor\")");
        return std::nullopt;
    }
    if (!channels) {
        messages.fail(path + ".channels", "is missing");
        return std::nullopt;
    }
    if (channels->isEmpty() || channels->size() > 4) {
        messages.fail(path + ".channels",
            "has " + std::to_string(channels->size()) + " entries; a file has 1 to 4 channels");
        return std::nullopt;
    }
    for (qsizetype i = 0; i < channels->size(); ++i) {
        const std::optional<ExportChannel> channel
            = readChannel(channels->at(i), path + ".channels[" + std::to_string(i) + "]", messages);
        if (!channel)
            return std::nullopt;
        output.channels.push_back(*channel);
    }
    if (output.bitDepth != 8 && output.bitDepth != 16 && output.bitDepth != 32) {
        messages.fail(path + ".bitDepth", std::to_string(output.bitDepth) + " is not 8, 16 or 32");
        return std::nullopt;
    }
    if (!holdsBitDepth(output.fileFormat, output.bitDepth)) {
        messages.fail(path + ".bitDepth",
            std::string(toString(output.fileFormat)) + " files cannot hold " + std::to_string(output.bitDepth)
                + "-bit channels (png: 8, 16; tga: 8; tiff: 8, 16, 32; exr: 16, 32)");
        return std::nullopt;
    }
    std::string problem;
    if (!checkPattern(output.fileName.empty() ? templatePattern : output.fileName, &problem)) {
        messages.fail(path + (output.fileName.empty() ? " (the template's fileName)" : ".fileName"), problem);
        return std::nullopt;
    }
    return output;
}

} // namespace

std::string toString(const ExportSource& source)
{
    const ExportField& field = infoOf(source.property).exportField;
    std::string name = field.source ? field.source : "";
    if (std::string_view components = field.components; !components.empty())
        name += std::string(".") + components[std::size_t(source.component)];
    return name;
}

std::optional<ExportSource> exportSourceFromString(std::string_view name)
{
    for (const ExportSource& source : exportSources())
        if (toString(source) == name)
            return source;
    return std::nullopt;
}

std::vector<ExportSource> exportSources()
{
    std::vector<ExportSource> sources;
    for (const MaterialPropertyInfo& info : materialProperties()) {
        if (!info.exportField.source)
            continue;
        const int count = std::max(1, int(std::string_view(info.exportField.components).size()));
        for (int component = 0; component < count; ++component)
            sources.push_back({info.property, component});
    }
    return sources;
}

const char* toString(TextureFileFormat format)
{
    for (const auto& [candidate, name] : kFormats)
        if (candidate == format)
            return name;
    return "png";
}

const char* extension(TextureFileFormat format)
{
    return format == TextureFileFormat::Tiff ? "tif" : toString(format);
}

std::optional<TextureFileFormat> textureFileFormatFromString(std::string_view name)
{
    for (const auto& [format, text] : kFormats)
        if (name == text)
            return format;
    return std::nullopt;
}

bool holdsBitDepth(TextureFileFormat format, int bitDepth)
{
    switch (format) {
    case TextureFileFormat::Png:
        return bitDepth == 8 || bitDepth == 16;
    case TextureFileFormat::Tga:
        return bitDepth == 8;
    case TextureFileFormat::Tiff:
        return bitDepth == 8 || bitDepth == 16 || bitDepth == 32;
    case TextureFileFormat::Exr:
        return bitDepth == 16 || bitDepth == 32;
    }
    return false;
}

bool expandFileName(const std::string& pattern, const std::string& material, const std::string& map,
    const std::string& size, const std::string& templateId, std::string* out, std::string* error)
{
    std::string result;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        const char c = pattern[i];
        if (c == '}')
            return fail("\"" + pattern + "\": a '}' without its '{'", error);
        if (c != '{') {
            result += c;
            continue;
        }
        const std::size_t close = pattern.find('}', i);
        if (close == std::string::npos)
            return fail("\"" + pattern + "\": a '{' without its '}'", error);
        const std::string token = pattern.substr(i + 1, close - i - 1);
        if (token == "material")
            result += material;
        else if (token == "map")
            result += map;
        else if (token == "size")
            result += size;
        else if (token == "template")
            result += templateId;
        else {
            std::string known;
            for (const char* name : kTokens)
                known += (known.empty() ? "{" : ", {") + std::string(name) + "}";
            return fail("\"" + pattern + "\": unknown token {" + token + "} (known: " + known + ")", error);
        }
        i = close;
    }
    if (out)
        *out = result;
    return true;
}

std::string fileNameSafe(std::string_view name)
{
    std::string safe;
    bool replaced = false;
    for (const char c : name) {
        const bool keep = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9')
            || c == '-' || c == '_' || c == '.';
        if (keep) {
            safe += c;
            replaced = false;
        } else if (!replaced) {
            safe += '_';
            replaced = true;
        }
    }
    while (!safe.empty() && safe.front() == '.')
        safe.erase(safe.begin());
    return safe.empty() ? std::string("Material") : safe;
}

std::optional<ExportTemplate> ExportTemplate::fromJson(const QJsonObject& object, std::string* error)
{
    if (!json::checkFormat(object, kFormatName, kFormatVersion, "an export template", error))
        return std::nullopt;
    Messages messages;
    ObjectReader reader(messages, object, std::string());
    reader.value("format");
    reader.value("version");
    ExportTemplate result;
    reader.string("name", result.name);
    reader.string("fileName", result.fileName);
    const std::optional<QJsonArray> outputs = reader.array("outputs");
    refuseUnknownKeys(messages, reader);
    if (!messages.failed() && (!outputs || outputs->isEmpty()))
        messages.fail("outputs", "is missing or empty: a template writes at least one file");
    if (!messages.failed() && outputs->size() > kMaxOutputs)
        messages.fail("outputs",
            "has " + std::to_string(outputs->size()) + " files; a template writes at most "
                + std::to_string(kMaxOutputs));
    if (!messages.failed()) {
        for (qsizetype i = 0; i < outputs->size(); ++i) {
            const std::optional<ExportOutput> output
                = readOutput(outputs->at(i), "outputs[" + std::to_string(i) + "]", result.fileName, messages);
            if (!output)
                break;
            result.outputs.push_back(*output);
        }
    }
    if (messages.failed())
        return failed(messages.error, error);
    return result;
}

std::optional<ExportTemplate> ExportTemplate::load(const std::string& path, std::string* error)
{
    std::string problem;
    constexpr qint64 kMaxBytes = 1 << 20; // a template is a few KiB
    const std::optional<QJsonObject> object = json::readObjectFile(path, kMaxBytes, &problem);
    std::optional<ExportTemplate> result = object ? fromJson(*object, &problem) : std::nullopt;
    if (!result)
        return failed(path + ": " + problem, error);
    result->id = ss(QFileInfo(qs(path)).completeBaseName());
    if (result->name.empty())
        result->name = result->id;
    return result;
}

const std::vector<std::string>& ExportTemplate::builtinIds()
{
    static const std::vector<std::string> ids
        = {"gltf-textures", "godot", "unity-hdrp", "unity-urp", "unreal"};
    return ids;
}

std::optional<ExportTemplate> ExportTemplate::builtin(std::string_view id)
{
    bool known = false;
    for (const std::string& candidate : builtinIds())
        known = known || candidate == id;
    if (!known)
        return std::nullopt;
    // resources/export/<id>.json, compiled into facet_core (core/CMakeLists.txt).
    QFile file(QStringLiteral(":/export/%1.json").arg(qs(std::string(id))));
    if (!file.open(QIODevice::ReadOnly))
        return std::nullopt;
    const QJsonDocument document = QJsonDocument::fromJson(file.readAll());
    std::string problem;
    std::optional<ExportTemplate> result = fromJson(document.object(), &problem);
    // The built-ins are checked by tests (TextureSetExportTest): a broken one is a build defect.
    Q_ASSERT_X(result, "ExportTemplate::builtin", problem.c_str());
    if (result) {
        result->id = std::string(id);
        if (result->name.empty())
            result->name = result->id;
    }
    return result;
}

} // namespace facet
