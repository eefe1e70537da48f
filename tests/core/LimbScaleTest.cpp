// Limb controls placed relative to the limb (issue 22: "control sizes relative
// to the character, today fixed in metres"): the biped authored at 1/100 of
// its size (a centimetre model read as metres) puts every limb's IK/FK switch
// and pole at 1/100 of where the full-size biped has them, so the switch sits
// beside the wrist or ankle rather than metres away, or on it.
#include "TestSupport.h"

#include "rigging/RigBuilder.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace rs {
namespace {

constexpr double kScale = 0.01;

// The biped with every guide joint's translation scaled by `scale`, so the whole guide is that size.
model::GuideDocument scaledBiped(double scale)
{
    model::GuideDocument guide = test::loadSample("biped");
    for (const auto& i : guide.instances())
        for (auto& joint : guide.instance(i.id)->joints)
            joint.local.translate *= scale;
    return guide;
}

Vec3 restPosition(const model::Rig& rig, const std::string& id) { return Vec3(test::node(rig, id).worldMatrix[3]); }

TEST(LimbScale, ACentimetreBipedHasItsSwitchesAndPolesAtAHundredthOfTheBipeds)
{
    const model::Rig full = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    const model::Rig small = rigging::buildRig(scaledBiped(kScale), test::builtinTemplates());
    ASSERT_FALSE(hasErrors(small.diagnostics)) << formatAll(small.diagnostics);
    for (const char* limb : {"arm.L", "arm.R", "leg.L", "leg.R"})
        for (const char* control : {"ctrls.switch", "ctrls.pole", "ctrls.ik", "ctrls.fk.2"}) {
            const std::string id = std::string(limb) + "::" + control;
            const Vec3 expected = restPosition(full, id) * kScale;
            EXPECT_LE(glm::length(restPosition(small, id) - expected), 1e-9 * glm::length(expected)) << id;
        }
}

// The switch sits off the wrist or ankle by a share of the limb, the same share
// at any size: a fifth of the arm, a seventh of the leg, never on the joint.
TEST(LimbScale, TheSwitchSitsBesideTheLimbsEndByAShareOfTheLimbAtEverySize)
{
    for (const double scale : {1.0, kScale, 100.0}) {
        const model::Rig rig = rigging::buildRig(scaledBiped(scale), test::builtinTemplates());
        for (const char* limb : {"arm.L", "leg.R"}) {
            const std::string at = std::string(limb) + "::";
            const Vec3 root = restPosition(rig, at + "blend.0"), mid = restPosition(rig, at + "blend.1"),
                       end = restPosition(rig, at + "blend.2");
            const double chain = glm::length(mid - root) + glm::length(end - mid);
            const double share = glm::length(restPosition(rig, at + "ctrls.switch") - end) / chain;
            EXPECT_NEAR(share, std::string(limb) == "arm.L" ? 0.22 : 0.14, 1e-9) << limb << " at " << scale;
        }
    }
}

} // namespace
} // namespace rs
