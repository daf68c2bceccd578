#pragma once
// Small helpers shared by the JSON readers and writers of core/ (Project.cpp, JsonFile.cpp):
// string conversion, error reporting in the "return false and say why" style, JSON type names.
// Not part of any public header of core; app/RenderScenario reads its JSON with the same names.

#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <QJsonArray>
#include <QJsonValue>
#include <QString>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "core/support/Failure.h"

namespace facet::jsonsupport {

inline QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}
inline std::string ss(const QString& s)
{
    return s.toStdString();
}

inline std::string number(double value)
{
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.9g", value);
    return buffer;
}

using facet::fail;
inline std::nullopt_t failed(const std::string& message, std::string* problem)
{
    fail(message, problem);
    return std::nullopt;
}

// Appends `lines` to *warning (when given), one a line, each after `prefix`.
inline void appendWarnings(
    std::string* warning, const std::vector<std::string>& lines, const std::string& prefix)
{
    if (!warning || lines.empty())
        return;
    for (const std::string& line : lines) {
        if (!warning->empty())
            *warning += "\n";
        *warning += prefix + line;
    }
}

inline const char* typeName(const QJsonValue& value)
{
    switch (value.type()) {
    case QJsonValue::Null:
        return "null";
    case QJsonValue::Bool:
        return "a boolean";
    case QJsonValue::Double:
        return "a number";
    case QJsonValue::String:
        return "a string";
    case QJsonValue::Array:
        return "an array";
    case QJsonValue::Object:
        return "an object";
    case QJsonValue::Undefined:
        break;
    }
    return "nothing";
}

inline QJsonArray toArray(const double* values, int count)
{
    QJsonArray array;
    for (int i = 0; i < count; ++i)
        array.append(values[i]);
    return array;
}
inline QJsonArray toArray(const glm::dvec2& v)
{
    return toArray(&v.x, 2);
}
inline QJsonArray toArray(const glm::dvec3& v)
{
    return toArray(&v.x, 3);
}
inline QJsonArray toArray(const glm::dvec4& v)
{
    return toArray(&v.x, 4);
}

} // namespace facet::jsonsupport
