// Controller groups from the common options `group` and `parent` (Mikan's
// animator groups): one per instance copy by default, nested like the
// instances; a named group shared; merge up and merge down.
#include "rigging/RigBuilder.h"
#include "core/TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace rs;

namespace {

const model::ControllerGroup* groupNamed(const model::Rig& rig, const std::string& name)
{
    for (const auto& g : rig.groups)
        if (g.name == name)
            return &g;
    return nullptr;
}

std::string parentOf(const model::Rig& rig, const model::ControllerGroup& g)
{
    return g.parent == model::ControllerGroup::kNoGroup ? std::string("-") : rig.groups[g.parent].name;
}

bool holds(const model::Rig& rig, const model::ControllerGroup& g, const std::string& path)
{
    const auto node = rig.findPath(path);
    return node && std::find(g.controllers.begin(), g.controllers.end(), *node) != g.controllers.end();
}

model::Rig bipedWith(const std::map<std::string, std::map<std::string, std::string>>& options)
{
    model::GuideDocument guide = test::loadSample("biped");
    for (const auto& [instance, values] : options)
        for (const auto& [option, value] : values)
            guide.instance(guide.instanceNamed(instance)->id)->options[option] = value;
    return rigging::buildRig(guide, test::builtinTemplates());
}

} // namespace

TEST(ControllerGroup, EveryInstanceCopyHasItsGroupNestedLikeTheInstancesWithEveryVisibleController)
{
    const model::Rig rig = bipedWith({});
    ASSERT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    const auto* arm = groupNamed(rig, "arm.L");
    const auto* hand = groupNamed(rig, "hand.L");
    const auto* spine = groupNamed(rig, "spine");
    ASSERT_TRUE(arm && hand && spine && groupNamed(rig, "arm.R") && groupNamed(rig, "index.R"));
    EXPECT_EQ(parentOf(rig, *arm), "spine");
    EXPECT_EQ(parentOf(rig, *hand), "arm.L");
    EXPECT_EQ(parentOf(rig, *groupNamed(rig, "index.L")), "hand.L");
    EXPECT_EQ(parentOf(rig, *groupNamed(rig, "world")), "-");
    EXPECT_TRUE(holds(rig, *arm, "arm.L::ctrls.ik"));
    EXPECT_FALSE(holds(rig, *arm, "arm.R::ctrls.ik"));
    // Every visible controller in exactly one group; no hidden node in any.
    std::vector<int> seen(rig.nodes.size(), 0);
    for (const auto& g : rig.groups)
        for (auto n : g.controllers)
            ++seen[n];
    for (model::RigNodeIndex i = 0; i < rig.nodes.size(); ++i) {
        const bool visible = rig.nodes[i].kind == model::RigNodeKind::Controller && !rig.nodes[i].hidden;
        EXPECT_EQ(seen[i], visible ? 1 : 0) << rig.nodes[i].path;
    }
}

TEST(ControllerGroup, ANamedGroupIsSharedAndMergeUpAndMergeDownJoinTheGroupAbove)
{
    // Both arms (and their mirrored copies) in one "arms" group under the spine's.
    const model::Rig named = bipedWith({{"arm", {{"group", "arms"}}}});
    const auto* arms = groupNamed(named, "arms");
    ASSERT_NE(arms, nullptr);
    EXPECT_EQ(parentOf(named, *arms), "spine");
    EXPECT_TRUE(holds(named, *arms, "arm.L::ctrls.ik") && holds(named, *arms, "arm.R::ctrls.ik"));
    EXPECT_EQ(groupNamed(named, "arm.L"), nullptr);
    EXPECT_EQ(parentOf(named, *groupNamed(named, "hand.R")), "arms");

    // merge up: the neck's controllers in the spine's group.
    const model::Rig up = bipedWith({{"neck", {{"parent", "merge up"}}}});
    EXPECT_EQ(groupNamed(up, "neck"), nullptr);
    EXPECT_TRUE(holds(up, *groupNamed(up, "spine"), "neck::ctrls.head"));

    // merge down on the hand: every finger's controllers in the hand's group.
    const model::Rig down = bipedWith({{"hand", {{"parent", "merge down"}}}});
    const auto* hand = groupNamed(down, "hand.L");
    ASSERT_NE(hand, nullptr);
    EXPECT_EQ(groupNamed(down, "index.L"), nullptr);
    EXPECT_TRUE(holds(down, *hand, "index.L::ctrls.fk.0"));
    EXPECT_TRUE(holds(down, *hand, "thumb.L::ctrls.fk.0"));
}
