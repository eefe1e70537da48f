// The virtual hierarchy from manifest `hierarchy`: root/parent/chain, option
// conditions (with an enum option given by index), and ids that only the
// builder creates (skin.last.up), which the manifest can still place.
#include "base/Paths.h"
#include "edit/GuideEdits.h"
#include "edit/History.h"
#include "eval/Pickwalk.h"
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

namespace {

// The biped with one option of one instance set.
model::Rig bipedWith(const std::string& instance, const std::string& option, const std::string& value)
{
    model::GuideDocument guide = test::loadSample("biped");
    const model::TemplateInstance* found = guide.instanceNamed(instance);
    EXPECT_NE(found, nullptr) << instance;
    guide.instance(found->id)->options[option] = value;
    return rigging::buildRig(guide, test::builtinTemplates());
}

const model::RigNode* virtualParentOf(const model::Rig& rig, const std::string& path)
{
    const model::RigNode& node = test::node(rig, path);
    return node.virtualParent == model::kNoNode ? nullptr : &rig.nodes[node.virtualParent];
}

bool mentions(const model::Rig& rig, const std::string& text)
{
    for (const auto& d : rig.diagnostics)
        if (d.message.find(text) != std::string::npos)
            return true;
    return false;
}

} // namespace

TEST(VirtualParent, AttachesTheRootsToTheClosestNodeOfTheNamedInstanceOnTheSameBranch)
{
    const model::Rig usual = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    const model::Rig rig = bipedWith("arm", "virtual_parent", "neck");
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    for (const std::string side : {"L", "R"}) {
        const model::RigNode* before = virtualParentOf(usual, "arm." + side + "::ctrls.clavicle");
        const model::RigNode* after = virtualParentOf(rig, "arm." + side + "::ctrls.clavicle");
        ASSERT_NE(before, nullptr);
        ASSERT_NE(after, nullptr);
        EXPECT_NE(before->key.instance, after->key.instance) << "the arm no longer walks up to the spine";
        EXPECT_EQ(after->path.substr(0, 6), "neck::") << after->path;
        // The closest of the neck's controllers to the clavicle, none closer.
        const Vec3 at = translationOf(test::node(rig, "arm." + side + "::ctrls.clavicle").worldMatrix);
        for (const auto& n : rig.nodes) {
            if (n.path.rfind("neck::ctrls.", 0) == 0) {
                EXPECT_GE(glm::length(translationOf(n.worldMatrix) - at) + 1e-9,
                          glm::length(translationOf(after->worldMatrix) - at)) << n.path;
            }
        }
        // Pickwalk up follows it.
        const auto from = *rig.findPath("arm." + side + "::ctrls.clavicle");
        EXPECT_EQ(rig.nodes[eval::pickwalk(rig, from, eval::WalkDirection::Up)].path, after->path);
    }
}

TEST(VirtualParent, AnUnknownInstanceOrALoopIsReportedAndTheUsualParentKept)
{
    const model::Rig usual = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    const model::Rig unknown = bipedWith("neck", "virtual_parent", "tail");
    EXPECT_TRUE(mentions(unknown, "virtual_parent: no instance named 'tail'")) << formatAll(unknown.diagnostics);
    EXPECT_EQ(virtualParentOf(unknown, "neck::ctrls.fk.0")->path, virtualParentOf(usual, "neck::ctrls.fk.0")->path);

    const model::Rig loop = bipedWith("spine", "virtual_parent", "neck"); // the neck hangs below the spine
    EXPECT_TRUE(mentions(loop, "(a loop)")) << formatAll(loop.diagnostics);
    for (const auto& n : usual.nodes) {
        if (n.path.rfind("spine::", 0) == 0 && n.virtualParent != model::kNoNode) {
            EXPECT_EQ(virtualParentOf(loop, n.path)->path, usual.nodes[n.virtualParent].path) << n.path;
        }
    }
}

TEST(VirtualParent, RenamingTheNamedInstanceKeepsTheLinkAndUndoRestoresIt)
{
    model::GuideDocument document = test::loadSample("biped");
    const model::InstanceId arm = document.instanceNamed("arm")->id;
    const model::InstanceId neck = document.instanceNamed("neck")->id;
    document.instance(arm)->options["virtual_parent"] = std::string("neck");
    edit::History history(document);
    const model::Rig before = rigging::buildRig(document, test::builtinTemplates());
    ASSERT_TRUE(test::succeeded(edit::renameInstance(history, neck, "collar")));
    EXPECT_EQ(std::get<std::string>(document.instance(arm)->options.at("virtual_parent")), "collar");
    const model::Rig after = rigging::buildRig(document, test::builtinTemplates());
    EXPECT_FALSE(mentions(after, "virtual_parent")) << formatAll(after.diagnostics);
    const auto& clavicle = test::node(after, "arm.L::ctrls.clavicle");
    EXPECT_EQ(after.nodes[clavicle.virtualParent].key, before.nodes[test::node(before, "arm.L::ctrls.clavicle").virtualParent].key);
    history.undo();
    EXPECT_EQ(std::get<std::string>(document.instance(arm)->options.at("virtual_parent")), "neck");
}
