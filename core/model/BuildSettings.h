#pragma once
// How a guide is built, saved with the guide (`build:` in the guide file, only
// when it differs from these defaults): which override kinds a build restores
// and whether it cleans the rig up for animators. The command line's
// `--no-restore KIND` adds to the guide's toggles and `--cleanup` /
// `--no-cleanup` replace its cleanup for one build.
#include "model/Override.h"

namespace rs::model {

struct BuildSettings {
    // Which override kinds a build applies (all by default); the records of a
    // kind switched off stay in the guide.
    RestoreToggles restore;
    // Cleanup (rigging/CleanupStage.h): setup groups and skin joints hidden,
    // every channel a template does not declare animatable locked and hidden,
    // each controller's animatable defaults recorded (and exported). Off by
    // default, as Mikan's `dev` mode: a rigger iterating in the editor sees
    // and poses everything; turned on in the guide, every build of it (the
    // editor's, rigsmith-cli's exports) is the animators' rig.
    bool cleanup = false;

    bool isDefault() const { return *this == BuildSettings{}; }
    bool operator==(const BuildSettings&) const = default;
};

} // namespace rs::model
