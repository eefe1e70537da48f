#pragma once
// The rig's cameras in an export (internal to io/ExportScene.cpp and
// io/ExportMotion.cpp). A camera is a node of the rig's "cameras" set
// (util.camera's view node, rigging/Plugins.cpp): aimed at its target and
// rolled, looking down its -Z with +Y up. Its lens is the attributes of the
// nearest node above it that carries `focal_length` (the camera controller):
// focal_length (mm), horizontal_aperture / vertical_aperture (film back,
// inches), near_clip / far_clip (metres), orthographic (enum), ortho_width (metres).
#include "eval/RigProgram.h"
#include "io/ExportScene.h"

#include <nlohmann/json.hpp>

#include <vector>

namespace rs::io {

// The rig nodes of the scene's cameras: the view node and the node carrying
// its lens (kNoNode: none; the lens keeps ExportCamera's defaults).
struct CameraNodes {
    std::vector<model::RigNodeIndex> views, lenses;
};

// One ExportCamera per node of the rig's "cameras" set, at its rest frame,
// with the lens attributes' default values.
void addCameras(const model::Rig& rig, ExportScene& scene, CameraNodes& nodes);

// A camera's frame from its view node's world matrix: the scale taken out
// (a scaled camera controller does not scale what the camera sees).
Mat4 cameraFrame(const Mat4& world);

// The lens attributes of `lens` in `pose` (the channels' values) on `camera`.
void applyLens(ExportCamera& camera, const eval::RigProgram& program, const eval::Pose& pose, model::RigNodeIndex lens);
// The focal length in `pose` (millimetres), `fallback` when `lens` has none.
double focalLengthIn(const eval::RigProgram& program, const eval::Pose& pose, model::RigNodeIndex lens, double fallback);

// Each camera's name, lens (focal length, film back, yfov) and its world
// position and look direction (-Z) at rest and at five key times of each clip
// that moves it, for the consumer checks (exportReferenceJson).
nlohmann::json camerasJson(const ExportScene& scene);

} // namespace rs::io
