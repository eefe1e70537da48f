#include "EvalTestSupport.h"

#include <gtest/gtest.h>

namespace rs::test {

PosedRig::PosedRig(const std::string& sample) : rig(rigging::buildRig(loadSample(sample), builtinTemplates()))
{
    EXPECT_FALSE(hasErrors(rig.diagnostics));
    auto compiled = eval::RigProgram::compile(rig);
    EXPECT_TRUE(compiled.ok()) << (compiled.diagnostics().empty() ? "" : compiled.diagnostics().front().message);
    if (!compiled.ok())
        return;
    program = std::make_unique<eval::RigProgram>(compiled.take());
    posing = std::make_unique<eval::Posing>(rig, *program);
    posing->evaluate(defaults());
}

model::RigNodeIndex PosedRig::index(const std::string& id) const
{
    auto found = rig.findPath(id);
    EXPECT_TRUE(found.has_value()) << "no rig node " << id;
    return found.value_or(0);
}

int PosedRig::channel(const std::string& id, const std::string& name) const
{
    auto found = program->channels().find(index(id), name);
    EXPECT_TRUE(found.has_value()) << "no channel " << id << "." << name;
    return found.value_or(0);
}

Vec3 PosedRig::position(const std::string& id) const
{
    return translationOf(posing->state().worldMatrix(index(id)));
}

Vec3 PosedRig::restPosition(const std::string& id) const { return translationOf(rig.nodes[index(id)].worldMatrix); }

eval::Pose PosedRig::moveTo(const eval::Pose& pose, const std::string& control, const Vec3& target, const std::string& measured)
{
    Mat4 world = posing->evaluate(pose).worldMatrix(index(control));
    world[3] = Vec4(target + restPosition(control) - restPosition(measured), 1.0);
    return posing->placeAt(pose, index(control), world);
}

} // namespace rs::test
