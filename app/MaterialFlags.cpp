#include "MaterialFlags.h"

#include "CommandInputs.h"

#include <QStringList>

namespace facet {

namespace {

QString number(double value)
{
    return QString::number(value, 'g', 6);
}

} // namespace

MaterialFlags::MaterialFlags()
{
    for (const MaterialPropertyInfo& info : materialProperties()) {
        if (!info.flag)
            continue;
        const QString range = QStringLiteral("[%1, %2]").arg(number(info.minimum), number(info.maximum));
        const bool color = info.value == PropertyValue::Color;
        const QString help = color
            ? QStringLiteral("%1 of every material: r,g,b, each in %2.")
                  .arg(QString::fromUtf8(info.label), range)
            : QStringLiteral("%1 of every material, in %2.").arg(QString::fromUtf8(info.label), range);
        m_flags.push_back(Flag {info.property,
            QCommandLineOption(QString::fromLatin1(info.flag), help,
                color ? QStringLiteral("r,g,b") : QStringLiteral("value"))});
    }
}

void MaterialFlags::addTo(QCommandLineParser& parser) const
{
    for (const Flag& flag : m_flags)
        parser.addOption(flag.option);
}

bool MaterialFlags::apply(
    const QCommandLineParser& parser, const std::vector<Material*>& materials, QString* error) const
{
    for (const Flag& flag : m_flags) {
        if (!parser.isSet(flag.option))
            continue;
        const MaterialPropertyInfo& info = infoOf(flag.property);
        const QString name = QString::fromLatin1(info.flag);
        const QString text = parser.value(flag.option);
        if (info.value == PropertyValue::Color) {
            const QStringList parts = text.split(QLatin1Char(','));
            if (parts.size() != 3) {
                *error = QStringLiteral("--%1: '%2' is not r,g,b").arg(name, text);
                return false;
            }
            glm::dvec3 rgb;
            for (int i = 0; i < 3; ++i)
                if (!parseNumber(name, parts[i], info.minimum, info.maximum, &rgb[i], error))
                    return false;
            for (Material* material : materials)
                setColor(*material, flag.property, rgb);
        } else {
            double value = 0.0;
            if (!parseNumber(name, text, info.minimum, info.maximum, &value, error))
                return false;
            for (Material* material : materials)
                setScalar(*material, flag.property, value);
        }
    }
    return true;
}

} // namespace facet
