// Issue 22 item 7: every template option comes with a sample guide that uses
// it. For each option of each template in the built-in registry, some instance
// of that template in resources/samples/*.yml sets it to a value other than its
// default, or the option is on the allow-list below with the reason it is not.
//
// The common options every manifest gets (branches, sym, group, parent,
// do_ctrl, do_skin, virtual_parent, isolate_skin: io/ManifestReader's
// commonOptions) are one mechanism built by one stage whatever the template, so
// one sample instance of any template setting one counts for all ("*.name").
// A template that declares one itself with its own default (world.default's
// group, util.camera's parent) is checked against that default.
//
// Only `opts` are checked: the `guides` parameters (number, length, upper,
// radius...) shape the guide joints of a new guide, which a sample already has.
#include "core/TestSupport.h"
#include "io/GuideFile.h"
#include "io/ManifestReader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

using namespace rs;

namespace {

constexpr const char* kBothSides =
    "both sides by default; one side is the common branches option, which the wheels, mud flaps and antennas set";
constexpr const char* kGroupIsXform = "on, a core.group is a core.xform (same builder), which the prop and the vehicle use";

// Options no sample sets to a non-default value, and why.
const std::map<std::string, std::string>& allowList()
{
    static const std::map<std::string, std::string> list = {
        // Exempt: their non-default is another mechanism a sample already uses.
        {"arm.limb.branches", kBothSides},
        {"leg.limb.branches", kBothSides},
        {"quad.leg.branches", kBothSides},
        {"face.brow.branches", kBothSides},
        {"face.eye.branches", kBothSides},
        {"core.group.do_ctrl", kGroupIsXform},
        {"core.group.do_skin", kGroupIsXform},
        {"core.xform.joint", "a weightless bone under the part: the vehicle's hitch (core.group, joint: on) runs the "
                             "same builder line"},
        {"util.camera.parent", "merge up: a camera's controls join its parent's group (Mikan's group plumbing)"},
        {"util.camera.do_skin", "off: a camera is not a bone of the exported skeleton (it exports as a camera)"},
        {"world.default.group", "'all' is the root group Mikan's world makes; another value is a root that is not the top"},
        {"world.default.parent", "merge up is the root group's relation; another value is a root that is not the top"},
        // Exempt: the non-default would be wrong for every sample's character (arm.limb shares the limb
        // builder and shows soft IK on the claw, FK by default on the robot).
        {"arm.limb.space_switch", "off fixes each space; the biped's arm needs its switches (chest/world)"},
        {"leg.limb.soft_ik", "standing legs are guided nearly straight (the biped's and the robot's 0.95 mm, the "
                             "quadruped's front legs 1.4 mm short of full reach), so any soft IK moves their rest pose"},
        {"leg.limb.ik_blend", "legs plant their feet: IK by default; FK by default is the arms' (the robot's)"},
        {"leg.limb.space_switch", "off fixes each space; a front leg in chest space must switch to world to plant"},
        {"quad.leg.ik_blend", "legs plant their feet: IK by default; FK by default is the arms' (the robot's)"},
    };
    return list;
}

std::vector<std::string> sampleNames()
{
    std::vector<std::string> names;
    const std::filesystem::path folder = std::filesystem::path(test::samplePath("biped")).parent_path();
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.path().extension() == ".yml")
            names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

std::string optionKey(const templates::TemplateManifest& manifest, const templates::Parameter& option)
{
    const auto& common = io::commonOptions();
    const auto same = std::find_if(common.begin(), common.end(), [&](const templates::Parameter& c) {
        return c.name == option.name && c.value == option.value;
    });
    return (same != common.end() ? std::string("*") : manifest.id) + "." + option.name;
}

// "template.option" (or "*.option") of every option some sample instance sets
// to a value other than its template's default.
std::set<std::string> optionsTheSamplesSet()
{
    std::set<std::string> used;
    for (const std::string& sample : sampleNames()) {
        const auto guide = test::loadSample(sample);
        for (const auto& instance : guide.instances()) {
            const auto* manifest = test::builtinTemplates().find(instance.templateId);
            if (!manifest) {
                ADD_FAILURE() << sample << ": unknown template " << instance.templateId;
                continue;
            }
            for (const auto& [name, value] : instance.options)
                if (const auto* option = manifest->findOpt(name); option && !sameValue(option->value, value))
                    used.insert(optionKey(*manifest, *option));
        }
    }
    return used;
}

} // namespace

TEST(Samples, EveryOptionIsUsedBySomeSample)
{
    const std::set<std::string> used = optionsTheSamplesSet();
    ASSERT_FALSE(used.empty());
    std::set<std::string> options;
    std::string missing;
    for (const auto* manifest : test::builtinTemplates().all())
        for (const auto& option : manifest->opts) {
            const std::string key = optionKey(*manifest, option);
            if (options.insert(key).second && !used.count(key) && !allowList().count(key))
                missing += "\n  " + key + " (default " + formatValue(option.value) + ")";
        }
    EXPECT_TRUE(missing.empty()) << "options no sample in resources/samples sets to a non-default value (put each in a "
                                    "sample where a rigger would use it, or on this test's allow-list with the reason):"
                                 << missing;
    // The allow-list stays true: an option a sample now uses comes off it.
    for (const auto& [key, reason] : allowList())
        EXPECT_FALSE(used.count(key)) << key << " is used by a sample now; take it off the allow-list (" << reason << ")";
}

// A sample is written as the editor saves it (option keys sorted, no comments
// in its body), so opening and saving one changes nothing but its first line
// (a sample's header comment says what it is).
TEST(Samples, EverySampleSavesBackByteForByte)
{
    for (const std::string& sample : sampleNames()) {
        const std::string original = test::readText(test::samplePath(sample));
        auto guide = io::readGuideText(original, sample + ".yml");
        ASSERT_TRUE(guide.ok()) << formatAll(guide.diagnostics());
        EXPECT_TRUE(guide.diagnostics().empty()) << sample << ": " << formatAll(guide.diagnostics());
        const auto body = [](const std::string& text) { return text.substr(text.find('\n') + 1); };
        EXPECT_EQ(body(io::writeGuideText(*guide)), body(original)) << sample;
    }
}
