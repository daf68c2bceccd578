#include "CommandInputs.h"

#include <cmath>
#include <cstdio>

#include <QFileInfo>
#include <QRegularExpression>

#include "core/ibl/Environment.h"
#include "core/project/AssetLibrary.h"
#include "core/project/AssetProject.h"

namespace facet {

bool applyIblOptions(const QString* method, const QString* samples, EnvironmentSettings& environment, QString* error)
{
    if (method) {
        const std::optional<IblMethod> parsed = iblMethodFromString(method->toStdString());
        if (!parsed) {
            *error = QStringLiteral("--ibl: '%1' is not split-sum, fis or reference").arg(*method);
            return false;
        }
        // The method with its own default count (--ibl-samples may follow): a project's count
        // belongs to its method, and the split sum takes none.
        environment.method = *parsed;
        environment.samples = 0;
    }
    if (samples) {
        bool ok = false;
        const int count = samples->toInt(&ok);
        if (!ok || count < 1 || count > kMaxIblSamples) {
            *error = QStringLiteral("--ibl-samples: '%1' is not a whole number from 1 to %2").arg(*samples).arg(kMaxIblSamples);
            return false;
        }
        if (environment.method == IblMethod::SplitSum) {
            *error = QStringLiteral("--ibl-samples: %1 given with --ibl split-sum, which takes no samples "
                                    "(add --ibl fis or --ibl reference)")
                         .arg(count);
            return false;
        }
        environment.samples = count;
    }
    return true;
}

bool checkOneInput(const QStringList& positional, QString* error)
{
    if (positional.size() <= 1)
        return true;
    *error = QStringLiteral("too many arguments: expected at most one project or glTF file, got '%1'")
                 .arg(positional.join(QStringLiteral("' '")));
    return false;
}

std::optional<std::string> exrOrPngOutput(
    bool isSet, const QString& value, const QString& missing, const QString& wrongType, QString* error)
{
    if (!isSet) {
        *error = missing;
        return std::nullopt;
    }
    const QString suffix = QFileInfo(value).suffix().toLower();
    if (suffix != QStringLiteral("exr") && suffix != QStringLiteral("png")) {
        *error = QStringLiteral("-o '%1': %2").arg(value, wrongType);
        return std::nullopt;
    }
    return value.toStdString();
}

std::optional<Project> commandInputProject(const QStringList& positional, const QString& command, QString* error)
{
    if (positional.isEmpty())
        return Project::defaultProject();
    std::string loadError;
    std::string warning;
    const std::string input = positional.first().toStdString();
    auto project = isAssetFileName(input) ? projectFromAsset(input, &loadError, &warning)
                                          : Project::load(input, &loadError, &warning);
    if (!project) {
        *error = QString::fromStdString(loadError);
        return std::nullopt;
    }
    if (!warning.empty())
        std::fprintf(stderr, "facet %s: %s\n", qPrintable(command), warning.c_str());
    return project;
}

bool parseNumber(
    const QString& flag, const QString& text, double low, double high, double* out, QString* error, bool open)
{
    bool ok = false;
    const double value = text.trimmed().toDouble(&ok);
    if (!ok || !std::isfinite(value)) {
        *error = QStringLiteral("--%1: '%2' is not a number").arg(flag, text);
        return false;
    }
    const bool inside = open ? value > low && value < high : value >= low && value <= high;
    if (!inside) {
        *error = QStringLiteral("--%1: %2 is outside %3%4, %5%6")
                     .arg(flag, text, open ? QStringLiteral("(") : QStringLiteral("["))
                     .arg(low)
                     .arg(high)
                     .arg(open ? QStringLiteral(")") : QStringLiteral("]"));
        return false;
    }
    *out = value;
    return true;
}

bool parseImageSize(const QString& flag, const QString& text, int minimum, int maximum, int* width, int* height,
    QString* error)
{
    const QStringList parts = text.toLower().split(QLatin1Char('x'));
    bool okW = false;
    bool okH = false;
    const int w = parts.size() == 2 ? parts[0].toInt(&okW) : 0;
    const int h = parts.size() == 2 ? parts[1].toInt(&okH) : 0;
    if (!okW || !okH || w < minimum || h < minimum || w > maximum || h > maximum) {
        *error = QStringLiteral("--%1: '%2' is not WxH with %3 <= W, H <= %4").arg(flag, text).arg(minimum).arg(maximum);
        return false;
    }
    *width = w;
    *height = h;
    return true;
}

// A bare name of an installed CC0 sample ("night") as its library reference
// (library:installed/hdri/night.exr); anything else as it is. A built-in name (studio, sky) stays
// built-in, as Environment::fromSpec resolves it, and a file of that name in the working folder
// stays that file.
QString expandInstalledName(const QString& spec)
{
    static const QRegularExpression bare(QStringLiteral("^[A-Za-z][A-Za-z0-9_-]*$"));
    const QString item = spec.trimmed();
    if (!bare.match(item).hasMatch() || Environment::builtinFromName(item.toStdString()) || QFileInfo::exists(item))
        return spec;
    const QString file
        = QString::fromStdString(AssetLibrary::installed().folder) + QStringLiteral("/hdri/") + item + QStringLiteral(".exr");
    return QFileInfo(file).isFile() ? QStringLiteral("library:installed/hdri/") + item + QStringLiteral(".exr") : spec;
}

// The items of an environment list, each through expandInstalledName.
QString expandInstalledNames(const QString& list)
{
    QStringList parts = list.split(QLatin1Char(','));
    for (QString& part : parts)
        part = expandInstalledName(part);
    return parts.join(QLatin1Char(','));
}

} // namespace facet
