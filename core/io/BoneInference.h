#pragma once
// What an FBX importer that makes bones out of joints infers from the file
// (Blender's io_scene_fbx, build_skeleton): a bone's tail lies on its joint's
// +Y axis, as far as the mean distance to its child joints, and a child whose
// head lies on that tail is *connected*. Blender ignores the location of a
// connected bone, so a clip that translates it plays wrong there. A Y-up
// export's root joints are turned so this cannot happen to them
// (io/ExportScene.h, converted()); for the rigger's own joints the FBX export
// warns, naming them, since only the rig's joint orientation can fix it.
#include "io/ExportScene.h"

#include <vector>

namespace rs::io {

// Indexes into scene.joints of the joints an importer would connect to their
// parent and whose translation a clip of `scene` animates or holds. The test
// is looser than Blender's (a relative 1e-6 per component, which float noise
// can defeat): a joint within 1e-6 of the inferred tail, relative to the
// bone's size, is named.
std::vector<int> connectedMovingJoints(const ExportScene& scene);

} // namespace rs::io
