#pragma once
// What the headless commands that render a project (render, sheet) read alike: the positional
// input (a project file, a glTF asset, or the built-in default project) and a WxH size.

#include <optional>
#include <string>

#include <QString>
#include <QStringList>

#include "core/project/Project.h"

namespace facet {

// At most one positional argument; else false with *error naming them.
bool checkOneInput(const QStringList& positional, QString* error);
// The -o value: present (else *error = `missing`) and ending in .exr or .png, any case (else
// *error = "-o 'VALUE': " + `wrongType`).
std::optional<std::string> exrOrPngOutput(
    bool isSet, const QString& value, const QString& missing, const QString& wrongType, QString* error);
// The project of `positional` (checkOneInput: a project file or a glTF asset with its
// materials), or Project::defaultProject() without one. A load warning goes to stderr prefixed
// "facet COMMAND: ". nullopt with *error when the file cannot be read.
std::optional<Project> commandInputProject(const QStringList& positional, const QString& command, QString* error);

// --ibl METHOD and --ibl-samples N (null: not given) into environment.method and .samples (--ibl
// alone: the method with its own default count, 0; a project's count belongs to its method). False
// with *error naming the flag: an unknown method ("--ibl: 'X' is not split-sum or reference"), a
// count outside 1..kMaxIblSamples, or a count for the split sum, which takes none.
bool applyIblOptions(const QString* method, const QString* samples, EnvironmentSettings& environment, QString* error);

// A finite number for --FLAG within [low, high] (within (low, high) when `open`); else false with
// *error "--FLAG: 'TEXT' is not a number" or "--FLAG: TEXT is outside [LOW, HIGH]" ("(LOW, HIGH)").
bool parseNumber(const QString& flag, const QString& text, double low, double high, double* out,
    QString* error, bool open = false);

// "WxH" (case-insensitive x) with minimum <= W, H <= maximum; else false with
// *error = "--FLAG: 'TEXT' is not WxH with MIN <= W, H <= MAX".
bool parseImageSize(const QString& flag, const QString& text, int minimum, int maximum, int* width, int* height,
    QString* error);

// A bare name of an installed CC0 sample ("night") as its library reference
// (library:installed/hdri/night.exr); anything else as it is. A built-in name (studio, sky) stays
// built-in, as Environment::fromSpec resolves it, and a file of that name in the working folder
// stays that file. expandInstalledNames does it to each item of a comma-separated list.
QString expandInstalledName(const QString& spec);
QString expandInstalledNames(const QString& list);

} // namespace facet
