#pragma once
// Helpers shared by the test executables: where the CC0 sample data and the test artefacts are.

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

#include <QProcessEnvironment>
#include <QString>
#include <QStringList>
#include <QtTest/QTest>

#include <glm/vec3.hpp>

#include "core/shading/MaterialBrdf.h"

namespace facet::test {

// The white furnace's material: base colour 1, IOR 1.5, the given metallic and perceptual
// roughness (its albedo is 1 where the model compensates multiple scattering).
inline MaterialInfo whiteMaterial(double metallic, double roughness)
{
    MaterialInfo m;
    m.baseColor = glm::dvec3(1.0);
    m.metallic = metallic;
    m.perceptualRoughness = roughness;
    m.ior = 1.5;
    return m;
}

// The unit direction at polar cosine `cosTheta` from +Z and azimuth `phi` from +X (a tangent frame's
// view or light direction).
inline glm::dvec3 direction(double cosTheta, double phi)
{
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

// Root of the sample data fetched by packaging/fetch-assets.sh ($FACET_ASSETS_DIR overrides the
// directory configured at build time).
QString assetsDir();
// Path of a sample HDR environment, e.g. hdriPath("studio") -> ".../hdri/studio.exr": the fetched
// sample data, else the copy the repository ships in tests/data/hdri (the CC0 studio map, so the
// tests of the hard case always run). Empty if neither has it.
QString hdriPath(const QString& name);
// Path of a sample mesh, e.g. modelPath("suzi") -> ".../models/suzi.glb". Empty if absent.
QString modelPath(const QString& name);
// The source tree (for golden data under tests/data).
QString sourceDir();
// Where tests write artefacts (actual and diff images, screenshots); created on demand.
QString outputDir();
// True when running under CI (CI=true): missing sample data is then a failure, not a skip.
bool runningInCi();

// The wall-clock bound of a "refused at once, not after minutes" check, given its Release value:
// a sanitizer build runs the same code 3 to 10 times slower, beside another test on 2 cores, so
// there the bound is 20 times as long. Speed itself is measured by the benchmarks, not tests.
constexpr qint64 wallClockBoundMs(qint64 releaseMs)
{
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
    return releaseMs * 20;
#else
    return releaseMs;
#endif
}

// The Khronos glTF-Validator's verdict on a .gltf or .glb (tests/tools/validate-gltf.cjs, run by
// node with the validator packaging/install-deps.sh installs): `ran` false when node or the
// validator is missing (`report` says what); `clean` when it found no error and no warning;
// `report` is its JSON report, for the failure message.
struct GltfValidation {
    bool ran = false;
    bool clean = false;
    QString report;
};
GltfValidation validateGltf(const QString& path);

// GL tests call this from initMain(), before any Q*Application: they must get their surfaceless
// EGL context with no display server at all, as the headless commands do.
void forgetDisplayServer();

// What a finished child process said.
struct ProcessResult {
    int exitCode = -1; // -1: crashed or did not finish (then `err` says "did not finish")
    QString out;
    QString err;
};
// Runs `executable` as the headless commands must run: with no display server (DISPLAY and
// WAYLAND_DISPLAY removed from the environment), plus the variables in `extra`. Waits up to five
// minutes.
ProcessResult runWithoutDisplay(const QString& executable, const QStringList& arguments,
    const QProcessEnvironment& extra = QProcessEnvironment());

// A width x height image of `channels` channels (rows top first, channels interleaved) whose
// sample (x, y, c) is (x + 3y + 7c) / 64: every sample different, exact in half floats.
std::vector<float> ramp(int width, int height, int channels);

// Writes a width x width/2 float EXR of constant `radiance` (R = G = B) through OpenImageIO (not
// core's Image::save, so that a bug there cannot hide one in loading), making its folder. For
// tests that need environment files of their own (libraries, relinking).
bool writeConstantExr(const QString& path, float radiance, int width = 16);

// Writes a PNG that claims to be width x height 8-bit RGB and holds no pixels (signature, IHDR, an
// empty IDAT, IEND, with correct CRCs): enough for a reader to see the size in the header, and for
// a loader that checks sizes before decoding to refuse it at no cost (a 16384² "map" in 57 bytes).
bool writePngHeaderOnly(const QString& path, int width, int height);
// Writes `text` to `path` (its folder made first), replacing what was there. False on any error.
bool writeText(const QString& path, const QByteArray& text);
// A QStringList of UTF-8 literals.
QStringList strings(std::initializer_list<const char*> items);

// "(x, y, z)" with `digits` significant digits, for failure messages.
std::string describe(const glm::dvec3& v, int digits = 6);

} // namespace facet::test

// Skips the test (locally) or fails it (CI) when a sample-data file is missing.
#define FACET_REQUIRE_ASSET(path, what)                                                                      \
    do {                                                                                                     \
        if ((path).isEmpty()) {                                                                              \
            const QByteArray message                                                                         \
                = QByteArray("sample data missing: ") + (what) + " (run packaging/fetch-assets.sh)";         \
            if (facet::test::runningInCi())                                                                  \
                QFAIL(message.constData());                                                                  \
            else                                                                                             \
                QSKIP(message.constData());                                                                  \
        }                                                                                                    \
    } while (false)

// Fails the test when the glTF at `path` has validator errors or warnings (the report attached);
// when the validator cannot run: skips locally, fails under CI=true (where install-deps.sh ran).
#define FACET_REQUIRE_VALID_GLTF(path)                                                                       \
    do {                                                                                                     \
        const facet::test::GltfValidation validation = facet::test::validateGltf(path);                      \
        if (!validation.ran) {                                                                               \
            const QByteArray why = "cannot run the glTF validator: " + validation.report.toLocal8Bit();      \
            if (facet::test::runningInCi())                                                                  \
                QFAIL(why.constData());                                                                      \
            else                                                                                             \
                QSKIP(why.constData());                                                                      \
        }                                                                                                    \
        if (!validation.clean)                                                                               \
            QFAIL(qPrintable(QStringLiteral("%1: the glTF validator reports errors or warnings:\n%2")        \
                                 .arg(path, validation.report)));                                            \
    } while (false)
