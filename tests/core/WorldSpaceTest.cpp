// The space named `world` (issue 22 item 2) means the same under every world
// template: what carries the whole rig, following the world and move
// controllers but no body part. A limb's IK in `world` space stays planted
// while the body moves and is carried when the animator places the character,
// whether the biped stands on world.character or on world.default.
#include "EvalTestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace rs {
namespace {

// The biped on Mikan's world.default (one guide joint) instead of world.character.
model::GuideDocument bipedOnWorldDefault()
{
    model::GuideDocument guide = test::loadSample("biped");
    const model::InstanceId worldId = guide.instanceNamed("world")->id;
    model::TemplateInstance& world = *guide.instance(worldId);
    world.templateId = "world.default";
    const model::JointId top = world.joints.front().id;
    world.joints.resize(1); // world.character's root guide sits on its world guide in the biped
    for (const auto& instance : guide.instances())
        if (instance.parent == worldId)
            guide.instance(instance.id)->parentJoint = top;
    return guide;
}

void set(eval::Pose& pose, const test::PosedRig& r, const std::string& id, const std::string& channel, double value)
{
    pose[std::size_t(r.channel(id, channel))] = value;
}

// The world and move controllers turned and moved, the cog moved off.
eval::Pose placedCharacter(const test::PosedRig& r)
{
    eval::Pose pose = r.defaults();
    set(pose, r, "world::ctrls.world", "tx", 1.5);
    set(pose, r, "world::ctrls.world", "ry", 30.0);
    set(pose, r, "world::ctrls.move", "tz", 2.0);
    set(pose, r, "world::ctrls.move", "ry", -75.0);
    set(pose, r, "spine::ctrls.cog", "tx", 0.3);
    set(pose, r, "spine::ctrls.cog", "ty", -0.2);
    return pose;
}

const char* const kIkControls[] = {"arm.L::ctrls.ik", "arm.R::ctrls.ik", "leg.L::ctrls.ik", "leg.R::ctrls.ik"};

} // namespace

TEST(WorldSpace, AnIkInWorldSpaceFollowsTheWorldAndMoveControllersUnderEitherWorldTemplate)
{
    test::PosedRig character("biped");
    test::PosedRig mikan(bipedOnWorldDefault());
    ASSERT_TRUE(character.ok() && mikan.ok());
    EXPECT_FALSE(hasErrors(mikan.rig.diagnostics)) << formatAll(mikan.rig.diagnostics);
    EXPECT_EQ(character.rig.nodes[character.index("world::ctrls.world")].key.instance,
              mikan.rig.nodes[mikan.index("world::ctrls.world")].key.instance);
    for (test::PosedRig* r : {&character, &mikan}) {
        const eval::EvalState& state = r->evaluate(placedCharacter(*r));
        // Where the world and move controllers take what hangs at rest under them.
        const model::RigNodeIndex move = r->index("world::ctrls.move");
        const Mat4 carried = state.worldMatrix(move) * glm::inverse(r->rig.nodes[move].worldMatrix);
        for (const std::string id : kIkControls) {
            const Vec3 expected = Vec3(carried * Vec4(r->restPosition(id), 1.0));
            EXPECT_LT(glm::length(r->position(id) - expected), 1e-9) << r->rig.nodes[0].name << " " << id;
        }
    }
    // And so the two rigs agree, control by control.
    for (const std::string id : kIkControls)
        EXPECT_LT(glm::length(character.position(id) - mikan.position(id)), 1e-9) << id;
}

} // namespace rs
