#include "ui/MapNaming.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <array>

namespace facet {

namespace {

struct NameRule {
    const char* suffix;
    std::optional<MapSlot> slot; // nullopt: ORM
    bool flipGreen = false;
};

// Longer suffixes first so "normal_gl" is not read as "gl".
const std::array kRules = {
    NameRule {"ambient_occlusion", MapSlot::Occlusion},
    NameRule {"ambientocclusion", MapSlot::Occlusion},
    NameRule {"base_color", MapSlot::BaseColor},
    NameRule {"basecolor", MapSlot::BaseColor},
    NameRule {"metalness", MapSlot::Metallic},
    NameRule {"roughness", MapSlot::Roughness},
    NameRule {"occlusion", MapSlot::Occlusion},
    NameRule {"normal_gl", MapSlot::Normal},
    NameRule {"normal_dx", MapSlot::Normal, true},
    NameRule {"normalgl", MapSlot::Normal},
    NameRule {"normaldx", MapSlot::Normal, true},
    NameRule {"metallic", MapSlot::Metallic},
    NameRule {"diffuse", MapSlot::BaseColor},
    NameRule {"albedo", MapSlot::BaseColor},
    NameRule {"normal", MapSlot::Normal},
    NameRule {"color", MapSlot::BaseColor},
    NameRule {"metal", MapSlot::Metallic},
    NameRule {"rough", MapSlot::Roughness},
    NameRule {"nrm", MapSlot::Normal},
    NameRule {"orm", std::nullopt},
    NameRule {"ao", MapSlot::Occlusion},
};

const NameRule* ruleFor(const QString& path)
{
    const QString name = QFileInfo(path).completeBaseName().toLower();
    for (const NameRule& rule : kRules) {
        const QString suffix = QLatin1String(rule.suffix);
        if (name == suffix)
            return &rule;
        if (name.endsWith(suffix)) {
            const QChar before = name.at(name.size() - suffix.size() - 1);
            if (before == u'_' || before == u'-' || before == u'.' || before == u' ')
                return &rule;
        }
    }
    return nullptr;
}

} // namespace

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
    std::sort(files.begin(), files.end(), [](const QString& a, const QString& b) {
        return QFileInfo(a).fileName().compare(QFileInfo(b).fileName(), Qt::CaseInsensitive) < 0;
    });

    MapNamingResult result;
    std::array<std::optional<MapAssignment>, kMapSlotCount> bySlot;
    QString ormFile;
    for (const QString& file : files) {
        if (!isImageFileName(file)) {
            result.notImages.append(file);
            continue;
        }
        const NameRule* rule = ruleFor(file);
        if (!rule) {
            result.unmatched.append(file);
            continue;
        }
        if (!rule->slot) {
            if (!ormFile.isEmpty()) {
                result.unmatched.append(file);
                continue;
            }
            ormFile = file;
            continue;
        }
        auto& slot = bySlot[std::size_t(*rule->slot)];
        if (slot) {
            result.unmatched.append(file);
            continue;
        }
        const MapChannel channel = isScalarSlot(*rule->slot) ? MapChannel::R : MapChannel::Rgb;
        slot = MapAssignment {*rule->slot, file, channel, rule->flipGreen};
    }
    if (!ormFile.isEmpty()) {
        const std::array<std::pair<MapSlot, MapChannel>, 3> orm = {{{MapSlot::Occlusion, MapChannel::R},
            {MapSlot::Roughness, MapChannel::G}, {MapSlot::Metallic, MapChannel::B}}};
        bool used = false;
        for (const auto& [slot, channel] : orm) {
            auto& assignment = bySlot[std::size_t(slot)];
            if (assignment)
                continue; // a separate file for this slot wins
            assignment = MapAssignment {slot, ormFile, channel, false};
            used = true;
        }
        if (!used)
            result.unmatched.append(ormFile);
    }
    for (const auto& assignment : bySlot)
        if (assignment)
            result.assignments.push_back(*assignment);
    return result;
}

Material withAssignedMaps(Material material, const std::vector<MapAssignment>& assignments)
{
    for (const MapAssignment& assignment : assignments) {
        MaterialMap& map = material.map(assignment.slot);
        map.path = assignment.path.toStdString();
        map.channel = assignment.channel;
        map.colorSpace = assignment.slot == MapSlot::BaseColor ? ColorEncoding::SRGB : ColorEncoding::Linear;
        if (assignment.slot == MapSlot::Normal)
            map.flipGreen = assignment.flipGreen;
        if (assignment.slot == MapSlot::BaseColor)
            map.factor = glm::dvec4(1.0, 1.0, 1.0, map.factor.w);
        else if (assignment.slot == MapSlot::Metallic || assignment.slot == MapSlot::Roughness)
            material.setFactor(assignment.slot, 1.0);
    }
    return material;
}

} // namespace facet
