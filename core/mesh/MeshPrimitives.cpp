#include "core/mesh/MeshPrimitives.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "core/mesh/Tangents.h"

namespace facet {

namespace {

constexpr float kPi = std::numbers::pi_v<float>;

int clampTessellation(int value, int minimum)
{
    return std::clamp(value, minimum, 4096);
}

// ---- Lathe ------------------------------------------------------------------------------
// A surface of revolution about +Y from a profile in the (r, y) half-plane: the sphere,
// cylinder, torus and shader ball are all lathes. The profile runs from bottom to top (for the
// torus: once around the tube), and its outward normal is the traversal direction turned
// clockwise, (dy, -dr). With u growing along -atan2(z, x) and v along the profile,
// cross(dP/du, dP/dv) is then that outward normal, so triangles counter-clockwise in (u, v) are
// counter-clockwise from outside and the tangent frame is right-handed (w = +1).

// How a stroke gets its UVs.
enum class StrokeUv {
    Lathe, // u = longitude (times uRepeat), v = the profile point's v
    PlanarUp, // a flat face toward +Y: mapped like makePlane()
    PlanarDown, // a flat face toward -Y: the same seen from below
};

struct ProfilePoint {
    glm::vec2 position; // (r, y), r >= 0; r == 0 is on the axis (a pole)
    glm::vec2 normal; // (r, y) components of the unit outward normal
    float v = 0.0f;
};

// Points joined smoothly (shared normals). Consecutive strokes meet at a hard edge: the next
// stroke starts at the same position with its own normal, so the vertices are split there.
struct Stroke {
    StrokeUv uv = StrokeUv::Lathe;
    std::vector<ProfilePoint> points;
};

class Profile {
public:
    void start(glm::vec2 position, glm::vec2 normal, StrokeUv uv = StrokeUv::Lathe)
    {
        m_strokes.push_back(Stroke {uv, {}});
        to(position, normal);
    }
    // A hard edge at the current point: a new stroke that starts there with another normal.
    void corner(glm::vec2 normal, StrokeUv uv = StrokeUv::Lathe)
    {
        const glm::vec2 at = m_strokes.back().points.back().position;
        start(at, normal, uv);
    }
    void to(glm::vec2 position, glm::vec2 normal)
    {
        m_strokes.back().points.push_back({position, glm::normalize(normal), 0.0f});
    }
    // A circular arc about `centre` from angle a0 to a1 (radians, from +r toward +y), outward
    // normals, in `steps` pieces. Without the start point when the stroke already ends there.
    void arc(glm::vec2 centre, float radius, float a0, float a1, int steps, bool includeStart)
    {
        for (int k = includeStart ? 0 : 1; k <= steps; ++k) {
            const float a = a0 + (a1 - a0) * float(k) / float(steps);
            to(arcPoint(centre, radius, a), {std::cos(a), std::sin(a)});
        }
    }
    static glm::vec2 arcPoint(glm::vec2 centre, float radius, float angle)
    {
        return centre + radius * glm::vec2(std::cos(angle), std::sin(angle));
    }

    // v of the lathe strokes: arc length along the profile, `metresPerUv` world units per UV.
    // Points within 1e-6 of the axis snap onto it (cos(pi/2) is not 0 in float).
    std::vector<Stroke> finish(float metresPerUv)
    {
        float length = 0.0f;
        glm::vec2 previous = m_strokes.front().points.front().position;
        for (Stroke& stroke : m_strokes)
            for (ProfilePoint& p : stroke.points) {
                if (std::abs(p.position.x) < 1e-6f) {
                    p.position.x = 0.0f;
                    p.normal = {0.0f, p.normal.y < 0.0f ? -1.0f : 1.0f};
                }
                if (stroke.uv == StrokeUv::Lathe)
                    length += glm::length(p.position - previous);
                previous = p.position;
                p.v = length / metresPerUv;
            }
        return m_strokes;
    }

private:
    std::vector<Stroke> m_strokes;
};

Mesh revolve(const std::string& name, const std::vector<Stroke>& strokes, int segments, float uRepeat)
{
    Mesh mesh;
    mesh.name = name;
    // One cosine/sine per column, indexed modulo `segments`, so the u = 1 column repeats the
    // u = 0 column's positions bit for bit and the seam welds exactly.
    std::vector<float> cosPhi(std::size_t(segments) + 1), sinPhi(std::size_t(segments) + 1);
    const auto phiOf = [&](float u) { return kPi - 2.0f * kPi * u; }; // u = 0.5 - phi / (2 pi)
    for (int j = 0; j <= segments; ++j) {
        const float phi = phiOf(float(j % segments) / float(segments));
        cosPhi[std::size_t(j)] = std::cos(phi);
        sinPhi[std::size_t(j)] = std::sin(phi);
    }

    const auto makeVertex = [&](const ProfilePoint& p, StrokeUv uvMode, float u, float c, float s) {
        Vertex v;
        v.position = {p.position.x * c, p.position.y, p.position.x * s};
        v.normal = glm::normalize(glm::vec3(p.normal.x * c, p.normal.y, p.normal.x * s));
        if (uvMode == StrokeUv::Lathe) {
            // dP/du is along the circle of latitude: (sin phi, 0, -cos phi) for growing u.
            v.tangent = {s, 0.0f, -c, 1.0f};
            v.uv = {u * uRepeat, p.v};
        } else {
            v.tangent = {1.0f, 0.0f, 0.0f, 1.0f};
            const float flip = uvMode == StrokeUv::PlanarUp ? -1.0f : 1.0f;
            v.uv = {0.5f + 0.5f * v.position.x, 0.5f + flip * 0.5f * v.position.z};
        }
        return v;
    };

    for (const Stroke& stroke : strokes) {
        std::vector<uint32_t> rowStart;
        std::vector<bool> rowIsPole;
        for (const ProfilePoint& p : stroke.points) {
            rowStart.push_back(uint32_t(mesh.vertices.size()));
            const bool pole = p.position.x == 0.0f;
            rowIsPole.push_back(pole);
            if (pole) {
                // One vertex per segment at mid-segment u, its tangent along that u's latitude
                // direction: the fan's triangles then each see a sensible tangent.
                for (int j = 0; j < segments; ++j) {
                    const float u = (float(j) + 0.5f) / float(segments);
                    const float phi = phiOf(u);
                    mesh.vertices.push_back(makeVertex(p, stroke.uv, u, std::cos(phi), std::sin(phi)));
                }
            } else {
                for (int j = 0; j <= segments; ++j)
                    mesh.vertices.push_back(makeVertex(p, stroke.uv, float(j) / float(segments),
                        cosPhi[std::size_t(j)], sinPhi[std::size_t(j)]));
            }
        }
        for (std::size_t row = 0; row + 1 < stroke.points.size(); ++row) {
            if (stroke.points[row].position == stroke.points[row + 1].position)
                continue; // zero-length piece: it would give only degenerate triangles
            const uint32_t a = rowStart[row], b = rowStart[row + 1];
            const bool aPole = rowIsPole[row], bPole = rowIsPole[row + 1];
            for (uint32_t j = 0; j < uint32_t(segments); ++j) {
                if (aPole && bPole)
                    break;
                if (aPole) {
                    mesh.indices.insert(mesh.indices.end(), {a + j, b + j + 1, b + j});
                } else if (bPole) {
                    mesh.indices.insert(mesh.indices.end(), {a + j, a + j + 1, b + j});
                } else {
                    mesh.indices.insert(mesh.indices.end(), {a + j, a + j + 1, b + j + 1});
                    mesh.indices.insert(mesh.indices.end(), {a + j, b + j + 1, b + j});
                }
            }
        }
    }
    return mesh;
}

// Common finishing of every primitive: one sub-mesh, flags, bounds.
Mesh finished(Mesh mesh)
{
    mesh.subMeshes = {SubMesh {mesh.name, 0, uint32_t(mesh.indices.size()), 0, true}};
    mesh.hasUvs = true;
    mesh.uvsGenerated = false;
    mesh.hasTangents = true;
    mesh.updateBounds();
    return mesh;
}

} // namespace

Mesh makeSphere(int segments, int rings)
{
    segments = clampTessellation(segments, 3);
    rings = clampTessellation(rings, 2);
    std::vector<Stroke> strokes(1);
    for (int i = 0; i <= rings; ++i) {
        const float v = float(i) / float(rings);
        const float latitude = kPi * (v - 0.5f);
        // Exact poles: r = 0 and y = +-1, so the pole rows are recognised and weld.
        const float r = i == 0 || i == rings ? 0.0f : std::cos(latitude);
        const float y = i == 0 ? -1.0f : (i == rings ? 1.0f : std::sin(latitude));
        strokes[0].points.push_back({{r, y}, glm::normalize(glm::vec2(r, y)), v});
    }
    return finished(revolve("sphere", strokes, segments, 1.0f));
}

Mesh makeCube()
{
    Mesh mesh;
    mesh.name = "cube";
    for (const BoxFace& face : boxProjectionFaces()) {
        const auto base = uint32_t(mesh.vertices.size());
        const glm::vec2 corners[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (const glm::vec2& uv : corners) {
            Vertex v;
            v.position
                = face.normal + (2.0f * uv.x - 1.0f) * face.tangent + (2.0f * uv.y - 1.0f) * face.bitangent;
            v.normal = face.normal;
            v.tangent = glm::vec4(face.tangent, 1.0f);
            v.uv = uv;
            mesh.vertices.push_back(v);
        }
        // Counter-clockwise in UV is counter-clockwise from outside: cross(tangent, bitangent) = normal.
        mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return finished(std::move(mesh));
}

Mesh makePlane(int subdivisions)
{
    const int n = clampTessellation(subdivisions, 1);
    Mesh mesh;
    mesh.name = "plane";
    for (int j = 0; j <= n; ++j)
        for (int i = 0; i <= n; ++i) {
            Vertex v;
            v.uv = {float(i) / float(n), float(j) / float(n)};
            v.position = {2.0f * v.uv.x - 1.0f, 0.0f, 1.0f - 2.0f * v.uv.y};
            v.normal = {0.0f, 1.0f, 0.0f};
            v.tangent = {1.0f, 0.0f, 0.0f, 1.0f}; // dP/du = +X; dP/dv = -Z = cross(+Y, +X)
            mesh.vertices.push_back(v);
        }
    const auto at = [&](int i, int j) { return uint32_t(j * (n + 1) + i); };
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            mesh.indices.insert(mesh.indices.end(),
                {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    return finished(std::move(mesh));
}

Mesh makeCylinder(int segments)
{
    segments = clampTessellation(segments, 3);
    Profile profile;
    profile.start({0.0f, -1.0f}, {0.0f, -1.0f}, StrokeUv::PlanarDown);
    profile.to({1.0f, -1.0f}, {0.0f, -1.0f});
    profile.corner({1.0f, 0.0f});
    profile.to({1.0f, 1.0f}, {1.0f, 0.0f});
    profile.corner({0.0f, 1.0f}, StrokeUv::PlanarUp);
    profile.to({0.0f, 1.0f}, {0.0f, 1.0f});
    // Side v from 0 to 1 over its height of 2; u three times around (circumference 2 pi ~ 3 x 2).
    return finished(revolve("cylinder", profile.finish(2.0f), segments, 3.0f));
}

Mesh makeTorus(int segments, int sides)
{
    segments = clampTessellation(segments, 3);
    sides = clampTessellation(sides, 3);
    constexpr float majorRadius = 0.7f, tubeRadius = 0.3f;
    // The tube's circle, once around from its inner equator, angles indexed modulo `sides` so
    // the v = 0/1 seam welds exactly.
    std::vector<Stroke> strokes(1);
    for (int k = 0; k <= sides; ++k) {
        const float psi = kPi + 2.0f * kPi * float(k % sides) / float(sides);
        const glm::vec2 normal(std::cos(psi), std::sin(psi));
        strokes[0].points.push_back(
            {glm::vec2(majorRadius, 0.0f) + tubeRadius * normal, normal, float(k) / float(sides)});
    }
    // u twice around: the ring's centre line (2 pi 0.7 = 4.4) is about twice the tube's girth (1.9).
    Mesh mesh = revolve("torus", strokes, segments, 2.0f);
    // Stand it up: +Y (the lathe axis) to +Z, a rotation of +90 degrees about +X, done by
    // swizzling (x, y, z) -> (x, -z, y) so no rounding breaks the welds.
    const auto turn = [](glm::vec3 p) { return glm::vec3(p.x, -p.z, p.y); };
    for (Vertex& v : mesh.vertices) {
        v.position = turn(v.position);
        v.normal = turn(v.normal);
        v.tangent = glm::vec4(turn(glm::vec3(v.tangent)), v.tangent.w);
    }
    return finished(std::move(mesh));
}

Mesh makeShaderBall(int segments)
{
    segments = clampTessellation(segments, 3);
    // Dimensions (world units). The ball: centre (0, 0.15), radius 0.8, top at y = 0.95. The
    // band: between latitudes -+10.3 degrees, recessed 0.06 deep. The base: radius 0.5, from
    // y = -0.95 to -0.85 with a 0.04 rounded top edge. The neck: radius 0.2.
    const glm::vec2 ballCentre(0.0f, 0.15f);
    constexpr float ballRadius = 0.8f, bandRadius = 0.74f, bandHalfAngle = 0.18f;
    constexpr float baseRadius = 0.5f, baseBottom = -0.95f, baseTop = -0.85f, bevel = 0.04f;
    constexpr float neckRadius = 0.2f;
    // Latitude where the neck meets the ball: r = ballRadius cos(latitude) = neckRadius.
    const float neckLatitude = -std::acos(neckRadius / ballRadius);
    // About 3 degrees per arc step at the default 96 segments (3.75 degrees around).
    const auto steps = [](float radians) { return std::max(2, int(std::ceil(radians / 0.055f))); };

    Profile profile;
    // Base: underside, then the side and its rounded top edge and the top, one smooth stroke.
    profile.start({0.0f, baseBottom}, {0.0f, -1.0f}, StrokeUv::PlanarDown);
    profile.to({baseRadius, baseBottom}, {0.0f, -1.0f});
    profile.corner({1.0f, 0.0f});
    profile.arc({baseRadius - bevel, baseTop - bevel}, bevel, 0.0f, kPi / 2.0f, 6, true);
    profile.to({neckRadius, baseTop}, {0.0f, 1.0f});
    // Neck, up to the ball.
    profile.corner({1.0f, 0.0f});
    profile.to(Profile::arcPoint(ballCentre, ballRadius, neckLatitude), {1.0f, 0.0f});
    // Lower half of the ball, down to the band.
    profile.corner({std::cos(neckLatitude), std::sin(neckLatitude)});
    profile.arc(
        ballCentre, ballRadius, neckLatitude, -bandHalfAngle, steps(neckLatitude + bandHalfAngle), false);
    // The band: lower wall (facing up into the groove), floor, upper wall (facing down).
    profile.corner({std::sin(bandHalfAngle), std::cos(bandHalfAngle)});
    profile.to(Profile::arcPoint(ballCentre, bandRadius, -bandHalfAngle),
        {std::sin(bandHalfAngle), std::cos(bandHalfAngle)});
    profile.corner({std::cos(-bandHalfAngle), std::sin(-bandHalfAngle)});
    profile.arc(ballCentre, bandRadius, -bandHalfAngle, bandHalfAngle, steps(2.0f * bandHalfAngle), false);
    profile.corner({std::sin(bandHalfAngle), -std::cos(bandHalfAngle)});
    profile.to(Profile::arcPoint(ballCentre, ballRadius, bandHalfAngle),
        {std::sin(bandHalfAngle), -std::cos(bandHalfAngle)});
    // Upper half of the ball, to the pole.
    profile.corner({std::cos(bandHalfAngle), std::sin(bandHalfAngle)});
    profile.arc(ballCentre, ballRadius, bandHalfAngle, kPi / 2.0f, steps(kPi / 2.0f - bandHalfAngle), false);

    // v: 2 world units per UV unit, as the other primitives; u three times around (the ball's
    // girth 2 pi 0.8 = 5.0 is about 3 x 2), which keeps texels near square on the ball.
    return finished(revolve("shaderball", profile.finish(2.0f), segments, 3.0f));
}

std::span<const std::string_view> primitiveNames()
{
    static constexpr std::array<std::string_view, 6> names {
        "sphere", "cube", "plane", "cylinder", "torus", "shaderball"};
    return names;
}

std::optional<Mesh> makePrimitive(std::string_view name)
{
    if (name == "sphere")
        return makeSphere();
    if (name == "cube")
        return makeCube();
    if (name == "plane")
        return makePlane();
    if (name == "cylinder")
        return makeCylinder();
    if (name == "torus")
        return makeTorus();
    if (name == "shaderball")
        return makeShaderBall();
    return std::nullopt;
}

} // namespace facet
