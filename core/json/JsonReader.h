#pragma once
// Reading JSON objects with JSON paths in the messages, shared by the readers of core/ (Project,
// CompareLayout): the first error naming the key's path ("lights[1].intensity: expected a number,
// got a string"), and a warning for each key nobody asked for. Also the camera object, which
// projects and compare layouts both hold. Private to core: not part of any public header.

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <QJsonArray>
#include <QJsonObject>
#include <QJsonValue>
#include <QSet>
#include <QString>

#include "core/json/JsonSupport.h"
#include "core/project/Camera.h"

namespace facet {
struct CompareLayout;
} // namespace facet

namespace facet::jsonsupport {

// ---- Reading with JSON paths ------------------------------------------------------------

// What a read collects: the first error (later ones are consequences) and ignored-key warnings.
struct Messages {
    std::string error;
    std::vector<std::string> warnings;
    bool failed() const { return !error.empty(); }
    void fail(const std::string& path, const std::string& problem)
    {
        if (error.empty())
            error = path + ": " + problem;
    }
    // A message that names its path already (from materialFromJson, say).
    void failWith(const std::string& message)
    {
        if (error.empty())
            error = message;
    }
};

// Every number of a Facet file reaches the GPU (or the CPU twins) as a 32-bit float: a finite
// double beyond that range (a light of 1e308) would become infinity there and a wrong image.
inline bool fitsFloat(double value)
{
    return std::abs(value) <= double(std::numeric_limits<float>::max());
}
inline std::string outOfFloatRange(double value)
{
    return jsonsupport::number(value)
        + " is beyond the range of the 32-bit floats Facet shades with (about 3.4e38)";
}

// Reads the fields of one JSON object. Missing keys leave the output (its default) alone; a key
// of the wrong type or an unknown name records an error naming the key's JSON path. Reading
// continues after an error, but only the first one is reported.
class ObjectReader {
public:
    ObjectReader(Messages& messages, QJsonObject object, std::string path)
        : m_messages(messages)
        , m_object(std::move(object))
        , m_path(std::move(path))
    {
    }

    std::string pathOf(const char* key) const
    {
        return m_path.empty() ? std::string(key) : m_path + "." + key;
    }

    // The value under `key` (Undefined when missing), marking the key as known.
    QJsonValue value(const char* key)
    {
        const QString name = QString::fromLatin1(key);
        m_known.insert(name);
        return m_object.value(name);
    }

    void number(const char* key, double& out)
    {
        const QJsonValue v = value(key);
        if (v.isUndefined())
            return;
        if (!v.isDouble())
            return wrongType(key, "a number", v);
        if (!fitsFloat(v.toDouble()))
            return m_messages.fail(pathOf(key), outOfFloatRange(v.toDouble()));
        out = v.toDouble();
    }
    void integer(const char* key, int& out)
    {
        const QJsonValue v = value(key);
        if (v.isUndefined())
            return;
        if (!v.isDouble())
            return wrongType(key, "an integer", v);
        const double d = v.toDouble();
        if (!(std::floor(d) == d && d >= -2147483648.0 && d <= 2147483647.0))
            return m_messages.fail(pathOf(key), "expected an integer, got " + jsonsupport::number(d));
        out = int(d);
    }
    void boolean(const char* key, bool& out)
    {
        const QJsonValue v = value(key);
        if (v.isUndefined())
            return;
        if (!v.isBool())
            return wrongType(key, "true or false", v);
        out = v.toBool();
    }
    void string(const char* key, std::string& out)
    {
        if (std::optional<std::string> text = nameAt(key))
            out = std::move(*text);
    }
    // An array of `minCount` to `maxCount` numbers into out[0..]; returns how many were read (0
    // when missing or wrong).
    int numbers(const char* key, double* out, int minCount, int maxCount)
    {
        const QJsonValue v = value(key);
        if (v.isUndefined())
            return 0;
        const std::string expected = minCount == maxCount
            ? "an array of " + std::to_string(minCount) + " numbers"
            : "an array of " + std::to_string(minCount) + " to " + std::to_string(maxCount) + " numbers";
        if (!v.isArray()) {
            wrongType(key, expected, v);
            return 0;
        }
        const QJsonArray array = v.toArray();
        if (array.size() < minCount || array.size() > maxCount) {
            m_messages.fail(pathOf(key), "expected " + expected + ", got " + std::to_string(array.size()));
            return 0;
        }
        for (int i = 0; i < int(array.size()); ++i) {
            if (!array[i].isDouble()) {
                m_messages.fail(pathOf(key) + "[" + std::to_string(i) + "]",
                    std::string("expected a number, got ") + typeName(array[i]));
                return 0;
            }
            if (!fitsFloat(array[i].toDouble())) {
                m_messages.fail(
                    pathOf(key) + "[" + std::to_string(i) + "]", outOfFloatRange(array[i].toDouble()));
                return 0;
            }
        }
        for (int i = 0; i < int(array.size()); ++i)
            out[i] = array[i].toDouble();
        return int(array.size());
    }
    void vec2(const char* key, glm::dvec2& out) { numbers(key, &out.x, 2, 2); }
    void vec3(const char* key, glm::dvec3& out) { numbers(key, &out.x, 3, 3); }

    // `table`: pairs of (value, name), e.g. kToneMappers.
    template <typename Enum, typename Table> void enumeration(const char* key, Enum& out, const Table& table)
    {
        const std::optional<std::string> name = nameAt(key);
        if (!name)
            return;
        std::string expected;
        for (const auto& [candidate, text] : table) {
            if (*name == text) {
                out = candidate;
                return;
            }
            expected += std::string(expected.empty() ? "" : ", ") + "\"" + text + "\"";
        }
        m_messages.fail(pathOf(key), "unknown name \"" + *name + "\" (expected one of " + expected + ")");
    }

    // A name `fromString` knows (an enum with aliases, such as core/shading/DebugView's); otherwise
    // "unknown <what> "<name>" (expected one of: <expected>)".
    template <typename Enum, typename Parse>
    void named(
        const char* key, Enum& out, const Parse& fromString, const char* what, const std::string& expected)
    {
        const std::optional<std::string> name = nameAt(key);
        if (!name)
            return;
        if (const std::optional<Enum> known = fromString(*name)) {
            out = *known;
            return;
        }
        m_messages.fail(pathOf(key),
            "unknown " + std::string(what) + " \"" + *name + "\" (expected one of: " + expected + ")");
    }

    // A nested object; nullopt when missing or of the wrong type (then an error is recorded).
    std::optional<QJsonObject> object(const char* key)
    {
        const QJsonValue v = value(key);
        if (v.isUndefined())
            return std::nullopt;
        if (!v.isObject()) {
            wrongType(key, "an object", v);
            return std::nullopt;
        }
        return v.toObject();
    }
    std::optional<QJsonArray> array(const char* key)
    {
        const QJsonValue v = value(key);
        if (v.isUndefined())
            return std::nullopt;
        if (!v.isArray()) {
            wrongType(key, "an array", v);
            return std::nullopt;
        }
        return v.toArray();
    }

    // The string at `key`; nullopt when missing, or (an error recorded) not a string or holding a
    // NUL, which would cut the text short where a C API reads it (a path would name another file).
    std::optional<std::string> nameAt(const char* key)
    {
        const QJsonValue v = value(key);
        if (v.isUndefined())
            return std::nullopt;
        if (!v.isString()) {
            wrongType(key, "a string", v);
            return std::nullopt;
        }
        if (v.toString().contains(QChar(0))) {
            m_messages.fail(pathOf(key), "holds a NUL character");
            return std::nullopt;
        }
        return ss(v.toString());
    }

    // Keys nobody asked for: a newer Facet's optional fields, or typos. Warned about, not errors.
    void warnAboutUnknownKeys()
    {
        for (auto it = m_object.begin(); it != m_object.end(); ++it)
            if (!m_known.contains(it.key()))
                m_messages.warnings.push_back(
                    pathOf(it.key().toUtf8().constData()) + ": unknown key, ignored");
    }

private:
    void wrongType(const char* key, const std::string& expected, const QJsonValue& got)
    {
        m_messages.fail(pathOf(key), "expected " + expected + ", got " + typeName(got));
    }

    Messages& m_messages;
    QJsonObject m_object;
    std::string m_path;
    QSet<QString> m_known;
};

// ---- Shared value types -----------------------------------------------------------------

// The "camera" object of docs/project-format.md.
inline QJsonObject cameraToJson(const Camera& camera)
{
    QJsonObject o;
    o[QLatin1String("position")] = toArray(camera.position);
    o[QLatin1String("target")] = toArray(camera.target);
    o[QLatin1String("up")] = toArray(camera.up);
    o[QLatin1String("verticalFovDegrees")] = camera.verticalFovDegrees;
    o[QLatin1String("nearPlane")] = camera.nearPlane;
    o[QLatin1String("farPlane")] = camera.farPlane;
    return o;
}

inline void readCamera(Messages& messages, const QJsonObject& object, const std::string& path, Camera& camera)
{
    ObjectReader r(messages, object, path);
    r.vec3("position", camera.position);
    r.vec3("target", camera.target);
    r.vec3("up", camera.up);
    r.number("verticalFovDegrees", camera.verticalFovDegrees);
    r.number("nearPlane", camera.nearPlane);
    r.number("farPlane", camera.farPlane);
    r.warnAboutUnknownKeys();
}

// ---- Readers defined elsewhere ------------------------------------------------------------

// core/project/CompareLayout.cpp: reads a "compare" object over `layout` (missing keys keep its values).
void readCompareLayout(Messages& messages, const QJsonObject& object, const std::string& path,
    const std::string& baseDir, CompareLayout& layout);

} // namespace facet::jsonsupport
