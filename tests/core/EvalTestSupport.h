#pragma once
// A sample built and compiled for evaluation tests, with shorthands by node id.
#include "TestSupport.h"
#include "rigging/RigBuilder.h"
#include "eval/Pickwalk.h"
#include "eval/PoseTools.h"

#include <map>
#include <memory>
#include <string>

namespace rs::test {

// A new instance of `templateId` (its default guide, `options`) under the
// guide joint `under` (kNoId: top level), appended to `doc`; fails the test
// when the template refuses it.
model::TemplateInstance addInstance(model::GuideDocument& doc, const std::string& templateId, model::JointId under,
                                    const std::map<std::string, Value>& options = {});

// The biped sample with `options` set on its arm and leg instances (both
// sides: the L/R branches are one instance each).
model::GuideDocument bipedLimbsWith(const std::map<std::string, Value>& options);

// The sample `sample` with `option` set to `value` on the instances named `instances` (a missing name fails the
// test that asks for it).
model::GuideDocument sampleWith(const std::string& sample, std::initializer_list<const char*> instances,
                                const std::string& option, Value value);

class PosedRig {
public:
    explicit PosedRig(const std::string& sample);
    explicit PosedRig(const model::GuideDocument& guide); // a sample with options changed
    PosedRig(const PosedRig&) = delete;
    PosedRig& operator=(const PosedRig&) = delete;

    bool ok() const { return program != nullptr; }
    eval::Pose defaults() const { return program->channels().defaults(); }
    model::RigNodeIndex index(const std::string& id) const;
    // A channel index by node id and channel name; fails the test when missing.
    int channel(const std::string& id, const std::string& name) const;
    const eval::EvalState& evaluate(const eval::Pose& pose) { return posing->evaluate(pose); }
    const eval::EvalState& state() const { return posing->state(); } // the last evaluation
    Vec3 position(const std::string& id) const;      // in the last evaluation
    Vec3 restPosition(const std::string& id) const;
    // Moves `control` so that `measured` (at the same rest place or offset from
    // it) would sit at `target`, keeping its orientation.
    eval::Pose moveTo(const eval::Pose& pose, const std::string& control, const Vec3& target, const std::string& measured);

    model::Rig rig;
    std::unique_ptr<eval::RigProgram> program;
    std::unique_ptr<eval::Posing> posing;
};

// A pose that moves every unlocked transform channel and every custom channel
// (ik_blend, stretch, roll, space, curl, post_scale...) off its default, by a
// different, deterministic amount per channel, so that every constraint of the
// rig has something to solve. Rotate orders keep their defaults.
eval::Pose sweepPose(const eval::ChannelLayout& layout);
// Every node's evaluated world transform, one line per node ("<id>: {t, r, s}",
// 6 decimals, quaternions [x, y, z, w]): what evaluation golden files hold.
std::string worldDump(const model::Rig& rig, const eval::EvalState& state);

// `pose` with `control` turned by `degrees` about the world `axis` through its own place.
eval::Pose turned(PosedRig& r, const eval::Pose& pose, const std::string& control, const Vec3& axis, double degrees);

} // namespace rs::test
