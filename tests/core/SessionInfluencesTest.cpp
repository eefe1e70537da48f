// Missing influences on a session import (issue 20 item 4, as the CLI's
// --missing / --name-map): a chunk influence the rig has no skin joint of
// (by identity or name) stops the import with a list, is mapped by a name
// map, or is created as a joint of the guide under its matched parent; either
// way the import is one undo step.
#include "SessionSkinFixture.h"

#include <gtest/gtest.h>

using namespace rs;
using namespace rs::test::sessionskin;

namespace {

// The bound sleeve's chunk with the elbow's influence renamed (another
// identity and name, as a rig of another build would have it), and where.
struct RenamedElbow {
    Fixture f;
    model::MeshWeights bound;
    std::vector<skin::SkinChunk> chunks;
    std::size_t elbow = 0, parent = 0; // skin bones (and chunk influences: the chunk is on the bones)
    std::string elbowName;

    RenamedElbow()
    {
        EXPECT_TRUE(test::succeeded(f.s.addModel(kArm)));
        f.bind();
        bound = f.s.document().bindings[0].weights;
        auto exported = f.s.exportSkinChunks(session::SkinScope::all());
        EXPECT_TRUE(exported.ok());
        chunks = exported.take();
        elbow = boneOf(f.s, "arm.L::skin.limb.1");
        elbowName = f.s.rig()->nodes[f.s.skinBones()[elbow].node].name;
        skin::SkinChunk& c = chunks[0];
        EXPECT_EQ(c.weights.joints[elbow], f.s.skinBones()[elbow].key) << "the chunk's influences are the skin bones";
        parent = std::size_t(c.weights.parents[elbow]);
        c.weights.joints[elbow] = {999, "", "skin.elbow_old"};
        c.joints[elbow].key = c.weights.joints[elbow];
        c.joints[elbow].name = "elbow_old";
    }

    float weightOn(const model::MeshWeights& w, std::size_t v, std::size_t bone) const
    {
        for (const model::Influence* i = w.begin(v); i != w.end(v); ++i)
            if (w.joints[i->joint] == f.s.skinBones()[bone].key)
                return i->weight;
        return 0.0f;
    }
};

float weightOnKey(const model::MeshWeights& w, std::size_t v, const NodeKey& key)
{
    for (const model::Influence* i = w.begin(v); i != w.end(v); ++i)
        if (w.joints[i->joint] == key)
            return i->weight;
    return 0.0f;
}

} // namespace

TEST(SessionInfluences, StopListsTheMissingInfluenceAndChangesNothing)
{
    RenamedElbow r;
    const model::GuideDocument before = r.f.s.document();
    const std::size_t steps = r.f.s.history().size();
    const auto missing = r.f.s.missingInfluences(r.chunks, {});
    ASSERT_EQ(missing.size(), 1u);
    EXPECT_EQ(missing[0].name, "elbow_old");
    EXPECT_EQ(missing[0].meshes, std::vector<std::string>{"sleeve"});

    auto reports = r.f.s.importSkinChunks(r.chunks, {}, session::SkinScope::all());
    ASSERT_FALSE(reports.ok());
    const std::string said = formatAll(reports.diagnostics());
    EXPECT_NE(said.find("influence 'elbow_old' (weighting mesh 'sleeve') is not a skin joint of the rig"), std::string::npos) << said;
    EXPECT_TRUE(r.f.s.document() == before);
    EXPECT_EQ(r.f.s.history().size(), steps);

    skin::InfluenceMapOptions mapWithoutNames;
    mapWithoutNames.missing = skin::MissingInfluences::Map;
    auto refused = r.f.s.prepareSkinImport(r.chunks, {}, session::SkinScope::all(), mapWithoutNames);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(formatAll(refused.diagnostics()).find("map needs a name map"), std::string::npos);
}

TEST(SessionInfluences, ANameMapPutsTheInfluenceBackOnItsJointExactly)
{
    RenamedElbow r;
    skin::InfluenceMapOptions influences;
    influences.missing = skin::MissingInfluences::Map;
    influences.names = {{"elbow_old", r.elbowName}};
    EXPECT_TRUE(r.f.s.missingInfluences(r.chunks, influences).empty()) << "the map places it";
    ASSERT_TRUE(r.f.s.applyWeightOperation(session::Session::WeightOperation::Limit, 1).ok()); // spoil them
    const model::MeshWeights spoiled = r.f.s.document().bindings[0].weights;

    auto job = r.f.s.prepareSkinImport(r.chunks, {}, session::SkinScope::all(), influences);
    ASSERT_TRUE(job.ok()) << formatAll(job.diagnostics());
    EXPECT_EQ(job->influences.count(skin::InfluenceMatch::How::Mapped), 1u);
    ASSERT_TRUE(test::succeeded(job->run()));
    auto applied = r.f.s.applySkinImport(job.take(), "Import skin weights");
    ASSERT_TRUE(applied.ok()) << formatAll(applied.diagnostics());
    EXPECT_EQ((*applied)[0].route, skin::ImportRoute::OneToOne);
    EXPECT_TRUE(r.f.s.document().bindings[0].weights == r.bound) << "mapped back by name: exactly the bound weights";
    EXPECT_EQ(r.f.s.history().undoText(), "Import skin weights");
    r.f.s.history().undo();
    EXPECT_TRUE(r.f.s.document().bindings[0].weights == spoiled) << "one undo step";
}

TEST(SessionInfluences, CreateAddsAJointUnderTheMatchedParentWithTheWeightsInOneUndoStep)
{
    RenamedElbow r;
    r.chunks[0].joints[r.elbow].name = "elbow_old_L"; // a left-side name: the branch copy keeps it
    const model::GuideDocument before = r.f.s.document();
    const Mat4 elbowBind = r.chunks[0].joints[r.elbow].bind;
    const std::string parentName = r.f.s.rig()->nodes[r.f.s.skinBones()[r.parent].node].name;
    const model::JointId parentGuide = r.f.s.rig()->nodes[r.f.s.skinBones()[r.parent].node].guide;
    const NodeKey elbowKey = r.f.s.skinBones()[r.elbow].key, parentKey = r.f.s.skinBones()[r.parent].key; // bone indices move with a rebuild
    skin::InfluenceMapOptions influences;
    influences.missing = skin::MissingInfluences::Create;
    const std::size_t steps = r.f.s.history().size();
    auto reports = r.f.s.importSkinChunks(r.chunks, {}, session::SkinScope::all(), influences);
    ASSERT_TRUE(reports.ok()) << formatAll(reports.diagnostics());
    const std::string said = formatAll(reports.diagnostics());
    EXPECT_NE(said.find("influence 'elbow_old_L' is created: skin joint 'elbow_old_L' under '" + parentName + "'"), std::string::npos) << said;
    EXPECT_EQ(r.f.s.history().size(), steps + 1) << "the joint and the weights: one undo step";
    EXPECT_EQ(r.f.s.history().undoText(), "Import skin weights");

    // The guide has a one-joint core.joints instance under the parent's guide joint, at the influence's bind position.
    ASSERT_EQ(r.f.s.document().instances().size(), before.instances().size() + 1);
    const model::TemplateInstance& added = r.f.s.document().instances().back();
    EXPECT_EQ(added.templateId, "core.joints");
    EXPECT_EQ(added.parentJoint, parentGuide);
    ASSERT_EQ(added.joints.size(), 1u);
    EXPECT_LT(glm::length(translationOf(r.f.s.document().jointWorldMatrix(added.joints[0].id)) - translationOf(elbowBind)), 1e-5);

    // The rebuilt rig has the skin joint of that name, there, under the matched parent, and the elbow's weights are on it.
    const auto& bones = r.f.s.skinBones();
    std::size_t created = bones.size();
    for (std::size_t b = 0; b < bones.size(); ++b)
        if (r.f.s.rig()->nodes[bones[b].node].name == "elbow_old_L")
            created = b;
    ASSERT_LT(created, bones.size()) << "a skin joint named as the influence";
    const model::RigNode& node = r.f.s.rig()->nodes[bones[created].node];
    EXPECT_EQ(node.key.instance, added.id);
    ASSERT_GE(bones[created].parent, 0);
    EXPECT_EQ(bones[std::size_t(bones[created].parent)].key, parentKey) << "its skin parent is the matched parent";
    EXPECT_LT(glm::length(translationOf(node.worldMatrix) - translationOf(elbowBind)), 1e-5);
    ASSERT_TRUE(r.f.s.characterMeshes()[0].weights);
    const model::MeshWeights& applied = *r.f.s.characterMeshes()[0].weights;
    std::size_t moved = 0;
    for (std::size_t v = 0; v < applied.vertexCount(); ++v) {
        const float was = weightOnKey(r.bound, v, elbowKey);
        moved += was > 0.0f ? 1 : 0;
        EXPECT_NEAR(weightOnKey(applied, v, node.key), was, 1e-6) << "vertex " << v;
        EXPECT_EQ(weightOnKey(applied, v, elbowKey), 0.0f) << "vertex " << v;
        EXPECT_NEAR(weightOnKey(applied, v, parentKey), weightOnKey(r.bound, v, parentKey), 1e-6) << "vertex " << v;
    }
    EXPECT_GT(moved, 20u) << "the elbow weighted part of the sleeve";

    // The next import of the same chunks finds it by name: nothing missing, nothing created.
    EXPECT_TRUE(r.f.s.missingInfluences(r.chunks, {}).empty());

    r.f.s.history().undo();
    EXPECT_TRUE(r.f.s.document() == before) << "undo removes the joint and the weights together";
    r.f.s.history().redo();
    EXPECT_EQ(r.f.s.document().instances().size(), before.instances().size() + 1);
}

TEST(SessionInfluences, CreateRefusesWhenTheGuideChangedSincePrepare)
{
    RenamedElbow r;
    skin::InfluenceMapOptions influences;
    influences.missing = skin::MissingInfluences::Create;
    auto job = r.f.s.prepareSkinImport(r.chunks, {}, session::SkinScope::all(), influences);
    ASSERT_TRUE(job.ok()) << formatAll(job.diagnostics());
    ASSERT_EQ(job->created.instances.size(), 1u);
    ASSERT_TRUE(test::succeeded(job->run()));
    ASSERT_TRUE(test::succeeded(r.f.s.addTemplate("core.joints", model::kNoId))); // takes the planned ids
    const model::GuideDocument changed = r.f.s.document();
    const std::size_t steps = r.f.s.history().size();
    auto applied = r.f.s.applySkinImport(job.take(), "Import skin weights");
    ASSERT_FALSE(applied.ok());
    EXPECT_NE(formatAll(applied.diagnostics()).find("the guide changed since the import was prepared"), std::string::npos);
    EXPECT_TRUE(r.f.s.document() == changed) << "nothing changed";
    EXPECT_EQ(r.f.s.history().size(), steps);
}
