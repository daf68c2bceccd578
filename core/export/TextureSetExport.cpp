#include "core/export/TextureSetExport.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <future>
#include <set>
#include <system_error>

#include "core/image/ImageCodec.h"
#include "core/image/ImageWriter.h"
#include "core/image/MapImageCache.h"
#include "core/image/ToneMap.h"
#include "core/support/Parallel.h"

namespace facet {

namespace {

const MapImage* imageOf(const Material& material, const MaterialMapImages& images, MapSlot slot)
{
    const MapImage* image = images[std::size_t(slot)];
    return material.map(slot).hasTexture() && image && !image->isEmpty() ? image : nullptr;
}

std::string sizeText(int width, int height)
{
    return width == height ? std::to_string(width) : std::to_string(width) + "x" + std::to_string(height);
}

FileSampleFormat sampleFormatOf(const ExportOutput& output)
{
    if (output.bitDepth == 32)
        return FileSampleFormat::Float;
    if (output.bitDepth == 16)
        return output.fileFormat == TextureFileFormat::Exr ? FileSampleFormat::Half
                                                           : FileSampleFormat::UInt16;
    return FileSampleFormat::UInt8;
}

// Whether channel `index` of a file of `count` channels is alpha: the last of 2 or 4.
bool isAlphaChannel(int index, int count)
{
    return (count == 2 || count == 4) && index == count - 1;
}

const char* channelLetter(int index, int count)
{
    if (count <= 2)
        return index == 0 ? "Y" : "A";
    static const char* const kLetters[] = {"R", "G", "B", "A"};
    return kLetters[index];
}

} // namespace

ExportTexel exportTexel(const Material& material, const MaterialMapImages& images, const glm::dvec2& uv)
{
    using P = MaterialProperty;
    // materialInputs is the shader's CPU twin: the same factors, picks and decoding.
    const MaterialInfo inputs = materialInputs(material, images, uv);
    ExportTexel texel;
    texel[P::BaseColor] = glm::dvec4(inputs.baseColor, 1.0);
    texel[P::Alpha] = glm::dvec4(inputs.alpha);
    texel[P::Metallic] = glm::dvec4(inputs.metallic);
    texel[P::Roughness] = glm::dvec4(inputs.perceptualRoughness);
    texel[P::Occlusion] = glm::dvec4(inputs.occlusion);
    texel[P::Clearcoat] = glm::dvec4(inputs.clearcoat);
    texel[P::ClearcoatRoughness] = glm::dvec4(inputs.clearcoatRoughness);
    texel[P::SheenColor] = glm::dvec4(inputs.sheenColor, 1.0);
    texel[P::SheenRoughness] = glm::dvec4(inputs.sheenRoughness);
    texel[P::Specular] = glm::dvec4(inputs.specular);
    texel[P::SpecularColor] = glm::dvec4(inputs.specularColor, 1.0);
    texel[P::Anisotropy] = glm::dvec4(inputs.anisotropy);
    texel[P::AnisotropyRotation] = glm::dvec4(inputs.anisotropyTangentDirection, 0.0, 0.0);
    texel[P::Iridescence] = glm::dvec4(inputs.iridescence);
    // The thickness texture's value back from the thickness it made (mix(minimum, maximum, g)).
    const double thicknessSpan = material.iridescenceThicknessMaximum() - material.iridescenceThicknessMinimum;
    texel[P::IridescenceThickness] = glm::dvec4(material.hasIridescence() && thicknessSpan != 0.0
            ? std::clamp((inputs.iridescenceThickness - material.iridescenceThicknessMinimum) / thicknessSpan,
                0.0, 1.0)
            : 1.0);
    // The emissive strength stays a parameter of the material, not a texel value.
    glm::dvec3 emissive;
    if (material.emissiveStrength > 0.0) {
        emissive = inputs.emissive / material.emissiveStrength;
    } else {
        emissive = glm::dvec3(material.map(MapSlot::Emissive).factor);
        const MaterialMap& emissiveMap = material.map(MapSlot::Emissive);
        if (const MapImage* image = imageOf(material, images, MapSlot::Emissive))
            emissive *= glm::dvec3(sampleMap(emissiveMap, *image, TexCoords {uv, uv}));
        emissive = glm::max(emissive, glm::dvec3(0.0));
    }
    texel[P::Emissive] = glm::dvec4(emissive, 1.0);
    const auto normalOf = [&](MapSlot slot) {
        const MaterialMap& map = material.map(slot);
        const MapImage* image = material.usesSlot(slot) ? imageOf(material, images, slot) : nullptr;
        return image
            ? tangentSpaceNormal(sampleMap(map, *image, TexCoords {uv, uv}), map.factor.x, map.flipGreen)
            : glm::dvec3(0.0, 0.0, 1.0);
    };
    texel[P::Normal] = glm::dvec4(normalOf(MapSlot::Normal), 0.0);
    texel[P::ClearcoatNormal] = glm::dvec4(normalOf(MapSlot::ClearcoatNormal), 0.0);
    return texel;
}

double channelValue(const ExportChannel& channel, const ExportTexel& texel)
{
    double value = channel.constant;
    if (channel.source) {
        value = texel[channel.source->property][channel.source->component];
        // A unit vector's components (the export field's "xyz", "xy") are stored as v * 0.5 + 0.5.
        if (std::string_view(infoOf(channel.source->property).exportField.components).starts_with('x'))
            value = value * 0.5 + 0.5;
    }
    return channel.invert ? 1.0 - value : value;
}

bool slotHasContent(const Material& material, MapSlot slot)
{
    if (!material.usesSlot(slot))
        return false;
    switch (slot) {
    case MapSlot::BaseColor:
    case MapSlot::Metallic:
    case MapSlot::Roughness:
    case MapSlot::Clearcoat: // in use: the coat is on
    case MapSlot::ClearcoatRoughness:
    case MapSlot::SheenColor: // in use: the sheen is on
    case MapSlot::SheenRoughness:
    case MapSlot::Specular: // in use: the layer is not the default
    case MapSlot::SpecularColor:
    case MapSlot::Anisotropy: // in use: the strength is above 0
    case MapSlot::Iridescence:
        return true;
    case MapSlot::IridescenceThickness: // a thickness of its own only with a texture
        break;
    case MapSlot::Emissive:
        return material.map(slot).hasTexture() || glm::dvec3(material.map(slot).factor) != glm::dvec3(0.0);
    case MapSlot::Normal:
    case MapSlot::Occlusion:
    case MapSlot::ClearcoatNormal:
        break;
    }
    return material.map(slot).hasTexture();
}

std::optional<MapSlot> slotOf(const ExportSource& source)
{
    const MaterialPropertyInfo& info = infoOf(source.property);
    return info.exportField.slot ? info.exportField.slot : info.slot;
}

bool usesSource(const Material& material, const ExportSource& source)
{
    const std::optional<MapSlot> slot = slotOf(source);
    return slot && slotHasContent(material, *slot);
}

std::optional<TextureSetPlan> planTextureSet(const ExportTemplate& exportTemplate, const Material& material,
    const MaterialMapImages& images, const TextureSetOptions& options, std::string* error)
{
    const auto fail = [error](const std::string& problem) {
        if (error)
            *error = problem;
        return std::nullopt;
    };
    if (options.size < 0 || options.size > TextureSetOptions::kMaxSize)
        return fail("the size " + std::to_string(options.size) + " is outside 1 to "
            + std::to_string(TextureSetOptions::kMaxSize));
    TextureSetPlan plan;
    plan.templateId = exportTemplate.id;
    plan.materialName = material.name;
    for (const MapSlot slot : kAllMapSlots) {
        if (const MapImage* image = imageOf(material, images, slot)) {
            plan.sourceWidth = std::max(plan.sourceWidth, image->width());
            plan.sourceHeight = std::max(plan.sourceHeight, image->height());
        }
    }
    int width = plan.sourceWidth;
    int height = plan.sourceHeight;
    if (options.size > 0) {
        const double scale = double(options.size) / double(std::max(width, height));
        width = std::max(1, int(std::lround(width * scale)));
        height = std::max(1, int(std::lround(height * scale)));
    }

    std::set<std::string> names;
    for (const ExportOutput& output : exportTemplate.outputs) {
        if (output.optional) {
            bool used = false;
            for (const ExportChannel& channel : output.channels)
                used = used || (channel.source && usesSource(material, *channel.source));
            if (!used) {
                plan.skipped.push_back(output.map);
                continue;
            }
        }
        PlannedTexture texture;
        texture.output = output;
        if (options.bitDepth != 0) {
            if (!holdsBitDepth(output.fileFormat, options.bitDepth))
                return fail(exportTemplate.id + "'s " + output.map + " is " + toString(output.fileFormat)
                    + ", which cannot hold " + std::to_string(options.bitDepth)
                    + "-bit channels (png: 8, 16; tga: 8; tiff: 8, 16, 32; exr: 16, 32)");
            texture.output.bitDepth = options.bitDepth;
        }
        texture.width = width;
        texture.height = height;
        std::string stem;
        std::string problem;
        if (!expandFileName(output.fileName.empty() ? exportTemplate.fileName : output.fileName,
                fileNameSafe(material.name), output.map, sizeText(width, height), exportTemplate.id, &stem,
                &problem))
            return fail(exportTemplate.id + "'s " + output.map + ": " + problem);
        texture.fileName = stem + "." + extension(output.fileFormat);
        if (!names.insert(texture.fileName).second)
            return fail(exportTemplate.id + " names two files " + texture.fileName
                + " (give each output its own {map} or fileName)");
        plan.files.push_back(std::move(texture));
    }
    return plan;
}

std::string describe(const PlannedTexture& texture)
{
    const ExportOutput& output = texture.output;
    const int count = int(output.channels.size());
    static const char* const kLayouts[] = {"grey", "grey+alpha", "RGB", "RGBA"};
    std::string text = texture.fileName + "  " + std::to_string(texture.width) + "x"
        + std::to_string(texture.height) + "  " + kLayouts[count - 1] + " " + toString(sampleFormatOf(output))
        + " " + (output.colorSpace == ColorEncoding::SRGB ? "sRGB" : "linear") + ":";
    for (int i = 0; i < count; ++i) {
        const ExportChannel& channel = output.channels[std::size_t(i)];
        std::string source = channel.source ? toString(*channel.source)
                                            : "constant " + std::to_string(channel.constant).substr(0, 5);
        if (channel.invert)
            source = "1 - " + source;
        text += std::string(i == 0 ? " " : ", ") + channelLetter(i, count) + " " + source;
    }
    return text;
}

// The file's values, linear. Empty with *error when the resize cannot be done (the image codec
// did not load).
std::vector<float> renderTexture(const PlannedTexture& texture, const TextureSetPlan& plan,
    const Material& material, const MaterialMapImages& images, std::string* error)
{
    const std::vector<ExportChannel>& channels = texture.output.channels;
    const int count = int(channels.size());
    // Only the maps this file reads are sampled: the others' textures are left out of the copy
    // the texels are evaluated from (an ORM file reads no base colour, normal or emissive).
    std::array<bool, kMapSlotCount> read {};
    for (const ExportChannel& channel : channels)
        if (const std::optional<MapSlot> slot = channel.source ? slotOf(*channel.source) : std::nullopt)
            read[std::size_t(*slot)] = true;
    Material needed = material;
    for (const MapSlot slot : kAllMapSlots)
        if (!read[std::size_t(slot)])
            needed.map(slot).path.clear();
    const int width = plan.sourceWidth;
    const int height = plan.sourceHeight;
    std::vector<float> values(std::size_t(width) * std::size_t(height) * std::size_t(count));
    parallelFor(std::size_t(height), [&](std::size_t row) {
        // Row 0 is the file's top row: texture coordinate v = 1 (core/image/MapImage.h).
        const double v = 1.0 - (double(row) + 0.5) / double(height);
        float* out = values.data() + row * std::size_t(width) * std::size_t(count);
        for (int x = 0; x < width; ++x) {
            const ExportTexel texel
                = exportTexel(needed, images, glm::dvec2((double(x) + 0.5) / double(width), v));
            for (int c = 0; c < count; ++c)
                *out++ = float(channelValue(channels[std::size_t(c)], texel));
        }
    });
    if (texture.width == width && texture.height == height)
        return values;

    // Resized as linear values, before any sRGB encoding: OIIO's default filters (a wide
    // Blackman-Harris going down, Lanczos going up).
    std::vector<float> result(std::size_t(texture.width) * std::size_t(texture.height) * std::size_t(count));
    std::string problem;
    const ImageCodec* codec = imageCodec(&problem);
    if (!codec
        || !codec->resize(
            values.data(), width, height, count, result.data(), texture.width, texture.height, &problem)) {
        *error = texture.fileName + ": resizing to " + std::to_string(texture.width) + "x"
            + std::to_string(texture.height) + ": " + problem;
        return {};
    }
    return result;
}

void encodeTexture(const PlannedTexture& texture, std::vector<float>& values)
{
    const ExportOutput& output = texture.output;
    if (output.colorSpace != ColorEncoding::SRGB)
        return;
    const int count = int(output.channels.size());
    for (int c = 0; c < count; ++c) {
        if (isAlphaChannel(c, count) || !output.channels[std::size_t(c)].source)
            continue;
        for (std::size_t i = std::size_t(c); i < values.size(); i += std::size_t(count))
            values[i] = float(tonemap::linearToSrgb(std::clamp(double(values[i]), 0.0, 1.0)));
    }
}

ImageFileSpec textureFileSpec(const PlannedTexture& texture)
{
    ImageFileSpec spec;
    spec.width = texture.width;
    spec.height = texture.height;
    spec.channels = int(texture.output.channels.size());
    spec.sampleFormat = sampleFormatOf(texture.output);
    spec.encoding = texture.output.colorSpace;
    spec.tagLinear = true;
    // Alpha only where the last channel is the base colour's coverage; a packed mask's fourth
    // channel (Unity's smoothness) is data.
    spec.alpha = (spec.channels == 2 || spec.channels == 4)
        && texture.output.channels.back().source == ExportSource {MaterialProperty::Alpha, 0};
    return spec;
}

bool writeTextureSet(const TextureSetPlan& plan, const Material& material, const MaterialMapImages& images,
    FileSet& files, std::string* error)
{
    // One file is encoded and written (OpenImageIO's PNG encoder is single-threaded: as long as
    // the render of a 2K file) while the next one renders on every core.
    std::string problem;
    const auto write = [&](const PlannedTexture& texture, std::vector<float> values) {
        const ImageFileSpec spec = textureFileSpec(texture);
        if (!writeImageFile(files.stagedPath(texture.fileName), spec, values.data(), "export", &problem)) {
            problem = files.named(problem);
            return false;
        }
        files.written(texture.fileName);
        return true;
    };
    std::future<bool> pending;
    for (const PlannedTexture& texture : plan.files) {
        std::string failure;
        std::vector<float> values = renderTexture(texture, plan, material, images, &failure);
        if (values.empty()) {
            if (pending.valid())
                pending.get();
            problem = failure;
            break;
        }
        encodeTexture(texture, values);
        if (pending.valid() && !pending.get())
            break;
        pending = std::async(std::launch::async, write, std::cref(texture), std::move(values));
    }
    if (pending.valid() && !pending.get()) {
        // "export: <path>: <reason>" -> "<path>: <reason>".
        if (error)
            *error = problem.starts_with("export: ") ? problem.substr(8) : problem;
        return false;
    }
    if (!problem.empty()) {
        if (error)
            *error = problem.starts_with("export: ") ? problem.substr(8) : problem;
        return false;
    }
    return true;
}

std::optional<TextureSetExport> TextureSetExport::prepare(const ExportTemplate& exportTemplate,
    const std::vector<Material>& materials, const TextureSetOptions& options, std::string* error)
{
    const auto fail = [error](const std::string& problem) {
        if (error)
            *error = problem;
        return std::nullopt;
    };
    TextureSetExport job;
    job.m_template = exportTemplate;
    std::set<std::string> names;
    for (const Material& material : materials) {
        auto source = std::make_shared<Source>();
        source->material = material;
        for (const MapSlot slot : kAllMapSlots) {
            const MaterialMap& map = material.map(slot);
            if (!map.hasTexture())
                continue;
            std::string problem;
            std::shared_ptr<const MapImage> image = MapImageCache::shared().load(map.path, &problem);
            if (!image)
                return fail("material '" + material.name + "', " + toString(slot) + ": " + problem);
            source->images[std::size_t(slot)] = image.get();
            source->keep.push_back(std::move(image));
        }
        std::string problem;
        std::optional<TextureSetPlan> plan
            = planTextureSet(exportTemplate, source->material, source->images, options, &problem);
        if (!plan)
            return fail("material '" + material.name + "': " + problem);
        for (const PlannedTexture& texture : plan->files)
            if (!names.insert(texture.fileName).second)
                return fail(texture.fileName
                    + " would hold two materials (two materials of one name? export them one at a time)");
        job.m_sources.push_back(std::move(source));
        job.m_plans.push_back(std::move(*plan));
    }
    return job;
}

std::vector<float> TextureSetExport::fileValues(std::size_t plan, std::size_t index, std::string* error) const
{
    const PlannedTexture& texture = m_plans[plan].files[index];
    std::vector<float> values
        = renderTexture(texture, m_plans[plan], m_sources[plan]->material, m_sources[plan]->images, error);
    encodeTexture(texture, values);
    return values;
}

std::vector<std::string> TextureSetExport::fileNames() const
{
    std::vector<std::string> names;
    for (const TextureSetPlan& plan : m_plans)
        for (const PlannedTexture& texture : plan.files)
            names.push_back(texture.fileName);
    return names;
}

std::string TextureSetExport::describeAll() const
{
    std::string text;
    for (const TextureSetPlan& plan : m_plans) {
        text += plan.materialName + " (" + m_template.name + "): " + std::to_string(plan.files.size())
            + " files\n";
        for (const PlannedTexture& texture : plan.files)
            text += "  " + describe(texture) + "\n";
        for (const std::string& skipped : plan.skipped)
            text += "  (no " + skipped + ": the material does not use it)\n";
    }
    return text;
}

bool TextureSetExport::write(
    const std::string& folder, bool replace, std::string* error, std::vector<std::string>* written) const
{
    const auto fail = [error](const std::string& problem) {
        if (error)
            *error = problem;
        return false;
    };
    std::error_code code;
    const std::filesystem::path path(folder);
    if (std::filesystem::exists(path, code) && !std::filesystem::is_directory(path, code))
        return fail(folder + ": is not a folder");
    std::filesystem::create_directories(path, code);
    if (code || !std::filesystem::is_directory(path, code))
        return fail(folder + ": cannot make the folder" + (code ? ": " + code.message() : std::string()));
    // All or nothing (core/support/FileSet.h): a set replaced with --force is either the whole new set or
    // the old one, also when the disk fills midway.
    FileSet files(folder);
    if (!replace)
        if (const std::vector<std::string> existing = files.existing(fileNames()); !existing.empty())
            return fail(existing.front() + ": exists");
    std::string problem;
    if (!files.begin(&problem))
        return fail(folder + ": " + problem);
    for (std::size_t i = 0; i < m_plans.size(); ++i)
        if (!writeTextureSet(m_plans[i], m_sources[i]->material, m_sources[i]->images, files, error))
            return false; // the set's destructor removes what was staged
    if (!files.commit(&problem))
        return fail(problem);
    if (written)
        *written = files.writtenPaths();
    return true;
}

} // namespace facet
