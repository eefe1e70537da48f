#include "skin/Visibility.h"

#include <embree3/rtcore.h>

#include <array>

namespace rs::skin {

struct Visibility::Impl {
    RTCDevice device = nullptr;
    RTCScene scene = nullptr;
};

namespace {

void attachTriangles(RTCDevice device, RTCScene scene, const std::vector<glm::vec3>& positions,
                     const std::vector<std::array<std::uint32_t, 3>>& triangles)
{
    if (triangles.empty())
        return;
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), positions.size()));
    for (std::size_t v = 0; v < positions.size(); ++v)
        for (int k = 0; k < 3; ++k)
            vertices[3 * v + std::size_t(k)] = positions[v][k];
    auto* indices = static_cast<unsigned*>(
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles.size()));
    for (std::size_t t = 0; t < triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            indices[3 * t + std::size_t(k)] = triangles[t][std::size_t(k)];
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
}

} // namespace

Visibility::Visibility(const Surface& surface, const std::vector<const model::Mesh*>& occluders) : m(std::make_unique<Impl>())
{
    m->device = rtcNewDevice("threads=1"); // queries run on the caller's threads
    m->scene = rtcNewScene(m->device);
    std::vector<glm::vec3> positions(surface.positions.begin(), surface.positions.end());
    attachTriangles(m->device, m->scene, positions, surface.triangles);
    for (const model::Mesh* mesh : occluders) {
        std::vector<std::array<std::uint32_t, 3>> triangles;
        for (std::size_t t = 0; t + 2 < mesh->indices.size(); t += 3) {
            const std::array<std::uint32_t, 3> tri{mesh->indices[t], mesh->indices[t + 1], mesh->indices[t + 2]};
            if (tri[0] < mesh->positions.size() && tri[1] < mesh->positions.size() && tri[2] < mesh->positions.size())
                triangles.push_back(tri);
        }
        attachTriangles(m->device, m->scene, mesh->positions, triangles);
    }
    rtcCommitScene(m->scene);
}

Visibility::~Visibility()
{
    if (m->scene)
        rtcReleaseScene(m->scene);
    if (m->device)
        rtcReleaseDevice(m->device);
}

bool Visibility::clear(const Vec3& from, const Vec3& to, double margin) const
{
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = float(from.x);
    ray.org_y = float(from.y);
    ray.org_z = float(from.z);
    const Vec3 d = to - from;
    ray.dir_x = float(d.x);
    ray.dir_y = float(d.y);
    ray.dir_z = float(d.z);
    ray.tnear = float(margin);
    ray.tfar = float(1.0 - margin);
    ray.mask = 0xffffffffu;
    ray.flags = 0;
    rtcOccluded1(m->scene, &context, &ray);
    return ray.tfar >= 0.0f; // set to -inf when something was hit
}

} // namespace rs::skin
