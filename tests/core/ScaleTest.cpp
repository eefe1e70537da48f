// Large guides (issue 18 item 12): a 2,000-joint chain and 2,000 instances in
// a tree build completely and correctly, with and without the build cache.
// How fast they build is measured by rigsmith-bench (ScaleBench.cpp), never here.
#include "TestSupport.h"

#include "io/RigDump.h"
#include "model/Skeleton.h"
#include "rigging/BuildCache.h"
#include "rigging/RigBuilder.h"
#include "templates/Structure.h"

#include <gtest/gtest.h>

using namespace rs;

namespace {

model::GuideJoint guideJoint(model::JointId id, model::JointId parent, double x, double y)
{
    model::GuideJoint j;
    j.id = id;
    j.parent = parent;
    j.local.translate = Vec3(x, y, 0.0);
    return j;
}

// One core.joints instance with `joints` guide joints 1 cm apart along +Y.
model::GuideDocument longChain(int joints)
{
    model::TemplateInstance chain;
    chain.id = 1;
    chain.templateId = "core.joints";
    chain.name = "chain";
    for (int k = 0; k < joints; ++k)
        chain.joints.push_back(guideJoint(model::JointId(k + 1), k == 0 ? model::kNoId : model::JointId(k), 0.0, 0.01));
    model::GuideDocument doc;
    doc.name = "chain";
    doc.insertInstance(std::move(chain), 0);
    return doc;
}

// Instance k hangs under the last joint of instance (k - 1) / 2; even ones are
// core.xform, odd ones three-joint core.joints.
model::GuideDocument instanceTree(int count)
{
    model::GuideDocument doc;
    doc.name = "tree";
    std::vector<model::JointId> lastJoint;
    model::JointId nextJoint = 1;
    for (int k = 0; k < count; ++k) {
        model::TemplateInstance instance;
        instance.id = model::InstanceId(k + 1);
        const bool isXform = k % 2 == 0;
        instance.templateId = isXform ? "core.xform" : "core.joints";
        instance.name = (isXform ? "xform" : "joints") + std::to_string(k);
        if (k > 0) {
            instance.parent = model::InstanceId((k - 1) / 2 + 1);
            instance.parentJoint = lastJoint[std::size_t((k - 1) / 2)];
        }
        for (int j = 0; j < (isXform ? 1 : 3); ++j) {
            const model::JointId id = nextJoint++;
            instance.joints.push_back(guideJoint(id, j == 0 ? model::kNoId : id - 1, k % 2 ? 0.1 : -0.1, 0.05));
        }
        lastJoint.push_back(instance.joints.back().id);
        doc.insertInstance(std::move(instance), doc.instances().size());
    }
    return doc;
}

} // namespace

TEST(Structure, ResolvesEveryIndexOfATwoThousandJointChain)
{
    const model::GuideDocument doc = longChain(2000);
    const templates::TemplateManifest& manifest = *test::builtinTemplates().find("core.joints");
    const templates::StructureResolver resolver(manifest, doc.instances().front());
    ASSERT_EQ(resolver.chain().size(), 2000u);
    for (int i : {0, 1, 1000, 1999}) {
        auto joint = resolver.address("chain[" + std::to_string(i) + "]");
        ASSERT_TRUE(joint) << i;
        EXPECT_EQ(*joint, std::vector<model::JointId>{model::JointId(i + 1)});
    }
    auto last = resolver.address("chain[-1] + /0");
    ASSERT_TRUE(last);
    EXPECT_EQ(*last, (std::vector<model::JointId>{2000, 1}));
}

TEST(RigBuilder, BuildsATwoThousandJointChainNodeForNode)
{
    const model::GuideDocument doc = longChain(2000);
    const model::Rig rig = rigging::buildRig(doc, test::builtinTemplates());
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    ASSERT_EQ(rig.nodes.size(), 1u + 3u * 2000u);
    for (int i : {0, 1, 999, 1999}) {
        const std::string index = std::to_string(i);
        const model::RigNode& ctrl = test::node(rig, "chain::ctrls." + index);
        EXPECT_NEAR(translationOf(ctrl.worldMatrix).y, 0.01 * (i + 1), 1e-9) << i;
        EXPECT_FALSE(ctrl.curves.empty()) << i;
        if (i > 0) {
            EXPECT_EQ(rig.nodes[ctrl.virtualParent].path, "chain::ctrls." + std::to_string(i - 1));
            EXPECT_EQ(rig.nodes[test::node(rig, "chain::roots." + index).parent].path, "chain::ctrls." + std::to_string(i - 1));
        }
    }
    const auto skeleton = model::extractSkeleton(rig);
    ASSERT_TRUE(skeleton) << formatAll(skeleton.diagnostics());
    ASSERT_EQ(skeleton->joints.size(), 2000u);
    for (std::size_t k = 1; k < skeleton->joints.size(); ++k)
        ASSERT_EQ(skeleton->joints[k].parent, int(k) - 1) << k;
}

TEST(IncrementalBuild, ATwoThousandJointChainRebuildsAsAFullBuildDoes)
{
    model::GuideDocument doc = longChain(2000);
    rigging::BuildCache cache;
    rigging::buildRig(doc, test::builtinTemplates(), rigging::BuilderRegistry::builtin(), {}, &cache);
    doc.instance(1)->joints[1000].local.translate.x += 0.05;
    const model::Rig incremental = rigging::buildRig(doc, test::builtinTemplates(), rigging::BuilderRegistry::builtin(), {}, &cache);
    EXPECT_EQ(io::writeRigDump(incremental), io::writeRigDump(rigging::buildRig(doc, test::builtinTemplates())));
}

TEST(RigBuilder, BuildsTwoThousandInstancesInATreeWithOneSkeleton)
{
    const model::GuideDocument doc = instanceTree(2000);
    rigging::BuildCache cache;
    const model::Rig first = rigging::buildRig(doc, test::builtinTemplates(), rigging::BuilderRegistry::builtin(), {}, &cache);
    const model::Rig rig = rigging::buildRig(doc, test::builtinTemplates(), rigging::BuilderRegistry::builtin(), {}, &cache);
    EXPECT_EQ(cache.lastBuild().replayed, 2000u);
    EXPECT_EQ(io::writeRigDump(rig), io::writeRigDump(first));
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    EXPECT_EQ(rig.skinJointCount(), 1000u + 3u * 1000u);
    // Every instance hangs under the last joint of its parent, physically and in the skin hierarchy.
    EXPECT_EQ(rig.nodes[test::node(rig, "joints1999::roots.0").parent].path, "joints999::ctrls.2");
    EXPECT_EQ(rig.nodes[test::node(rig, "xform1998::skin.xform").virtualParent].path, "xform998::skin.xform");
    const auto skeleton = model::extractSkeleton(rig);
    ASSERT_TRUE(skeleton) << formatAll(skeleton.diagnostics());
    EXPECT_EQ(skeleton->joints.size(), rig.skinJointCount());
}
