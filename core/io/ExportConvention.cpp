// The file's convention (ExportScene.h: conventionFor, converted): a scene in
// the rig's metres and Y-up converted to a file's units and up axis, its
// roots turned into a Z-up frame in a Y-up file, joints, controllers,
// cameras, meshes and every clip's keys and slopes alike.
#include "io/ExportScene.h"

#include <cmath>

namespace rs::io {

Convention conventionFor(ExportPreset preset, bool fbx)
{
    // glTF fixes metres and Y-up; Unreal's glTF importer converts on its side.
    if (preset == ExportPreset::Unreal && fbx)
        return {kCentimetresPerMetre, true}; // Z-up centimetres
    return {};
}

namespace {

Mat4 conjugate(const Mat4& m, const Mat4& basis, double scale)
{
    Mat4 out = basis * m * glm::transpose(basis);
    out[3] = Vec4(Vec3(out[3]) * scale, 1.0);
    return out;
}

// A Y-up file's root joints take a Z-up frame (Z up, Y back), as the roots of
// Blender's and Unreal's skeletons do: an identity root points its +Y, the
// bone axis Blender infers, straight at a hips joint above it, and Blender's
// FBX importer then connects the hips to the root and ignores their location
// curves. C = -90 degrees about X permutes the root's Y and Z axes, so
// root' = root * C and child' = C^-1 * child keep every world transform,
// with the root's scale's y and z swapped.
void turnRootsUp(ExportScene& scene)
{
    const Mat4 turn = rotationMatrix(Vec3(1, 0, 0), glm::radians(-90.0));
    const Mat4 back = glm::transpose(turn);
    const Quat c = glm::quat_cast(Mat3(turn)), cInverse = glm::conjugate(c);
    const Mat3 backRotation(back);
    auto swapYz = [](const Vec3& v) { return Vec3(v.x, v.z, v.y); };
    std::vector<int> role(scene.joints.size(), 0); // 1: a root, 2: a root's child
    for (std::size_t j = 0; j < scene.joints.size(); ++j) {
        ExportJoint& joint = scene.joints[j];
        if (joint.parent < 0) {
            role[j] = 1;
            joint.bindWorld = joint.bindWorld * turn;
            joint.bindLocal = joint.bindLocal * turn;
            joint.poseLocal = joint.poseLocal * turn;
        } else if (scene.joints[std::size_t(joint.parent)].parent < 0) {
            role[j] = 2;
            joint.bindLocal = back * joint.bindLocal;
            joint.poseLocal = back * joint.poseLocal;
        }
    }
    for (auto& clip : scene.clips)
        for (auto& track : clip.tracks) {
            if (track.controller || track.camera || role[std::size_t(track.node)] == 0)
                continue;
            if (role[std::size_t(track.node)] == 1) {
                for (auto& r : track.rotations)
                    r = r * c;
                for (auto& r : track.rotationSlopes)
                    r = r * c;
                for (auto& s : track.scales)
                    s = swapYz(s);
                for (auto& s : track.scaleSlopes)
                    s = swapYz(s);
            } else {
                for (auto& t : track.translations)
                    t = backRotation * t;
                for (auto& t : track.translationSlopes)
                    t = backRotation * t;
                for (auto& r : track.rotations)
                    r = cInverse * r;
                for (auto& r : track.rotationSlopes)
                    r = cInverse * r;
            }
        }
}

} // namespace

ExportScene converted(ExportScene scene, const Convention& convention)
{
    if (!convention.zUp)
        turnRootsUp(scene);
    if (convention.unitsPerMetre == 1.0 && !convention.zUp)
        return scene;
    const double s = convention.unitsPerMetre;
    // Y-up to Z-up: +90 degrees about X (y -> z, z -> -y).
    const Mat4 basis = convention.zUp ? rotationMatrix(Vec3(1, 0, 0), glm::radians(90.0)) : Mat4(1.0);
    const Quat q = glm::quat_cast(Mat3(basis));
    for (auto& j : scene.joints) {
        j.bindWorld = conjugate(j.bindWorld, basis, s);
        j.bindLocal = conjugate(j.bindLocal, basis, s);
        j.poseLocal = conjugate(j.poseLocal, basis, s);
    }
    for (auto& c : scene.controllers) {
        c.poseLocal = conjugate(c.poseLocal, basis, s);
        for (auto& [channel, value] : c.defaults) // channel box values: only distances change unit
            if (channel == "tx" || channel == "ty" || channel == "tz")
                value *= s;
    }
    // A camera keeps its own axes (it looks down its -Z): the basis turns its
    // frame, it does not conjugate it.
    for (auto& camera : scene.cameras) {
        camera.poseWorld = basis * camera.poseWorld;
        camera.poseWorld[3] = Vec4(Vec3(camera.poseWorld[3]) * s, 1.0);
        camera.nearClip *= s;
        camera.farClip *= s;
    }
    const glm::mat3 rotation = glm::mat3(Mat3(basis));
    for (auto& mesh : scene.meshes) {
        for (auto& p : mesh.positions)
            p = rotation * p * float(s);
        for (auto& n : mesh.normals)
            n = rotation * n;
    }
    for (auto& clip : scene.clips)
        for (auto& track : clip.tracks) {
            for (auto& t : track.translations)
                t = Mat3(basis) * t * s;
            for (auto& r : track.rotations)
                r = track.camera ? q * r : q * r * glm::conjugate(q);
            for (auto& sc : track.scales)
                sc = glm::abs(Mat3(basis) * sc);
            // Slopes change as their values do (scales are positive: the
            // permutation's signs are what abs() took off the values).
            for (auto& t : track.translationSlopes)
                t = Mat3(basis) * t * s;
            for (auto& r : track.rotationSlopes)
                r = track.camera ? q * r : q * r * glm::conjugate(q);
            const Vec3 signs = glm::sign(Mat3(basis) * Vec3(1.0));
            for (auto& sc : track.scaleSlopes)
                sc = signs * (Mat3(basis) * sc);
        }
    return scene;
}

} // namespace rs::io
