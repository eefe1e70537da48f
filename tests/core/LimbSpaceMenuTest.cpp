// Space menus as an animator reads them (issue 22): a limb's IK control, pole
// and first FK control offer only the spaces the rig has. On the strider (a
// core.xform hull, no spine) the legs' menus leave out the cog, hips and chest
// instead of offering entries that silently followed the world; the sample
// builds clean, since a space a template merely offers is not the rigger's
// choice. A space the option picks and the rig lacks is warned, naming the
// instance, the option and the control.
// The biped, which has every space, keeps its full menus.
#include "TestSupport.h"

#include "rigging/RigBuilder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>

namespace rs {
namespace {

const std::string kStriderLegs[] = {"front_leg.L", "front_leg.R", "hind_leg.L", "hind_leg.R"};

// The labels of the enum attribute `name` on node `id`; empty (with a failure) when it is missing.
std::vector<std::string> menuOf(const model::Rig& rig, const std::string& id, const std::string& name = "space")
{
    for (const auto& a : test::node(rig, id).attributes)
        if (a.name == name)
            return a.labels;
    ADD_FAILURE() << id << " has no attribute " << name;
    return {};
}

double defaultOf(const model::Rig& rig, const std::string& id, const std::string& name = "space")
{
    for (const auto& a : test::node(rig, id).attributes)
        if (a.name == name)
            return a.value;
    ADD_FAILURE() << id << " has no attribute " << name;
    return -1.0;
}

// How many diagnostics of `rig` contain every one of `parts`.
int countMentioning(const model::Rig& rig, const std::vector<std::string>& parts)
{
    int n = 0;
    for (const auto& d : rig.diagnostics) {
        bool all = true;
        for (const std::string& part : parts)
            all = all && d.message.find(part) != std::string::npos;
        n += all ? 1 : 0;
    }
    return n;
}

struct Switch {
    const char* control; // tag on the leg
    const char* option;
    std::vector<std::string> missing, offered;
};

const Switch kStriderSwitches[] = {
    {"ctrls.ik", "ik_space", {"cog", "hips", "chest"}, {"world", "root"}},
    {"ctrls.pole", "pv_space", {"cog"}, {"follow", "ik", "world", "root"}},
    {"ctrls.fk.0", "fk_space", {"hips", "chest", "cog"}, {"parent", "world", "root"}},
};

TEST(LimbSpaceMenu, TheStridersLegsOfferOnlyItsSpacesAndBuildClean)
{
    const model::Rig rig = rigging::buildRig(test::loadSample("strider"), test::builtinTemplates());
    for (const std::string& leg : kStriderLegs)
        for (const Switch& s : kStriderSwitches) {
            const std::string id = leg + "::" + s.control;
            EXPECT_EQ(menuOf(rig, id), s.offered) << id;
            EXPECT_EQ(defaultOf(rig, id), 0.0) << id << ": the option's default space exists and stays the default";
            for (const std::string& space : s.missing)
                EXPECT_EQ(std::count(s.offered.begin(), s.offered.end(), space), 0) << id << " offers " << space;
        }
    // Spaces the template offers and the rig lacks are not the rigger's choice: no warning.
    EXPECT_TRUE(rig.diagnostics.empty()) << formatAll(rig.diagnostics);
    // The space constraint has one target per entry offered, so each entry follows what it names.
    for (const auto& c : rig.constraints) {
        if (c.key.tag == "cns.ik_space") {
            EXPECT_EQ(c.targets.size(), 2u) << c.key.tag;
        }
    }
}

TEST(LimbSpaceMenu, AMissingDefaultSpaceIsWarnedOnceAndTheMenuDefaultsToItsFirstEntry)
{
    model::GuideDocument guide = test::loadSample("strider");
    for (const auto& i : guide.instances())
        if (i.templateId == "quad.leg")
            guide.instance(i.id)->options["ik_space"] = std::string("chest");
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    for (const std::string& leg : kStriderLegs) {
        const std::string id = leg + "::ctrls.ik";
        EXPECT_EQ(menuOf(rig, id), (std::vector<std::string>{"world", "root"})) << id;
        EXPECT_EQ(defaultOf(rig, id), 0.0) << id << ": world, the first entry";
        EXPECT_EQ(countMentioning(rig, {"instance '" + leg + "'", "'chest'", "(option 'ik_space')"}), 1) << formatAll(rig.diagnostics);
        EXPECT_EQ(countMentioning(rig, {"instance '" + leg + "'", "(option 'ik_space')"}), 1)
            << "only the chosen space is warned\n" << formatAll(rig.diagnostics);
        EXPECT_EQ(countMentioning(rig, {"instance '" + leg + "'", "the default space 'chest' is not a space of this rig",
                                        "follows 'world' by default"}),
                  1)
            << formatAll(rig.diagnostics);
    }
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
}

TEST(LimbSpaceMenu, TheBipedKeepsEveryMenuWhole)
{
    const model::Rig rig = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    EXPECT_TRUE(rig.diagnostics.empty()) << formatAll(rig.diagnostics);
    using Menu = std::vector<std::string>;
    const std::map<std::string, Menu> menus = {
        {"ctrls.ik", {"world", "root", "cog", "chest", "head"}},
        {"ctrls.pole", {"follow", "ik", "world", "root", "cog"}},
        {"ctrls.fk.0", {"parent", "chest", "cog", "world", "root"}},
    };
    const std::map<std::string, Menu> legMenus = {
        {"ctrls.ik", {"world", "root", "cog", "hips", "chest"}},
        {"ctrls.pole", {"follow", "ik", "world", "root", "cog"}},
        {"ctrls.fk.0", {"parent", "hips", "chest", "cog", "world", "root"}},
    };
    for (const char* side : {".L", ".R"}) {
        for (const auto& [control, menu] : menus)
            EXPECT_EQ(menuOf(rig, "arm" + std::string(side) + "::" + control), menu) << side << control;
        for (const auto& [control, menu] : legMenus)
            EXPECT_EQ(menuOf(rig, "leg" + std::string(side) + "::" + control), menu) << side << control;
    }
    // The options the biped sets keep their entries: fk_space chest, pv_space cog.
    EXPECT_EQ(defaultOf(rig, "arm.L::ctrls.fk.0"), 1.0);
    EXPECT_EQ(defaultOf(rig, "arm.L::ctrls.pole"), 4.0);
    EXPECT_EQ(menuOf(rig, "neck::ctrls.head"), (Menu{"neck", "chest", "cog", "world"}));
    EXPECT_EQ(menuOf(rig, "neck::ctrls.head", "point_space"), (Menu{"neck", "chest", "cog", "world"}));
}

TEST(LimbSpaceMenu, TheClawsArmsLeaveOutTheHeadItDoesNotHave)
{
    const model::Rig rig = rigging::buildRig(test::loadSample("claw"), test::builtinTemplates());
    for (const char* arm : {"arm.L", "arm.R"}) {
        EXPECT_EQ(menuOf(rig, std::string(arm) + "::ctrls.ik"), (std::vector<std::string>{"world", "root", "cog", "chest"})) << arm;
    }
    EXPECT_TRUE(rig.diagnostics.empty()) << formatAll(rig.diagnostics);
}

} // namespace
} // namespace rs
