#include "io/ExportCamera.h"

#include <algorithm>
#include <cmath>

namespace rs::io {

namespace {

constexpr double kMillimetresPerInch = 25.4;

// The nearest node above `view` (itself included) with a focal_length attribute.
model::RigNodeIndex lensNodeOf(const model::Rig& rig, model::RigNodeIndex view)
{
    for (model::RigNodeIndex n = view; n != model::kNoNode; n = rig.nodes[n].parent)
        if (rig.nodes[n].attribute("focal_length"))
            return n;
    return model::kNoNode;
}

double valueIn(const eval::RigProgram& program, const eval::Pose& pose, model::RigNodeIndex node, const char* name,
               double fallback)
{
    if (node == model::kNoNode)
        return fallback;
    const auto channel = program.channels().find(node, name);
    return channel && std::size_t(*channel) < pose.size() ? pose[std::size_t(*channel)] : fallback;
}

nlohmann::json placement(const Mat4& world)
{
    const Vec3 p = translationOf(world);
    const Vec3 look = glm::normalize(-Vec3(world[2]));
    const Vec3 up = glm::normalize(Vec3(world[1]));
    return {{"position", {p.x, p.y, p.z}}, {"look", {look.x, look.y, look.z}}, {"up", {up.x, up.y, up.z}}};
}

} // namespace

double verticalFieldOfView(const ExportCamera& camera, double focalLength)
{
    return 2.0 * std::atan(0.5 * camera.filmHeight * kMillimetresPerInch / focalLength);
}

double horizontalFieldOfView(const ExportCamera& camera, double focalLength)
{
    return 2.0 * std::atan(0.5 * camera.filmWidth * kMillimetresPerInch / focalLength);
}

void addCameras(const model::Rig& rig, ExportScene& scene, CameraNodes& nodes)
{
    const auto set = rig.sets.find("cameras");
    if (set == rig.sets.end())
        return;
    for (model::RigNodeIndex view : set->second) {
        const model::RigNode& node = rig.nodes[view];
        ExportCamera camera;
        camera.name = node.name;
        camera.id = node.path;
        camera.poseWorld = cameraFrame(node.worldMatrix);
        const model::RigNodeIndex lens = lensNodeOf(rig, view);
        if (lens != model::kNoNode) {
            const model::RigNode& owner = rig.nodes[lens];
            auto value = [&](const char* name, double fallback) {
                const model::RigAttribute* a = owner.attribute(name);
                return a ? a->value : fallback;
            };
            camera.focalLength = value("focal_length", camera.focalLength);
            camera.filmWidth = value("horizontal_aperture", camera.filmWidth);
            camera.filmHeight = value("vertical_aperture", camera.filmHeight);
            camera.nearClip = value("near_clip", camera.nearClip);
            camera.farClip = value("far_clip", camera.farClip);
            camera.orthographic = value("orthographic", 0.0) >= 0.5;
            camera.orthoWidth = value("ortho_width", camera.orthoWidth);
        }
        scene.cameras.push_back(camera);
        nodes.views.push_back(view);
        nodes.lenses.push_back(lens);
    }
}

Mat4 cameraFrame(const Mat4& world)
{
    Vec3 t, s;
    Quat r;
    decompose(world, t, r, s);
    Mat4 out = glm::mat4_cast(glm::normalize(r));
    out[3] = Vec4(t, 1.0);
    return out;
}

void applyLens(ExportCamera& camera, const eval::RigProgram& program, const eval::Pose& pose, model::RigNodeIndex lens)
{
    camera.focalLength = valueIn(program, pose, lens, "focal_length", camera.focalLength);
    camera.filmWidth = valueIn(program, pose, lens, "horizontal_aperture", camera.filmWidth);
    camera.filmHeight = valueIn(program, pose, lens, "vertical_aperture", camera.filmHeight);
    camera.nearClip = valueIn(program, pose, lens, "near_clip", camera.nearClip);
    camera.farClip = valueIn(program, pose, lens, "far_clip", camera.farClip);
    camera.orthographic = valueIn(program, pose, lens, "orthographic", camera.orthographic ? 1.0 : 0.0) >= 0.5;
    camera.orthoWidth = valueIn(program, pose, lens, "ortho_width", camera.orthoWidth);
}

double focalLengthIn(const eval::RigProgram& program, const eval::Pose& pose, model::RigNodeIndex lens, double fallback)
{
    return valueIn(program, pose, lens, "focal_length", fallback);
}

nlohmann::json camerasJson(const ExportScene& scene)
{
    using nlohmann::json;
    json cameras = json::array();
    for (std::size_t c = 0; c < scene.cameras.size(); ++c) {
        const ExportCamera& camera = scene.cameras[c];
        json out = {{"name", camera.name},
                    {"id", camera.id},
                    {"focal_length", camera.focalLength},
                    {"film", {camera.filmWidth, camera.filmHeight}},
                    {"yfov", verticalFieldOfView(camera, camera.focalLength)},
                    {"clip", {camera.nearClip, camera.farClip}},
                    {"rest", placement(camera.poseWorld)}};
        json samples = json::array();
        for (const ExportClip& clip : scene.clips)
            for (const ExportTrack& track : clip.tracks) {
                if (!track.camera || std::size_t(track.node) != c || clip.times.empty())
                    continue;
                const std::size_t last = clip.times.size() - 1;
                std::vector<std::size_t> keys;
                for (std::size_t q = 0; q <= 4; ++q)
                    keys.push_back(last * q / 4);
                keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
                for (std::size_t k : keys) {
                    Mat4 world = glm::mat4_cast(track.rotations[k]);
                    world[3] = Vec4(track.translations[k], 1.0);
                    json sample = placement(world);
                    sample["clip"] = clip.name;
                    sample["time"] = clip.times[k];
                    sample["focal_length"] = k < track.focalLengths.size() ? track.focalLengths[k] : camera.focalLength;
                    samples.push_back(std::move(sample));
                }
            }
        out["samples"] = std::move(samples);
        cameras.push_back(std::move(out));
    }
    return cameras;
}

} // namespace rs::io
