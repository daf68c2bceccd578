#include "core/material/MapNaming.h"

#include <QDir>
#include <QFileInfo>
#include <QRegularExpression>

#include <algorithm>
#include <array>
#include <tuple>

namespace facet {

namespace {

// What a name can say a file is. Each has its reads (TextureNaming) below.
enum class Layout {
    BaseColor,
    Normal,
    NormalOpenGl,
    NormalDirectX,
    Metallic,
    Roughness,
    Gloss,
    Occlusion,
    Orm,
    GltfMetallicRoughness,
    UnityMaskMap,
    UnityMetallicSmoothness,
    Mra,
    Rma,
    Emissive,
    Clearcoat,
    ClearcoatRoughness,
    ClearcoatNormal,
    PackedClearcoat, // R the coat's strength, G its roughness (KHR_materials_clearcoat's channels)
    SheenColor,
    SheenRoughness,
    SpecularColor,
    Anisotropy, // KHR_materials_anisotropy's texture: direction RG, strength B
    Iridescence, // R the film's strength, G its thickness (KHR_materials_iridescence's channels)
    IridescenceThickness, // the film's thickness alone (G)
};

MapRead scalar(MapSlot slot, MapChannel channel, bool invert = false)
{
    return MapRead {slot, channel, invert, std::nullopt};
}

TextureNaming single(MapRead read)
{
    return TextureNaming {{read}, QString()};
}

TextureNaming packed(const char* convention, std::vector<MapRead> reads)
{
    std::sort(reads.begin(), reads.end(), [](const MapRead& a, const MapRead& b) { return a.slot < b.slot; });
    return TextureNaming {std::move(reads), QString::fromLatin1(convention)};
}

TextureNaming namingOf(Layout layout)
{
    using S = MapSlot;
    using C = MapChannel;
    switch (layout) {
    case Layout::BaseColor:
        return single(scalar(S::BaseColor, C::Rgb));
    case Layout::Normal:
        return single(MapRead {S::Normal, C::Rgb, false, std::nullopt});
    case Layout::NormalOpenGl:
        return single(MapRead {S::Normal, C::Rgb, false, false});
    case Layout::NormalDirectX:
        return single(MapRead {S::Normal, C::Rgb, false, true});
    case Layout::Metallic:
        return single(scalar(S::Metallic, C::R));
    case Layout::Roughness:
        return single(scalar(S::Roughness, C::R));
    case Layout::Gloss:
        return single(scalar(S::Roughness, C::R, true));
    case Layout::Occlusion:
        return single(scalar(S::Occlusion, C::R));
    case Layout::Orm:
        return packed(
            "ORM", {scalar(S::Occlusion, C::R), scalar(S::Roughness, C::G), scalar(S::Metallic, C::B)});
    case Layout::GltfMetallicRoughness:
        // glTF 2.0, material.pbrMetallicRoughness.metallicRoughnessTexture: "The metalness values
        // are sampled from the B channel. The roughness values are sampled from the G channel."
        return packed("glTF metallic-roughness", {scalar(S::Roughness, C::G), scalar(S::Metallic, C::B)});
    case Layout::UnityMaskMap:
        // Unity HDRP "Mask and detail maps": R metallic, G ambient occlusion, B detail mask,
        // A smoothness (= 1 - roughness).
        return packed("Unity mask map",
            {scalar(S::Metallic, C::R), scalar(S::Occlusion, C::G), scalar(S::Roughness, C::A, true)});
    case Layout::UnityMetallicSmoothness:
        // Unity Standard / URP Lit metallic map: R metallic, A smoothness.
        return packed(
            "Unity metallic-smoothness", {scalar(S::Metallic, C::R), scalar(S::Roughness, C::A, true)});
    case Layout::Mra:
        return packed(
            "MRA", {scalar(S::Metallic, C::R), scalar(S::Roughness, C::G), scalar(S::Occlusion, C::B)});
    case Layout::Rma:
        return packed(
            "RMA", {scalar(S::Roughness, C::R), scalar(S::Metallic, C::G), scalar(S::Occlusion, C::B)});
    case Layout::Emissive:
        return single(scalar(S::Emissive, C::Rgb));
    case Layout::Clearcoat:
        return single(scalar(S::Clearcoat, C::R));
    case Layout::ClearcoatRoughness:
        return single(scalar(S::ClearcoatRoughness, C::R));
    case Layout::ClearcoatNormal:
        return single(MapRead {S::ClearcoatNormal, C::Rgb, false, std::nullopt});
    case Layout::PackedClearcoat:
        // KHR_materials_clearcoat: "The clearcoat layer intensity ... sampled from the R channel",
        // "roughness ... from the G channel"; Facet's Unreal export writes its T_*_CC so.
        return packed("clear coat", {scalar(S::Clearcoat, C::R), scalar(S::ClearcoatRoughness, C::G)});
    case Layout::SheenColor:
        return single(MapRead {S::SheenColor, C::Rgb, false, std::nullopt});
    case Layout::SheenRoughness:
        return single(scalar(S::SheenRoughness, C::R));
    case Layout::SpecularColor:
        return single(MapRead {S::SpecularColor, C::Rgb, false, std::nullopt});
    case Layout::Anisotropy:
        return single(MapRead {S::Anisotropy, C::Rgb, false, std::nullopt});
    case Layout::Iridescence:
        // KHR_materials_iridescence: the strength "in the R channel", the thickness "in the G
        // channel"; Facet's glTF textures write <material>_iridescence.png so.
        return packed("iridescence", {scalar(S::Iridescence, C::R), scalar(S::IridescenceThickness, C::G)});
    case Layout::IridescenceThickness:
        return single(scalar(S::IridescenceThickness, C::G));
    }
    return {};
}

enum class Where {
    Anywhere, // the key occurs anywhere in the lower-case base name
    LastWords, // the name's last words are the key's words ('_' separates them in the key)
    Unreal, // T_<name>_<key>: at least three words, the first "t", the last the key
};

struct NameRule {
    const char* key;
    Where where;
    Layout layout;
};

// Anywhere rules first, then the last-words rules with more words before those with fewer (so
// "metallic_smoothness" is not read as "smoothness"), then Unreal's one- and two-letter codes.
// docs/app.md lists the sources of each.
// clang-format off: one rule a line
constexpr NameRule kRules[] = {
    {"occlusionroughnessmetallic", Where::Anywhere, Layout::Orm}, // Substance "UE4 packed", glTF samples
    {"occlusionroughmetal", Where::Anywhere, Layout::Orm}, // glTF FlightHelmet
    {"metallicroughness", Where::Anywhere, Layout::GltfMetallicRoughness},
    {"metalroughness", Where::Anywhere, Layout::GltfMetallicRoughness}, // glTF DamagedHelmet

    {"ambient_occlusion", Where::LastWords, Layout::Occlusion},
    {"metallic_smoothness", Where::LastWords, Layout::UnityMetallicSmoothness},
    {"mask_map", Where::LastWords, Layout::UnityMaskMap}, {"base_color", Where::LastWords, Layout::BaseColor},
    {"base_colour", Where::LastWords, Layout::BaseColor},
    {"normal_gl", Where::LastWords, Layout::NormalOpenGl},
    {"normal_dx", Where::LastWords, Layout::NormalDirectX},
    {"nor_gl", Where::LastWords, Layout::NormalOpenGl}, // Poly Haven
    {"nor_dx", Where::LastWords, Layout::NormalDirectX}, // Poly Haven
    {"clearcoat_roughness", Where::LastWords, Layout::ClearcoatRoughness},
    {"clearcoat_normal", Where::LastWords, Layout::ClearcoatNormal},
    {"coat_roughness", Where::LastWords, Layout::ClearcoatRoughness},
    {"coat_normal", Where::LastWords, Layout::ClearcoatNormal},
    {"clear_coat", Where::LastWords, Layout::Clearcoat},
    {"sheen_roughness", Where::LastWords, Layout::SheenRoughness},
    {"sheen_color", Where::LastWords, Layout::SheenColor},
    {"sheen_colour", Where::LastWords, Layout::SheenColor},
    {"specular_color", Where::LastWords, Layout::SpecularColor},
    {"specular_colour", Where::LastWords, Layout::SpecularColor},
    {"iridescence_thickness", Where::LastWords, Layout::IridescenceThickness},

    {"clearcoatroughness", Where::LastWords, Layout::ClearcoatRoughness}, // glTF's clearcoatRoughnessTexture
    {"clearcoatnormal", Where::LastWords, Layout::ClearcoatNormal}, // glTF's clearcoatNormalTexture
    {"clearcoat", Where::LastWords, Layout::Clearcoat}, {"coat", Where::LastWords, Layout::Clearcoat},
    {"sheenroughness", Where::LastWords, Layout::SheenRoughness}, // glTF's sheenRoughnessTexture
    {"sheencolor", Where::LastWords, Layout::SheenColor}, // glTF's sheenColorTexture
    {"sheen", Where::LastWords, Layout::SheenColor},
    {"specularcolor", Where::LastWords, Layout::SpecularColor}, // glTF's specularColorTexture
    {"anisotropy", Where::LastWords, Layout::Anisotropy}, // glTF's anisotropyTexture
    {"iridescencethickness", Where::LastWords, Layout::IridescenceThickness}, // glTF's iridescenceThicknessTexture
    {"iridescence", Where::LastWords, Layout::Iridescence}, // glTF's iridescenceTexture

    {"ambientocclusion", Where::LastWords, Layout::Occlusion}, // ambientCG
    {"metallicsmoothness", Where::LastWords, Layout::UnityMetallicSmoothness},
    {"maskmap", Where::LastWords, Layout::UnityMaskMap}, // Unity HDRP
    {"basecolor", Where::LastWords, Layout::BaseColor}, {"basecolour", Where::LastWords, Layout::BaseColor},
    {"normalgl", Where::LastWords, Layout::NormalOpenGl}, // ambientCG
    {"normaldx", Where::LastWords, Layout::NormalDirectX}, // ambientCG
    {"albedo", Where::LastWords, Layout::BaseColor}, {"diffuse", Where::LastWords, Layout::BaseColor},
    {"diff", Where::LastWords, Layout::BaseColor}, // Poly Haven
    {"color", Where::LastWords, Layout::BaseColor}, {"colour", Where::LastWords, Layout::BaseColor},
    {"col", Where::LastWords, Layout::BaseColor}, // Poliigon
    {"bc", Where::LastWords, Layout::BaseColor}, // Unreal
    {"normal", Where::LastWords, Layout::Normal}, {"nrm", Where::LastWords, Layout::Normal}, // Poliigon
    {"nor", Where::LastWords, Layout::Normal}, {"metallic", Where::LastWords, Layout::Metallic},
    {"metalness", Where::LastWords, Layout::Metallic},
    {"metal", Where::LastWords, Layout::Metallic}, // Poly Haven
    {"roughness", Where::LastWords, Layout::Roughness},
    {"rough", Where::LastWords, Layout::Roughness}, // Poly Haven
    {"glossiness", Where::LastWords, Layout::Gloss}, {"gloss", Where::LastWords, Layout::Gloss}, // Poliigon
    {"smoothness", Where::LastWords, Layout::Gloss}, {"occlusion", Where::LastWords, Layout::Occlusion},
    {"ao", Where::LastWords, Layout::Occlusion}, {"orm", Where::LastWords, Layout::Orm},
    {"arm", Where::LastWords, Layout::Orm}, // Poly Haven: AO, roughness, metal
    {"mra", Where::LastWords, Layout::Mra}, {"rma", Where::LastWords, Layout::Rma},
    {"mr", Where::LastWords, Layout::GltfMetallicRoughness}, {"emissive", Where::LastWords, Layout::Emissive},
    {"emission", Where::LastWords, Layout::Emissive}, // Poly Haven, ambientCG
    {"emit", Where::LastWords, Layout::Emissive}, {"glow", Where::LastWords, Layout::Emissive},

    // Unreal texture suffixes (Allar's / Gamemakin UE style guide, 1.2.6): only after a T_ prefix,
    // where a one-letter word is not something else. Unreal's normal maps are DirectX (Y-).
    {"d", Where::Unreal, Layout::BaseColor}, {"n", Where::Unreal, Layout::NormalDirectX},
    {"r", Where::Unreal, Layout::Roughness},
    {"m", Where::Unreal, Layout::Metallic}, // "metallic or mask": read as metallic
    {"mt", Where::Unreal, Layout::Metallic}, {"o", Where::Unreal, Layout::Occlusion},
    {"e", Where::Unreal, Layout::Emissive},
    {"cc", Where::Unreal, Layout::PackedClearcoat}, // Facet's Unreal template writes T_<name>_CC
};
// clang-format on

// The words of a file's base name, lower case, without trailing resolution words ("4k", "2048").
QStringList nameWords(const QString& path)
{
    static const QRegularExpression kSeparators(QStringLiteral("[_\\-. ]+"));
    static const QRegularExpression kResolution(QStringLiteral("^[0-9]+k?$"));
    QStringList words = QFileInfo(path).completeBaseName().toLower().split(kSeparators, Qt::SkipEmptyParts);
    while (words.size() > 1 && kResolution.match(words.last()).hasMatch())
        words.removeLast();
    return words;
}

bool matches(const NameRule& rule, const QString& lowerName, const QStringList& words)
{
    const QString key = QLatin1String(rule.key);
    switch (rule.where) {
    case Where::Anywhere:
        return lowerName.contains(key);
    case Where::LastWords: {
        const QStringList keyWords = key.split(u'_');
        if (words.size() < keyWords.size())
            return false;
        return std::equal(keyWords.begin(), keyWords.end(), words.end() - keyWords.size());
    }
    case Where::Unreal:
        return words.size() >= 3 && words.first() == QLatin1String("t") && words.last() == key;
    }
    return false;
}

} // namespace

TextureNaming textureNaming(const QString& path)
{
    const QString lowerName = QFileInfo(path).completeBaseName().toLower();
    const QStringList words = nameWords(path);
    for (const NameRule& rule : kRules)
        if (matches(rule, lowerName, words))
            return namingOf(rule.layout);
    return {};
}

MapRead mapReadFor(MapSlot slot, const QString& path)
{
    const TextureNaming naming = textureNaming(path);
    for (const MapRead& read : naming.reads)
        if (read.slot == slot)
            return read;
    return MapRead {slot, isScalarSlot(slot) ? MapChannel::R : MapChannel::Rgb, false, std::nullopt};
}

bool isImageFileName(const QString& path)
{
    static const QStringList kExtensions = {QStringLiteral("png"), QStringLiteral("jpg"),
        QStringLiteral("jpeg"), QStringLiteral("tga"), QStringLiteral("tif"), QStringLiteral("tiff"),
        QStringLiteral("exr"), QStringLiteral("hdr"), QStringLiteral("bmp"), QStringLiteral("webp"),
        QStringLiteral("pfm"), QStringLiteral("dds"), QStringLiteral("psd")};
    return kExtensions.contains(QFileInfo(path).suffix().toLower());
}

MapNamingResult assignMapsByName(const QStringList& paths)
{
    QStringList files;
    for (const QString& path : paths) {
        const QFileInfo info(path);
        if (info.isDir()) {
            const QDir dir(path);
            for (const QString& entry : dir.entryList(QDir::Files, QDir::Name))
                files.append(dir.filePath(entry));
        } else {
            files.append(path);
        }
    }
    std::stable_sort(files.begin(), files.end(), [](const QString& a, const QString& b) {
        return QFileInfo(a).fileName().compare(QFileInfo(b).fileName(), Qt::CaseInsensitive) < 0;
    });

    MapNamingResult result;
    struct Candidate {
        int rank; // 0 a single map, 1 a DirectX normal (Facet's convention is OpenGL), 2 a packed channel
        int file; // index in `files`: name order breaks ties
        MapRead read;
        QString convention;
    };
    std::array<std::optional<Candidate>, kMapSlotCount> bySlot;
    std::vector<int> recognisedFiles;
    for (int index = 0; index < files.size(); ++index) {
        const QString& file = files[index];
        if (!isImageFileName(file)) {
            result.notImages.append(file);
            continue;
        }
        const TextureNaming naming = textureNaming(file);
        if (!naming.recognised()) {
            result.unmatched.append(file);
            continue;
        }
        recognisedFiles.push_back(index);
        for (const MapRead& read : naming.reads) {
            const int rank = naming.reads.size() > 1 ? 2 : (read.flipGreen.value_or(false) ? 1 : 0);
            auto& best = bySlot[std::size_t(read.slot)];
            if (!best || std::tie(rank, index) < std::tie(best->rank, best->file))
                best = Candidate {rank, index, read, naming.convention};
        }
    }
    for (const int index : recognisedFiles) {
        const bool used = std::any_of(bySlot.begin(), bySlot.end(),
            [index](const std::optional<Candidate>& c) { return c && c->file == index; });
        if (!used)
            result.unmatched.append(files[index]);
    }
    for (const auto& candidate : bySlot)
        if (candidate)
            result.assignments.push_back(MapAssignment {candidate->read.slot, files[candidate->file],
                candidate->read.channel, candidate->read.invert, candidate->read.flipGreen.value_or(false),
                candidate->convention});
    return result;
}

Material withAssignedMaps(Material material, const std::vector<MapAssignment>& assignments)
{
    for (const MapAssignment& assignment : assignments) {
        MaterialMap& map = material.map(assignment.slot);
        map.path = assignment.path.toStdString();
        map.channel = assignment.channel;
        map.colorSpace = isColorSlot(assignment.slot) ? ColorEncoding::SRGB : ColorEncoding::Linear;
        map.invert = isScalarSlot(assignment.slot) && assignment.invert;
        map.flipGreen = isNormalSlot(assignment.slot) && assignment.flipGreen;
        if (assignment.slot == MapSlot::BaseColor)
            map.factor = glm::dvec4(1.0, 1.0, 1.0, map.factor.w);
        else if (assignment.slot == MapSlot::Emissive || assignment.slot == MapSlot::SheenColor)
            map.factor = glm::dvec4(1.0); // the default factor, black, would hide the texture
        else if (assignment.slot == MapSlot::Metallic || assignment.slot == MapSlot::Roughness
            || assignment.slot == MapSlot::Clearcoat || assignment.slot == MapSlot::ClearcoatRoughness
            || assignment.slot == MapSlot::SheenRoughness || assignment.slot == MapSlot::Anisotropy
            || assignment.slot == MapSlot::Iridescence)
            material.setFactor(assignment.slot, 1.0); // a coat texture turns the coat on, as painted
    }
    // A coat normal or roughness map alone says there is a coat: a full one, shaped by the map;
    // a sheen roughness map alone, a white sheen.
    for (const MapAssignment& assignment : assignments) {
        if (lobeOf(assignment.slot) == MaterialLobe::Clearcoat && !material.hasClearcoat())
            material.setFactor(MapSlot::Clearcoat, 1.0);
        if (lobeOf(assignment.slot) == MaterialLobe::Sheen && !material.hasSheen())
            material.map(MapSlot::SheenColor).factor = glm::dvec4(1.0);
        // A film thickness map alone says there is a film (its strength 1).
        if (lobeOf(assignment.slot) == MaterialLobe::Iridescence && !material.hasIridescence())
            material.setFactor(MapSlot::Iridescence, 1.0);
    }
    return material;
}

Material withTextureSet(
    Material material, const std::vector<MapAssignment>& assignments, std::vector<MapSlot>* cleared)
{
    material = withAssignedMaps(std::move(material), assignments);
    const auto defaults = Material::defaultMaps();
    for (MapSlot slot : kAllMapSlots) {
        const bool assigned = std::any_of(assignments.begin(), assignments.end(),
            [slot](const MapAssignment& a) { return a.slot == slot; });
        MaterialMap& map = material.map(slot);
        if (assigned || !map.hasTexture())
            continue;
        const UvTransform uv = map.uv;
        map = defaults[std::size_t(slot)];
        map.uv = uv;
        if (cleared)
            cleared->push_back(slot);
    }
    return material;
}

} // namespace facet
