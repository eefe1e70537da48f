#pragma once
// Sampling the rig for an export's clips (internal to io/ExportMotion.cpp and
// io/ExportSampling.cpp): each scene node's local transform for an evaluated
// state, one sample per time, and the tracks the samples are appended to.
#include "eval/RigProgram.h"
#include "io/ExportCamera.h"
#include "io/ExportMotion.h"
#include "io/ExportScene.h"

#include <vector>

namespace rs::io {

// Local transforms of the scene's nodes for one evaluated state.
struct Sampler {
    const ExportScene& scene;
    const SceneNodes& nodes;

    Mat4 world(model::RigNodeIndex node, const eval::EvalState& state) const
    {
        return node == model::kNoNode ? Mat4(1.0) : state.worldMatrix(node);
    }
    Mat4 jointLocal(std::size_t j, const eval::EvalState& state) const
    {
        const int parent = scene.joints[j].parent;
        const Mat4 w = world(nodes.joints[j], state);
        return parent < 0 ? w : glm::inverse(world(nodes.joints[std::size_t(parent)], state)) * w;
    }
    Mat4 controllerLocal(std::size_t c, const eval::EvalState& state) const
    {
        const int parent = scene.controllers[c].parent;
        const Mat4 w = state.worldMatrix(nodes.controllers[c]);
        return parent < 0 ? w : glm::inverse(state.worldMatrix(nodes.controllers[std::size_t(parent)])) * w;
    }
    // Cameras sit at the scene root: their local transform is their frame.
    Mat4 cameraWorld(std::size_t c, const eval::EvalState& state) const
    {
        return cameraFrame(state.worldMatrix(nodes.cameras.views[c]));
    }
};

// One sampled time of a clip: every scene node's local transform (joints,
// controllers, then cameras) and each camera's focal length.
struct Sample {
    double frame = 0.0;
    std::vector<Vec3> translations, scales;
    std::vector<Quat> rotations;
    std::vector<double> focalLengths;
};

// The tracks of a clip before sampling: joints, controllers, then cameras (a Sample's order).
std::vector<ExportTrack> emptyTracks(const ExportScene& scene);

// Marks which channels of a sampled track change and which constant ones differ
// from the node's written transform (and a camera's lens).
void markTrack(ExportTrack& track, const ExportScene& scene);

// One key on every track of `clip`, each rotation on the hemisphere of the
// track's previous key (no half-turn flip between keys).
void appendSample(ExportClip& clip, const Sample& sample);

// The scene's nodes sampled at `frame` after evaluating `pose` into `state`.
Sample sampleAt(double frame, const eval::Pose& pose, const eval::RigProgram& program, const Sampler& sampler,
                eval::EvalState& state);

} // namespace rs::io
