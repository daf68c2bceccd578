#pragma once
// An HDR environment: an equirectangular radiance image plus rotation and intensity.
// Conventions (docs/architecture.md): for a unit world direction d,
//   u = atan2(d.z, d.x) / (2 pi) + 0.5,   v = asin(d.y) / pi + 0.5,   v = 1 is the image's top row.
// Rotation turns the environment about +Y by rotationDegrees, right-handed: a positive angle turns
// it counter-clockwise seen from above, so a feature the image shows at direction d appears in the
// world at R_y(theta) d, R_y = [[c, 0, s], [0, 1, 0], [-s, 0, c]] (+90 degrees takes +X to -Z, and
// the feature's u decreases by theta / 360). A sampler looks up the image at R_y(-theta) w for a
// world direction w, i.e. at u_world + theta / 360. Intensity multiplies radiance.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "core/image/Image.h"

namespace facet {

// Direction <-> equirect mapping of docs/architecture.md, in the environment's own (unrotated) frame.
glm::dvec2 equirectUvFromDirection(const glm::dvec3& direction);
glm::dvec3 directionFromEquirectUv(const glm::dvec2& uv);

class Environment {
public:
    // Built-in environments that need no file.
    enum class Builtin {
        Studio, // a dim grey room with a large soft box overhead, two strip lights and a floor bounce
        Sky, // a clear sky gradient with a soft sun and a ground plane
    };

    Environment() = default; // empty: no image

    // A constant environment of `radiance` in every direction (the white furnace): an 8x4 image,
    // named "uniform:R,G,B" (shortest round-trip numbers, so fromSpec(name()) gives it back).
    static Environment uniform(const glm::dvec3& radiance);
    // Procedural, deterministic and anti-aliased (each texel averages 4x4 directions), width x
    // width/2 (width at least 8, made even). Named "studio" / "sky".
    static Environment builtin(Builtin which, int width = 512);
    // The largest image an environment keeps: a larger file is area-filtered down while it is
    // read, a band of rows at a time (same aspect), so an 8192x4096 EXR costs 128 MiB, not 512.
    // Nothing Facet computes from an environment reads more (the cube's source is 4x its width,
    // EnvironmentSourceTextures the same limit).
    static constexpr int kMaxWidth = 4096;
    static constexpr int kMaxHeight = 2048;

    // Loads an equirect image (EXR, HDR, ...), sanitising NaN/Inf/negative pixels; an sRGB-encoded
    // (LDR) image is decoded to linear; larger than kMaxWidth x kMaxHeight, area-filtered to fit.
    // Named by its path.
    // A file loaded before, unchanged since (core/ibl/EnvironmentIndex.h), is not decoded here: the
    // environment has its content hash, size and warnings at once and decodes the pixels at the
    // first image() (lighting found in the IBL disk cache never asks for them).
    // Errors name the file and the problem: "Environment::load: <path>: <reason>". `warning` gets
    // one line per remark: "<path>: replaced N NaN, N Inf, N negative samples", and a note when
    // the image is not 2:1 (allowed, stretched over the sphere).
    static std::optional<Environment> load(
        const std::string& path, std::string* error, std::string* warning = nullptr);
    // Accepts a path, a built-in name ("studio", "sky"; a file of that name needs "./studio"), a
    // library reference ("library:installed/hdri/night.exr", core/project/AssetLibrary.h) or
    // "uniform:VALUE" / "uniform:R,G,B" with finite non-negative numbers; else an error naming the
    // spec. A missing file of a library says how to get it (AssetLibrary::missingFileAdvice).
    static std::optional<Environment> fromSpec(
        const std::string& spec, std::string* error, std::string* warning = nullptr);
    // What fromSpec can tell without reading a file: `spec` is not empty, and a "uniform:" spec is
    // well formed. On failure false and *problem, e.g. "uniform:-1: expected uniform:VALUE or
    // uniform:R,G,B with finite non-negative numbers" (no function prefix: callers add the field).
    static bool checkSpec(const std::string& spec, std::string* problem);
    static std::optional<Builtin> builtinFromName(const std::string& name);
    // Whether fromSpec reads `spec` from a file (a path or a library reference), not a built-in
    // or a uniform environment made in memory.
    static bool namesFile(const std::string& spec);
    static const char* builtinName(Builtin which);

    // Takes any equirect image; its pixels are sanitize()d (radiance is finite and non-negative).
    explicit Environment(Image equirect, std::string name = {});

    bool isEmpty() const { return !m_pixels || m_width <= 0 || m_height <= 0; }
    // The pixels. For an environment load() found in its index, the first call decodes the file
    // (thread-safe: copies share the pixels, one decodes, the others wait). Should the file no
    // longer decode, or decode to other pixels than the index said, the record is forgotten and a
    // warning names the file; the pixels are then black, or the new ones under the old hash, for
    // this one environment: the next load() reads the file afresh.
    const Image& image() const;
    // The image's size, known without decoding it.
    int width() const { return m_width; }
    int height() const { return m_height; }
    // Whether the pixels are in memory (false until a deferred environment's first image()).
    bool decoded() const;
    const std::string& name() const { return m_name; }
    // True for uniform(): every direction has the same radiance.
    bool isUniform() const { return m_uniform; }

    double rotationDegrees() const { return m_rotationDegrees; }
    void setRotationDegrees(double degrees) { m_rotationDegrees = degrees; }
    double intensity() const { return m_intensity; }
    void setIntensity(double intensity) { m_intensity = intensity; }

    // Hash of the pixels and size only (not rotation or intensity), stable across runs and
    // machines: the key of every cache of work derived from the image. 64-bit FNV-1a over
    // width, height (uint32) and each pixel's R, G, B float bits (-0 as +0), little-endian.
    std::uint64_t contentHash() const { return m_contentHash; }

    // World direction -> direction in the image's frame (undoes the rotation), and back.
    glm::dvec3 toImageFrame(const glm::dvec3& worldDirection) const;
    glm::dvec3 toWorldFrame(const glm::dvec3& imageDirection) const;

    // Radiance arriving from world direction `direction` (unit), bilinear between texel centres
    // (row y's centre is at v = 1 - (y + 0.5) / height), wrapping in u, clamped in v, times
    // intensity: what a GL_LINEAR sampler with REPEAT/CLAMP_TO_EDGE returns at mip level 0.
    // radianceNearest: the texel that holds the direction, times intensity.
    glm::dvec3 radiance(const glm::dvec3& direction) const;
    glm::dvec3 radianceNearest(const glm::dvec3& direction) const;

private:
    class Pixels;
    Environment(std::string path, std::uint64_t contentHash, int width, int height);

    std::shared_ptr<Pixels> m_pixels; // shared: copies of an Environment share the pixels
    int m_width = 0;
    int m_height = 0;
    std::string m_name;
    double m_rotationDegrees = 0.0;
    double m_intensity = 1.0;
    std::uint64_t m_contentHash = 0;
    bool m_uniform = false;
};

} // namespace facet
