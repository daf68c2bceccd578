#include "core/truth/RayScene.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <embree3/rtcore.h>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "core/mesh/Mesh.h"
#include "core/shading/ReferenceView.h"

namespace facet {

namespace {

// One triangle geometry's own data, in world space, for what a hit interpolates.
struct TriangleSurface {
    int surface = 0;
    std::vector<glm::uvec3> triangles;
    std::vector<glm::dvec3> normals; // per vertex, unit
    std::vector<glm::dvec4> tangents; // per vertex
    std::vector<glm::dvec2> uvs; // per vertex
};

glm::dvec3 unitOr(const glm::dvec3& v, const glm::dvec3& fallback)
{
    const double length = glm::length(v);
    return length > 0.0 && std::isfinite(length) ? v / length : fallback;
}

} // namespace

struct RayScene::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
    bool committed = false;
    int surfaces = 0;
    int sphereSurface = -1;
    // Indexed by Embree's geometry id (attached in order from 0).
    std::vector<TriangleSurface> triangleSurfaces;
    // Geometries made before commit(), attached there.
    struct PendingGeometry {
        std::vector<float> positions; // xyz per vertex
    };
    std::vector<PendingGeometry> pending;

    ~Impl()
    {
        if (scene)
            rtcReleaseScene(scene);
        if (device)
            rtcReleaseDevice(device);
    }
};

RayScene::RayScene()
    : m(std::make_unique<Impl>())
{
}

RayScene::~RayScene() = default;
RayScene::RayScene(RayScene&&) noexcept = default;
RayScene& RayScene::operator=(RayScene&&) noexcept = default;

int RayScene::addUnitSphere()
{
    if (m->sphereSurface < 0)
        m->sphereSurface = m->surfaces++;
    return m->sphereSurface;
}

int RayScene::addMesh(const Mesh& mesh, const glm::dmat4& model)
{
    TriangleSurface surface;
    surface.surface = m->surfaces++;
    Impl::PendingGeometry geometry;
    const glm::dmat3 normalMatrix = glm::transpose(glm::inverse(glm::dmat3(model)));
    const glm::dmat3 linear(model);
    geometry.positions.reserve(mesh.vertices.size() * 3);
    surface.normals.reserve(mesh.vertices.size());
    surface.tangents.reserve(mesh.vertices.size());
    surface.uvs.reserve(mesh.vertices.size());
    const bool mirrored = glm::determinant(linear) < 0.0;
    for (const Vertex& vertex : mesh.vertices) {
        const glm::dvec3 p(model * glm::dvec4(glm::dvec3(vertex.position), 1.0));
        geometry.positions.insert(geometry.positions.end(), {float(p.x), float(p.y), float(p.z)});
        const glm::dvec3 n = unitOr(normalMatrix * glm::dvec3(vertex.normal), glm::dvec3(0.0, 1.0, 0.0));
        surface.normals.push_back(n);
        const glm::dvec3 t
            = unitOr(linear * glm::dvec3(glm::vec3(vertex.tangent)), glm::dvec3(1.0, 0.0, 0.0));
        surface.tangents.emplace_back(t, mirrored ? -double(vertex.tangent.w) : double(vertex.tangent.w));
        surface.uvs.emplace_back(vertex.uv);
    }
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        glm::uvec3 triangle(mesh.indices[i], mesh.indices[i + 1], mesh.indices[i + 2]);
        if (mirrored)
            std::swap(triangle.y, triangle.z);
        surface.triangles.push_back(triangle);
    }
    m->triangleSurfaces.push_back(std::move(surface));
    m->pending.push_back(std::move(geometry));
    return m->triangleSurfaces.back().surface;
}

int RayScene::addFloor(double height, double size, const glm::dvec2& centre)
{
    TriangleSurface surface;
    surface.surface = m->surfaces++;
    Impl::PendingGeometry geometry;
    const double h = 0.5 * size;
    // Counter-clockwise seen from above (+Y): (x, z) corners.
    const glm::dvec2 corners[4] = {{-h, h}, {h, h}, {h, -h}, {-h, -h}};
    for (const glm::dvec2& corner : corners) {
        geometry.positions.insert(geometry.positions.end(),
            {float(centre.x + corner.x), float(height), float(centre.y + corner.y)});
        surface.normals.emplace_back(0.0, 1.0, 0.0);
        surface.tangents.emplace_back(1.0, 0.0, 0.0, 1.0);
        surface.uvs.emplace_back(corner.x / size + 0.5, 0.5 - corner.y / size);
    }
    surface.triangles = {{0u, 1u, 2u}, {0u, 2u, 3u}};
    m->triangleSurfaces.push_back(std::move(surface));
    m->pending.push_back(std::move(geometry));
    return m->triangleSurfaces.back().surface;
}

int RayScene::surfaceCount() const
{
    return m->surfaces;
}

bool RayScene::commit(std::string* error)
{
    const auto fail = [&](const char* what) {
        if (error) {
            const RTCError code = m->device ? rtcGetDeviceError(m->device) : RTC_ERROR_UNKNOWN;
            *error = std::string("Embree: ") + what + " (error " + std::to_string(int(code)) + ")";
        }
        return false;
    };
    if (m->committed)
        return true;
    // Embree's own threads are not wanted: the integrator runs its rows on every core and each
    // ray query runs on the thread that asks.
    m->device = rtcNewDevice("threads=1");
    if (!m->device)
        return fail("cannot create a device");
    m->scene = rtcNewScene(m->device);
    if (!m->scene)
        return fail("cannot create a scene");
    rtcSetSceneBuildQuality(m->scene, RTC_BUILD_QUALITY_HIGH);
    for (std::size_t g = 0; g < m->triangleSurfaces.size(); ++g) {
        const TriangleSurface& surface = m->triangleSurfaces[g];
        const Impl::PendingGeometry& pending = m->pending[g];
        RTCGeometry geometry = rtcNewGeometry(m->device, RTC_GEOMETRY_TYPE_TRIANGLE);
        if (!geometry)
            return fail("cannot create a triangle geometry");
        const std::size_t vertexCount = pending.positions.size() / 3;
        auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
            geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), vertexCount));
        auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0,
            RTC_FORMAT_UINT3, 3 * sizeof(unsigned), surface.triangles.size()));
        if (!vertices || !indices) {
            rtcReleaseGeometry(geometry);
            return fail("cannot allocate a geometry's buffers");
        }
        std::copy(pending.positions.begin(), pending.positions.end(), vertices);
        for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
            indices[3 * t] = surface.triangles[t].x;
            indices[3 * t + 1] = surface.triangles[t].y;
            indices[3 * t + 2] = surface.triangles[t].z;
        }
        rtcCommitGeometry(geometry);
        const unsigned id = rtcAttachGeometry(m->scene, geometry);
        rtcReleaseGeometry(geometry);
        if (id != unsigned(g))
            return fail("geometry ids out of order");
    }
    rtcCommitScene(m->scene);
    if (rtcGetDeviceError(m->device) != RTC_ERROR_NONE)
        return fail("cannot build the scene");
    m->pending.clear();
    m->pending.shrink_to_fit();
    m->committed = true;
    return true;
}

namespace {

RTCRay toEmbree(const glm::dvec3& origin, const glm::dvec3& direction, double tMin, double tMax)
{
    RTCRay ray {};
    ray.org_x = float(origin.x);
    ray.org_y = float(origin.y);
    ray.org_z = float(origin.z);
    ray.dir_x = float(direction.x);
    ray.dir_y = float(direction.y);
    ray.dir_z = float(direction.z);
    ray.tnear = float(tMin);
    ray.tfar = std::isfinite(tMax) ? float(tMax) : std::numeric_limits<float>::infinity();
    ray.mask = 0xFFFFFFFFu;
    ray.time = 0.0f;
    ray.flags = 0;
    return ray;
}

// The unit sphere's nearest root of |o + t d|^2 = 1 in (tMin, tMax).
std::optional<double> sphereDistance(
    const glm::dvec3& origin, const glm::dvec3& direction, double tMin, double tMax)
{
    const double b = glm::dot(origin, direction);
    const double c = glm::dot(origin, origin) - referenceview::kSphereRadius * referenceview::kSphereRadius;
    const double discriminant = b * b - c;
    if (discriminant < 0.0)
        return std::nullopt;
    const double root = std::sqrt(discriminant);
    // The nearer root first; the farther one when the ray starts inside.
    for (const double t : {-b - root, -b + root})
        if (t > tMin && t < tMax)
            return t;
    return std::nullopt;
}

} // namespace

std::optional<RayHit> RayScene::intersect(
    const glm::dvec3& origin, const glm::dvec3& direction, double tMin, double tMax) const
{
    std::optional<RayHit> best;
    if (!m->triangleSurfaces.empty() && m->committed) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit query {};
        query.ray = toEmbree(origin, direction, tMin, tMax);
        query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(m->scene, &context, &query);
        if (query.hit.geomID != RTC_INVALID_GEOMETRY_ID) {
            const TriangleSurface& surface = m->triangleSurfaces[query.hit.geomID];
            const glm::uvec3 triangle = surface.triangles[query.hit.primID];
            const double u = query.hit.u;
            const double v = query.hit.v;
            const double w = 1.0 - u - v;
            RayHit hit;
            hit.distance = query.ray.tfar;
            hit.position = origin + hit.distance * direction;
            // Embree's Ng is the unnormalised (p1 - p0) x (p2 - p0): outward for counter-clockwise.
            hit.geometricNormal = unitOr(
                glm::dvec3(query.hit.Ng_x, query.hit.Ng_y, query.hit.Ng_z), surface.normals[triangle.x]);
            hit.shadingNormal = unitOr(w * surface.normals[triangle.x] + u * surface.normals[triangle.y]
                    + v * surface.normals[triangle.z],
                hit.geometricNormal);
            const glm::dvec4 tangent = w * surface.tangents[triangle.x] + u * surface.tangents[triangle.y]
                + v * surface.tangents[triangle.z];
            hit.tangent = glm::dvec4(
                unitOr(glm::dvec3(tangent), glm::dvec3(1.0, 0.0, 0.0)), surface.tangents[triangle.x].w);
            hit.uv = w * surface.uvs[triangle.x] + u * surface.uvs[triangle.y] + v * surface.uvs[triangle.z];
            hit.surface = surface.surface;
            if (glm::dot(hit.geometricNormal, direction) > 0.0) {
                hit.backFace = true;
                hit.geometricNormal = -hit.geometricNormal;
                hit.shadingNormal = -hit.shadingNormal;
            }
            best = hit;
            tMax = hit.distance;
        }
    }
    if (m->sphereSurface >= 0)
        if (const std::optional<double> t = sphereDistance(origin, direction, tMin, tMax)) {
            RayHit hit;
            hit.distance = *t;
            hit.position = origin + *t * direction;
            const glm::dvec3 outward = glm::normalize(hit.position);
            hit.backFace = glm::dot(outward, direction) > 0.0;
            hit.geometricNormal = hit.backFace ? -outward : outward;
            hit.shadingNormal = hit.geometricNormal;
            hit.tangent = referenceview::sphereTangent(outward);
            hit.surface = m->sphereSurface;
            best = hit;
        }
    return best;
}

bool RayScene::occluded(const glm::dvec3& origin, const glm::dvec3& direction, double tMin, double tMax) const
{
    if (m->sphereSurface >= 0 && sphereDistance(origin, direction, tMin, tMax))
        return true;
    if (m->triangleSurfaces.empty() || !m->committed)
        return false;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray = toEmbree(origin, direction, tMin, tMax);
    rtcOccluded1(m->scene, &context, &ray);
    // Embree sets tfar to -inf when something blocks the ray.
    return ray.tfar < 0.0f;
}

} // namespace facet
