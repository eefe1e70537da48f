// The virtual hierarchy from manifest `hierarchy`: root/parent/chain, option
// conditions (with an enum option given by index), and ids that only the
// builder creates (skin.last.up), which the manifest can still place.
#include "base/Paths.h"
#include "io/TemplateFolders.h"
#include "rigging/RigBuilder.h"
#include "rigging/TemplateBuilder.h"
#include "core/TestSupport.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace rs;
using model::RigNodeKind;

namespace {

class TwoSegmentBuilder final : public rigging::TemplateBuilder {
public:
    std::vector<rigging::GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                                   const std::map<std::string, Value>&) const override { return {{}}; }
    void generate(rigging::BuildContext& ctx) const override
    {
        const auto root = ctx.hookNode();
        const Mat4 at(1.0);
        const auto a = ctx.createNode(RigNodeKind::Controller, "ctrls.a", "c_a", root, at);
        ctx.createNode(RigNodeKind::Controller, "ctrls.b", "c_b", a, at);
        ctx.createNode(RigNodeKind::Joint, "skin.up.0", "sk_up0", a, at);
        ctx.createNode(RigNodeKind::Joint, "skin.up.1", "sk_up1", a, at);
        ctx.createNode(RigNodeKind::Joint, "skin.last.up", "sk_last_up", a, at);
        ctx.createNode(RigNodeKind::Joint, "skin.dn.0", "sk_dn0", a, at);
    }
};

class HierarchyStage : public ::testing::Test {
protected:
    void SetUp() override
    {
        const std::string folder = test::temporaryPath("hierarchy-templates");
        std::filesystem::remove_all(folder);
        std::filesystem::create_directories(folder + "/test/limb");
        std::ofstream(folder + "/test/limb/template.yml") << R"(name: limb
opts:
  unchain: {value: off}
  orient: {value: auto, enum: {0: auto, 1: copy}}
hierarchy:
  ctrls.a: {root: on}
  ctrls.b:
    parent: ctrls.a
    opts:
      unchain: {root: on, parent: []}
  skin.up:
    root: on
    chain: on
    opts:
      orient == "copy": {chain: off}
  skin.last.up: {parent: skin.up.1}
  skin.dn.0: {parent: skin.last.up}
)";
        const Diagnostics d = io::scanTemplates(registry, {builtinTemplatesDirectory(), folder}, iconsDirectory());
        ASSERT_FALSE(hasErrors(d)) << formatAll(d);
        builders.add("test.limb", std::make_unique<TwoSegmentBuilder>());
    }

    model::Rig build(const std::map<std::string, Value>& options = {})
    {
        model::GuideDocument guide;
        model::TemplateInstance i;
        i.id = 1;
        i.templateId = "test.limb";
        i.name = "arm";
        i.options = options;
        i.joints.push_back({1, 0, {}, {}, {}});
        guide.insertInstance(i, 0);
        return rigging::buildRig(guide, registry, builders);
    }

    std::string virtualParentOf(const model::Rig& rig, const std::string& id)
    {
        const auto& node = rig.nodes[*rig.findPath("arm::" + id)];
        return node.virtualParent == model::kNoNode ? "(none)" : rig.nodes[node.virtualParent].path;
    }

    templates::TemplateRegistry registry;
    rigging::BuilderRegistry builders;
};

} // namespace

TEST_F(HierarchyStage, LinksParentsChainsAndBuilderCreatedIds)
{
    const auto rig = build();
    ASSERT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    EXPECT_EQ(virtualParentOf(rig, "ctrls.b"), "arm::ctrls.a");
    EXPECT_EQ(virtualParentOf(rig, "skin.up.1"), "arm::skin.up.0") << "chain: on";
    EXPECT_EQ(virtualParentOf(rig, "skin.last.up"), "arm::skin.up.1") << "an id only the builder makes";
    EXPECT_EQ(virtualParentOf(rig, "skin.dn.0"), "arm::skin.last.up");
}

TEST_F(HierarchyStage, AppliesOptionConditionsIncludingEnumsGivenByIndex)
{
    const auto rig = build({{"unchain", true}, {"orient", 1LL}});
    ASSERT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    EXPECT_EQ(virtualParentOf(rig, "ctrls.b"), "(none)") << "unchain: root on, no parent";
    EXPECT_EQ(virtualParentOf(rig, "skin.up.1"), "(none)") << "orient index 1 is 'copy': chain off";
}
