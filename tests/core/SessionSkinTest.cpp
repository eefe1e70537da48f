// The character in the core session: models read through the host's loader,
// a bind as one undo step, weight edits and strokes, weights carried onto the
// rebuilt rig by identity (a gone joint's share to its ancestor, said in the
// log), a changed mesh reported and its weights kept, the skin palette
// following the pose, the weights file beside the guide, painting, mirroring
// and skin chunks. Re-fitting a changed mesh: SessionSkinRefitTest.cpp.
#include "SessionSkinFixture.h"
#include "TestSupport.h"

#include "io/WeightsFile.h"
#include "session/Session.h"
#include "skin/BindModels.h"
#include "skin/Skinning.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>

using namespace rs;
using session::ChangeKind;

using namespace rs::test::sessionskin;

TEST(SessionSkin, AModelIsReadOnceAddedAsOneUndoStepAndRefusedTwice)
{
    Fixture f;
    ASSERT_TRUE(test::succeeded(f.s.addModel(kArm)));
    EXPECT_EQ(f.files.reads, 1) << "the session keeps what it read to add the model";
    EXPECT_EQ(f.s.history().undoText(), "Add model arm.obj");
    ASSERT_EQ(f.s.models().size(), 1u);
    ASSERT_TRUE(f.s.models()[0].model);
    ASSERT_EQ(f.s.characterMeshes().size(), 1u);
    EXPECT_EQ(f.s.characterMeshes()[0].binding, -1);
    EXPECT_FALSE(f.s.characterMeshes()[0].weights) << "unbound";
    EXPECT_NE(test::refusal(f.s.addModel(kArm)), "");
    EXPECT_FALSE(f.s.addModel("/virtual/missing.obj").ok()) << "a file the loader cannot read is refused";
    EXPECT_EQ(f.s.document().models.size(), 1u);
    f.s.history().undo();
    EXPECT_TRUE(f.s.models().empty());
    EXPECT_TRUE(f.s.characterMeshes().empty());
    f.s.history().redo();
    EXPECT_EQ(f.s.characterMeshes().size(), 1u);
}

TEST(SessionSkin, ABindIsOneUndoStepAndTheMeshFollowsThePose)
{
    Fixture f;
    ASSERT_TRUE(test::succeeded(f.s.addModel(kArm)));
    f.bind();
    EXPECT_EQ(f.s.history().undoText(), "Bind skin");
    const session::CharacterMesh& mesh = f.s.characterMeshes()[0];
    ASSERT_TRUE(mesh.weights);
    EXPECT_EQ(mesh.weights->joints.size(), f.s.skinBones().size());
    ASSERT_EQ(f.s.skinPalette().size(), f.s.skinBones().size());
    for (const Mat4& m : f.s.skinPalette())
        EXPECT_LT(maxAbsDifference(m, Mat4(1.0)), 1e-9) << "the rest pose is the bind pose";

    // Bend the elbow in FK: the forearm's vertices move, the upper arm's stay.
    const auto blend = f.s.program()->channels().find(*f.s.rig()->findPath("arm.L::ctrls.switch"), "ik_blend");
    ASSERT_TRUE(test::succeeded(f.s.setChannel(*blend, 0.0, false)));
    const auto rz = f.s.program()->channels().find(*f.s.rig()->findPath("arm.L::ctrls.fk.1"), "rz");
    ASSERT_TRUE(rz);
    ASSERT_TRUE(test::succeeded(f.s.setChannel(*rz, -60.0, false)));
    const model::Mesh& data = mesh.data(f.s.models());
    std::vector<glm::vec3> posed(data.vertexCount());
    skin::SkinningJob job;
    job.positions = data.positions;
    job.weights = f.s.characterMeshes()[0].weights.get();
    job.skinMatrices = f.s.skinPalette();
    job.outPositions = posed;
    ASSERT_TRUE(test::succeeded(job.validate()));
    job.run();
    EXPECT_LT(glm::length(posed.front() - data.positions.front()), 1e-4) << "the shoulder ring stays";
    EXPECT_GT(glm::length(posed.back() - data.positions.back()), 0.1) << "the wrist ring follows the bent elbow";

    f.s.history().undo(); // the pose
    f.s.history().undo(); // the switch
    f.s.history().undo(); // the bind
    EXPECT_FALSE(f.s.characterMeshes()[0].weights);
    EXPECT_TRUE(f.s.document().bindings.empty());
    f.s.history().redo();
    EXPECT_TRUE(f.s.characterMeshes()[0].weights);
}

TEST(SessionSkin, AWeightStrokeIsOneUndoStepAndBadWeightsAreRefused)
{
    Fixture f;
    ASSERT_TRUE(test::succeeded(f.s.addModel(kArm)));
    f.bind();
    const model::MeshWeights before = f.s.document().bindings[0].weights;
    const std::uint32_t hand = std::uint32_t(boneOf(f.s, "arm.L::skin.limb.2"));
    std::vector<session::Change> events;
    f.s.subscribe([&](const session::Change& c) { events.push_back(c); });

    f.s.beginWeightStroke("Paint weights");
    for (std::uint32_t v : {0u, 1u}) {
        edit::WeightEdit dab;
        dab.vertices = {{v, {{hand, 1.0f}}}};
        ASSERT_TRUE(test::succeeded(f.s.setVertexWeights(dab, "dab")));
        EXPECT_TRUE(events.back().has(ChangeKind::Weights) && events.back().preview);
        EXPECT_EQ(events.back().bindings, std::vector<std::size_t>{0});
    }
    f.s.endWeightStroke();
    EXPECT_EQ(f.s.history().undoText(), "Paint weights");
    const model::MeshWeights& after = f.s.document().bindings[0].weights;
    EXPECT_EQ(std::vector<model::Influence>(after.begin(1), after.end(1)), (std::vector<model::Influence>{{hand, 1.0f}}));
    EXPECT_EQ(std::vector<model::Influence>(after.begin(2), after.end(2)), std::vector<model::Influence>(before.begin(2), before.end(2)));
    f.s.history().undo();
    EXPECT_TRUE(f.s.document().bindings[0].weights == before) << "one undo takes the whole stroke back";

    edit::WeightEdit bad;
    bad.vertices = {{0, {{hand, 0.5f}}}};
    EXPECT_NE(test::refusal(f.s.setVertexWeights(bad, "x")), "") << "weights must sum to 1";
    bad.vertices = {{0, {{9999, 1.0f}}}};
    EXPECT_NE(test::refusal(f.s.setVertexWeights(bad, "x")), "") << "no such joint";
    bad.vertices = {{100000, {{hand, 1.0f}}}};
    EXPECT_NE(test::refusal(f.s.setVertexWeights(bad, "x")), "") << "no such vertex";
    EXPECT_TRUE(f.s.document().bindings[0].weights == before);
}

TEST(SessionSkin, AGoneSkinJointsShareGoesToItsAncestorAndTheLogSaysSo)
{
    Fixture f;
    ASSERT_TRUE(test::succeeded(f.s.addModel(kArm)));
    f.bind();
    const model::MeshWeights& w = f.s.document().bindings[0].weights;
    const std::uint32_t elbow = std::uint32_t(boneOf(f.s, "arm.L::skin.limb.1"));
    // A joint an earlier build had (a template option removed it since).
    edit::WeightEdit edit;
    edit.joints = w.joints;
    edit.parents = w.parents;
    edit.joints.push_back({w.joints[elbow].instance, w.joints[elbow].branch, "skin.gone"});
    edit.parents.push_back(std::int32_t(elbow));
    const std::uint32_t gone = std::uint32_t(edit.joints.size() - 1);
    edit.vertices = {{5, {{gone, 1.0f}}}};
    f.reported.clear();
    ASSERT_TRUE(test::succeeded(f.s.setVertexWeights(edit, "Paint weights")));
    EXPECT_TRUE(f.saidSomething("skin.gone is gone; its weights go to its ancestor"));
    const model::MeshWeights& applied = *f.s.characterMeshes()[0].weights;
    EXPECT_EQ(std::vector<model::Influence>(applied.begin(5), applied.end(5)), (std::vector<model::Influence>{{elbow, 1.0f}}));
    EXPECT_EQ(f.s.document().bindings[0].weights.joints.size(), edit.joints.size()) << "the record keeps the gone joint";
}

TEST(SessionSkin, WeightsAreSavedBesideTheGuideAndLoadedBack)
{
    Fixture f;
    ASSERT_TRUE(test::succeeded(f.s.addModel(kArm)));
    f.bind();
    const std::string folder = test::temporaryPath("session-skin");
    std::filesystem::create_directories(folder);
    const std::string guide = folder + "/hero.yml";
    EXPECT_EQ(io::weightsPathFor(guide), folder + "/hero.weights");
    ASSERT_TRUE(test::succeeded(io::saveGuideWeights(f.s.document(), guide)));
    model::GuideDocument loaded;
    ASSERT_TRUE(test::succeeded(io::loadGuideWeights(guide, loaded)));
    ASSERT_EQ(loaded.bindings.size(), 1u);
    EXPECT_TRUE(loaded.bindings[0] == f.s.document().bindings[0]) << "model paths come back absolute";

    // No bindings never replaces a file with an empty one; a damaged file is an error and changes nothing.
    ASSERT_TRUE(test::succeeded(io::saveGuideWeights(model::GuideDocument{}, guide)));
    EXPECT_TRUE(std::filesystem::file_size(io::weightsPathFor(guide)) > 100);
    { std::ofstream(io::weightsPathFor(guide), std::ios::binary | std::ios::trunc) << "RSWEIGHTbroken"; }
    EXPECT_FALSE(io::loadGuideWeights(guide, loaded).ok());
    EXPECT_EQ(loaded.bindings.size(), 1u);
    model::GuideDocument none;
    EXPECT_TRUE(test::succeeded(io::loadGuideWeights(folder + "/other.yml", none))) << "no file: no weights";
    std::filesystem::remove_all(folder);
}

TEST(SessionSkin, PaintingIsOneStepPerStrokeAndRespectsLocks)
{
    Fixture f;
    ASSERT_TRUE(test::succeeded(f.s.addModel(kArm)));
    f.bind();
    const model::Mesh& data = f.s.characterMeshes()[0].data(f.s.models());
    const NodeKey hand = f.s.skinBones()[boneOf(f.s, "arm.L::skin.limb.2")].key;
    skin::Brush brush;
    brush.mode = skin::BrushMode::Add;
    brush.radius = 0.06;
    brush.strength = 1.0;
    brush.falloff = skin::Falloff::Constant;
    brush.vertex = 0; // the shoulder ring
    brush.centre = Vec3(data.positions[0]);
    const std::size_t steps = f.s.history().size();
    f.s.beginWeightStroke("Paint weights");
    ASSERT_TRUE(test::succeeded(f.s.paintWeights(0, hand, brush)));
    brush.vertex = 1;
    brush.centre = Vec3(data.positions[1]);
    ASSERT_TRUE(test::succeeded(f.s.paintWeights(0, hand, brush)));
    f.s.endWeightStroke();
    EXPECT_EQ(f.s.history().size(), steps + 1);
    const model::MeshWeights& applied = *f.s.characterMeshes()[0].weights;
    const std::uint32_t handBone = std::uint32_t(boneOf(f.s, "arm.L::skin.limb.2"));
    EXPECT_EQ(std::vector<model::Influence>(applied.begin(0), applied.end(0)), (std::vector<model::Influence>{{handBone, 1.0f}}));

    f.s.history().undo();
    f.s.setJointLocked(hand, true);
    EXPECT_NE(test::refusal(f.s.paintWeights(0, hand, brush)), "") << "a locked joint is not painted";
    f.s.setJointLocked(hand, false);

    // Operations on the selected vertices only, one step each.
    f.s.selectVertices(0, {0, 1, 2}, false);
    ASSERT_TRUE(test::succeeded(f.s.applyWeightOperation(session::Session::WeightOperation::Limit, 1)));
    EXPECT_EQ(f.s.history().undoText(), "Limit influences");
    const model::MeshWeights& limited = f.s.document().bindings[0].weights;
    for (std::uint32_t v : {0u, 1u, 2u})
        EXPECT_EQ(limited.end(v) - limited.begin(v), 1);
    EXPECT_NE(test::refusal(f.s.applyWeightOperation(session::Session::WeightOperation::Limit, 1)), "") << "no change, no step";

    // Copy vertex 0's weights onto the far ring.
    f.s.selectVertices(0, {0}, false);
    ASSERT_TRUE(test::succeeded(f.s.copyVertexWeights()));
    const std::uint32_t last = std::uint32_t(data.vertexCount() - 1);
    f.s.selectVertices(0, {last}, false);
    ASSERT_TRUE(test::succeeded(f.s.pasteVertexWeights()));
    const model::MeshWeights& pasted = f.s.document().bindings[0].weights;
    EXPECT_EQ(std::vector<model::Influence>(pasted.begin(last), pasted.end(last)),
              std::vector<model::Influence>(pasted.begin(0), pasted.end(0)));
}

TEST(SessionSkin, MirroringCopiesTheLeftArmsWeightsOntoTheRightWithTwinJoints)
{
    Fixture f;
    // Both arms' sleeves in one mesh, bound, then the right one's weights spoiled.
    const model::Mesh left = f.files.files[kArm].meshes[0];
    model::Mesh both = left;
    for (glm::vec3 p : left.positions)
        both.positions.emplace_back(-p.x, p.y, p.z);
    for (std::uint32_t i : left.indices)
        both.indices.push_back(i + std::uint32_t(left.vertexCount()));
    f.files.files[kArm].meshes[0] = both;
    ASSERT_TRUE(test::succeeded(f.s.addModel(kArm)));
    f.bind();
    const std::uint32_t count = std::uint32_t(left.vertexCount());
    std::vector<std::uint32_t> right;
    for (std::uint32_t v = count; v < 2 * count; ++v)
        right.push_back(v);
    f.s.selectVertices(0, right, false);
    ASSERT_TRUE(test::succeeded(f.s.applyWeightOperation(session::Session::WeightOperation::Limit, 1)));
    f.s.clearVertexSelection();
    ASSERT_TRUE(test::succeeded(f.s.mirrorWeights(true)));
    EXPECT_EQ(f.s.history().undoText(), "Mirror weights +X to -X");
    const model::MeshWeights& w = *f.s.characterMeshes()[0].weights;
    const model::Rig& rig = *f.s.rig();
    for (std::uint32_t v = 0; v < count; ++v) {
        std::vector<std::pair<NodeKey, float>> l, r;
        for (const model::Influence* i = w.begin(v); i != w.end(v); ++i) {
            const auto twin = rig.nodes[*rig.find(w.joints[i->joint])].twin;
            l.emplace_back(twin == model::kNoNode ? w.joints[i->joint] : rig.nodes[twin].key, i->weight);
        }
        for (const model::Influence* i = w.begin(v + count); i != w.end(v + count); ++i)
            r.emplace_back(w.joints[i->joint], i->weight);
        std::sort(l.begin(), l.end());
        std::sort(r.begin(), r.end());
        ASSERT_EQ(l.size(), r.size()) << "vertex " << v;
        for (std::size_t k = 0; k < l.size(); ++k) {
            EXPECT_EQ(l[k].first, r[k].first);
            EXPECT_NEAR(l[k].second, r[k].second, 1e-6);
        }
    }
}

TEST(SessionSkin, ExportedChunksImportBackOneToOneExactlyAsOneUndoStep)
{
    Fixture f;
    ASSERT_TRUE(test::succeeded(f.s.addModel(kArm)));
    f.bind();
    const model::MeshBinding bound = f.s.document().bindings[0];
    EXPECT_FALSE(f.s.exportSkinChunks(session::SkinScope::selectedVertices())) << "no vertex selected";
    auto chunks = f.s.exportSkinChunks(session::SkinScope::all());
    ASSERT_TRUE(chunks.ok());
    ASSERT_EQ(chunks->size(), 1u);
    EXPECT_EQ((*chunks)[0].vertexCount(), bound.vertexCount);
    EXPECT_TRUE((*chunks)[0].inBindPose) << "nothing is posed";

    // Spoil the weights, then import: 1:1, exactly the bound weights again.
    f.s.selectVertices(0, {0, 1, 2, 3}, false);
    ASSERT_TRUE(test::succeeded(f.s.applyWeightOperation(session::Session::WeightOperation::Limit, 1)));
    f.s.clearVertexSelection();
    const model::MeshWeights spoiled = f.s.document().bindings[0].weights;
    ASSERT_FALSE(spoiled == bound.weights);
    const std::size_t steps = f.s.history().size();
    auto reports = f.s.importSkinChunks(*chunks, {}, session::SkinScope::all());
    ASSERT_TRUE(reports.ok()) << formatAll(reports.diagnostics());
    ASSERT_EQ(reports->size(), 1u);
    EXPECT_EQ((*reports)[0].route, skin::ImportRoute::OneToOne);
    EXPECT_EQ((*reports)[0].oneToOne, bound.vertexCount);
    EXPECT_TRUE(f.s.document().bindings[0].weights == bound.weights) << "a 1:1 round trip is exact";
    EXPECT_EQ(f.s.history().size(), steps + 1);
    EXPECT_EQ(f.s.history().undoText(), "Import skin weights");
    f.s.history().undo();
    EXPECT_TRUE(f.s.document().bindings[0].weights == spoiled) << "one undo takes the import back";
}

TEST(SessionSkin, ImportOntoSelectedVerticesChangesOnlyThoseAndAPoseIsExported)
{
    Fixture f;
    ASSERT_TRUE(test::succeeded(f.s.addModel(kArm)));
    f.bind();
    const model::MeshWeights bound = f.s.document().bindings[0].weights;
    auto chunks = f.s.exportSkinChunks(session::SkinScope::ofMeshes({0}));
    ASSERT_TRUE(chunks.ok());
    f.s.selectVertices(0, {0, 1, 2, 3, 4, 5}, false);
    ASSERT_TRUE(test::succeeded(f.s.applyWeightOperation(session::Session::WeightOperation::Limit, 1)));
    const model::MeshWeights spoiled = f.s.document().bindings[0].weights;
    f.s.selectVertices(0, {0, 1}, false);
    auto job = f.s.prepareSkinImport(*chunks, {}, session::SkinScope::selectedVertices());
    ASSERT_TRUE(job.ok());
    ASSERT_TRUE(test::succeeded(job->run()));
    const auto routes = job->routes(0);
    EXPECT_EQ(std::count(routes.begin(), routes.end(), session::VertexRoute::OneToOne), std::ptrdiff_t(bound.vertexCount()));
    ASSERT_TRUE(f.s.applySkinImport(job.take(), "Import skin weights").ok());
    const model::MeshWeights& w = f.s.document().bindings[0].weights;
    for (std::uint32_t v : {0u, 1u})
        EXPECT_EQ(std::vector<model::Influence>(w.begin(v), w.end(v)), std::vector<model::Influence>(bound.begin(v), bound.end(v)));
    for (std::uint32_t v : {2u, 5u})
        EXPECT_EQ(std::vector<model::Influence>(w.begin(v), w.end(v)), std::vector<model::Influence>(spoiled.begin(v), spoiled.end(v)));

    // Posed: positions follow the pose, bind positions are kept.
    const auto blend = f.s.program()->channels().find(*f.s.rig()->findPath("arm.L::ctrls.switch"), "ik_blend");
    ASSERT_TRUE(test::succeeded(f.s.setChannel(*blend, 0.0, false)));
    const auto rz = f.s.program()->channels().find(*f.s.rig()->findPath("arm.L::ctrls.fk.1"), "rz");
    ASSERT_TRUE(test::succeeded(f.s.setChannel(*rz, -60.0, false)));
    auto posed = f.s.exportSkinChunks(session::SkinScope::all());
    ASSERT_TRUE(posed.ok());
    EXPECT_FALSE((*posed)[0].inBindPose);
    EXPECT_GT(glm::length((*posed)[0].positions.back() - (*posed)[0].bindPositions.back()), 0.1f);
}

TEST(SessionSkin, ACancelledImportChangesNothing)
{
    Fixture f;
    ASSERT_TRUE(test::succeeded(f.s.addModel(kArm)));
    f.bind();
    auto chunks = f.s.exportSkinChunks(session::SkinScope::all());
    ASSERT_TRUE(chunks.ok());
    // A remeshed sleeve under the same name: a fallback, cancelled half way.
    (*chunks)[0].fingerprint ^= 1;
    const model::GuideDocument before = f.s.document();
    const std::size_t steps = f.s.history().size();
    skin::TransferOptions options;
    options.progress = [](double fraction) { return fraction < 0.5; };
    auto reports = f.s.importSkinChunks(*chunks, options, session::SkinScope::all());
    EXPECT_FALSE(reports.ok());
    EXPECT_NE(formatAll(reports.diagnostics()), "") << "says why";
    EXPECT_TRUE(f.s.document() == before);
    EXPECT_EQ(f.s.history().size(), steps);
}
