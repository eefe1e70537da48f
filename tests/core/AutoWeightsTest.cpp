// Automatic weights (skin/AutoWeights.h) on small meshes built here: a limb
// tube, boxes that touch, an eyeball no bone can see, a non-manifold fan with
// duplicated vertices, zero-area faces and a loose point. Whatever the mesh,
// every vertex ends up weighted, normalised and within the influence limit.
#include "TestSupport.h"

#include "rigging/RigBuilder.h"
#include "skin/AutoWeights.h"
#include "skin/Retarget.h"
#include "skin/Surface.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace rs;
using skin::SkinBone;

namespace {

SkinBone bone(const std::string& tag, Vec3 head, std::vector<Vec3> tails)
{
    SkinBone b;
    b.key = {1, {}, tag};
    b.head = head;
    b.tails = std::move(tails);
    return b;
}

// An open tube along +X from x = 0 to `length`, radius r, `rings` rings of `sides` vertices.
model::Mesh tube(double length, double r, int rings, int sides)
{
    model::Mesh m;
    m.name = "tube";
    for (int i = 0; i < rings; ++i)
        for (int k = 0; k < sides; ++k) {
            const double a = 2.0 * M_PI * k / sides;
            m.positions.emplace_back(float(length * i / (rings - 1)), float(r * std::cos(a)), float(r * std::sin(a)));
        }
    for (int i = 0; i + 1 < rings; ++i)
        for (int k = 0; k < sides; ++k) {
            const auto a = std::uint32_t(i * sides + k), b = std::uint32_t(i * sides + (k + 1) % sides);
            const auto c = a + std::uint32_t(sides), d = b + std::uint32_t(sides);
            m.indices.insert(m.indices.end(), {a, b, d, a, d, c});
        }
    return m;
}

// A closed box; each face has its own four vertices (split like a file's UV seams).
void addBox(model::Mesh& m, Vec3 centre, Vec3 half)
{
    const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0}) {
            const Vec3 n = axes[axis] * sign;
            const Vec3 u = axes[(axis + 1) % 3], v = axes[(axis + 2) % 3];
            const auto base = std::uint32_t(m.positions.size());
            for (auto [su, sv] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}})
                m.positions.push_back(glm::vec3(centre + half * (n + double(su) * u + double(sv) * v)));
            if (sign > 0)
                m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
            else
                m.indices.insert(m.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
        }
}

void addSphere(model::Mesh& m, Vec3 centre, double r, int rings, int sides)
{
    const auto base = std::uint32_t(m.positions.size());
    for (int i = 0; i <= rings; ++i)
        for (int k = 0; k < sides; ++k) {
            const double polar = M_PI * i / rings, a = 2.0 * M_PI * k / sides;
            m.positions.push_back(glm::vec3(centre + r * Vec3(std::sin(polar) * std::cos(a), std::cos(polar), std::sin(polar) * std::sin(a))));
        }
    for (int i = 0; i < rings; ++i)
        for (int k = 0; k < sides; ++k) {
            const auto a = base + std::uint32_t(i * sides + k), b = base + std::uint32_t(i * sides + (k + 1) % sides);
            m.indices.insert(m.indices.end(), {a, b, b + std::uint32_t(sides), a, b + std::uint32_t(sides), a + std::uint32_t(sides)});
        }
}

std::uint32_t dominant(const model::MeshWeights& w, std::size_t v)
{
    std::uint32_t best = 0;
    float most = -1.0f;
    for (auto* i = w.begin(v); i != w.end(v); ++i)
        if (i->weight > most) {
            most = i->weight;
            best = i->joint;
        }
    return best;
}

// Every vertex weighted, normalised, within the limit, to known joints.
void expectWellFormed(const model::Mesh& mesh, const model::MeshWeights& w, int limit, const std::string& what)
{
    ASSERT_EQ(w.vertexCount(), mesh.vertexCount()) << what;
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const auto count = w.end(v) - w.begin(v);
        ASSERT_GE(count, 1) << what << ": vertex " << v << " is unweighted";
        ASSERT_LE(count, limit) << what << ": vertex " << v;
        double sum = 0.0;
        for (auto* i = w.begin(v); i != w.end(v); ++i) {
            ASSERT_LT(i->joint, w.joints.size()) << what;
            ASSERT_GT(i->weight, 0.0f) << what;
            sum += i->weight;
        }
        ASSERT_NEAR(sum, 1.0, 1e-5) << what << ": vertex " << v;
    }
}

} // namespace

TEST(AutoWeights, ALimbTubeFollowsItsBonesAndBlendsAtTheJoint)
{
    const model::Mesh mesh = tube(2.0, 0.1, 41, 12);
    const std::vector<SkinBone> bones = {bone("upper", {0, 0, 0}, {{1, 0, 0}}), bone("lower", {1, 0, 0}, {{2, 0, 0}}),
                                         bone("hand", {2, 0, 0}, {})};
    skin::BindStats stats;
    auto weights = skin::bindMesh(mesh, bones, {}, &stats);
    ASSERT_TRUE(weights.ok()) << formatAll(weights.diagnostics());
    expectWellFormed(mesh, *weights, 4, "tube");
    EXPECT_EQ(stats.parts, 1u);
    EXPECT_EQ(stats.partsByClosestBone, 0u);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        const double x = mesh.positions[v].x;
        if (x < 0.8)
            EXPECT_EQ(dominant(*weights, v), 0u) << "x = " << x;
        if (x > 1.2 && x < 1.8)
            EXPECT_EQ(dominant(*weights, v), 1u) << "x = " << x;
    }
    // Smooth across the elbow: both bones share the vertices at x = 1.
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
        if (std::abs(mesh.positions[v].x - 1.0f) < 1e-4f)
            EXPECT_GE(weights->end(v) - weights->begin(v), 2) << "a hard seam at the elbow";
}

TEST(AutoWeights, SeamVerticesOfOnePointGetTheSameWeights)
{
    model::Mesh mesh;
    addBox(mesh, {0, 0.5, 0}, {0.2, 0.5, 0.2}); // 24 file vertices, 8 positions
    const std::vector<SkinBone> bones = {bone("low", {0, 0, 0}, {{0, 0.5, 0}}), bone("high", {0, 0.5, 0}, {{0, 1, 0}})};
    auto weights = skin::bindMesh(mesh, bones, {});
    ASSERT_TRUE(weights.ok());
    expectWellFormed(mesh, *weights, 4, "box");
    EXPECT_EQ(skin::makeSurface(mesh).positions.size(), 8u) << "welded across the face seams";
    for (std::size_t a = 0; a < mesh.vertexCount(); ++a)
        for (std::size_t b = 0; b < mesh.vertexCount(); ++b)
            if (mesh.positions[a] == mesh.positions[b])
                EXPECT_EQ(dominant(*weights, a), dominant(*weights, b));
}

TEST(AutoWeights, TwoBoxesThatTouchEachFollowTheirOwnBone)
{
    model::Mesh mesh;
    addBox(mesh, {-0.5, 0, 0}, {0.5, 0.2, 0.2});
    addBox(mesh, {0.5, 0, 0}, {0.5, 0.2, 0.2});
    const std::vector<SkinBone> bones = {bone("left", {-0.9, 0, 0}, {{-0.1, 0, 0}}), bone("right", {0.1, 0, 0}, {{0.9, 0, 0}})};
    skin::BindStats stats;
    auto weights = skin::bindMesh(mesh, bones, {}, &stats);
    ASSERT_TRUE(weights.ok());
    expectWellFormed(mesh, *weights, 4, "two boxes");
    EXPECT_EQ(stats.parts, 1u) << "they share the face where they touch";
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
        if (std::abs(mesh.positions[v].x) > 0.5f)
            EXPECT_EQ(dominant(*weights, v), mesh.positions[v].x < 0 ? 0u : 1u);
}

TEST(AutoWeights, AnEyeballNoBoneCanSeeTakesItsClosestBoneAndSaysSo)
{
    model::Mesh mesh;
    addBox(mesh, {0, 1.6, 0}, {0.15, 0.15, 0.15});   // the head, closed
    addSphere(mesh, {0.05, 1.62, 0.1}, 0.02, 6, 8);  // an eye inside it
    const std::size_t headVertices = 24;
    const std::vector<SkinBone> bones = {bone("neck", {0, 1.0, 0}, {{0, 1.3, 0}}), bone("chest", {0, 0.5, 0}, {{0, 1.0, 0}})};
    skin::BindStats stats;
    auto weights = skin::bindMesh(mesh, bones, {}, &stats);
    ASSERT_TRUE(weights.ok());
    expectWellFormed(mesh, *weights, 4, "eyeball");
    EXPECT_EQ(stats.parts, 2u);
    EXPECT_EQ(stats.partsByClosestBone, 1u);
    ASSERT_FALSE(weights.diagnostics().empty());
    EXPECT_NE(weights.diagnostics().front().message.find("sees no bone"), std::string::npos);
    for (std::size_t v = headVertices; v < mesh.vertexCount(); ++v) {
        ASSERT_EQ(weights->end(v) - weights->begin(v), 1);
        EXPECT_EQ(weights->begin(v)->joint, 0u) << "the neck is the closest bone";
    }
}

TEST(AutoWeights, BrokenGeometryStillBindsEveryVertex)
{
    model::Mesh mesh = tube(1.0, 0.1, 6, 6);
    const auto n = std::uint32_t(mesh.positions.size());
    // A non-manifold fan: three extra triangles on one edge of the tube.
    for (float y : {0.3f, 0.4f, 0.5f}) {
        mesh.positions.emplace_back(0.5f, y, 0.0f);
        mesh.indices.insert(mesh.indices.end(), {0, 1, std::uint32_t(mesh.positions.size() - 1)});
    }
    mesh.positions.push_back(mesh.positions[3]);                       // a duplicated vertex
    mesh.indices.insert(mesh.indices.end(), {2, 3, n + 3});            // a zero-area face through it
    mesh.indices.insert(mesh.indices.end(), {4, 4, 5});                // a degenerate face
    mesh.positions.emplace_back(3.0f, 3.0f, 3.0f);                     // a loose point in no face
    mesh.positions.emplace_back(std::nanf(""), 0.0f, 0.0f);            // a NaN point in no face
    const std::vector<SkinBone> bones = {bone("a", {0, 0, 0}, {{0.5, 0, 0}}), bone("b", {0.5, 0, 0}, {{1, 0, 0}})};
    for (skin::BindMethod method : {skin::BindMethod::Heat, skin::BindMethod::Envelope, skin::BindMethod::Closest}) {
        skin::BindOptions options;
        options.method = method;
        options.maxInfluences = 2;
        auto weights = skin::bindMesh(mesh, bones, options);
        ASSERT_TRUE(weights.ok()) << skin::bindMethodName(method);
        expectWellFormed(mesh, *weights, 2, skin::bindMethodName(method));
    }
}

TEST(AutoWeights, ACancelledBindFailsAndBadOptionsAreRefused)
{
    const model::Mesh mesh = tube(2.0, 0.1, 11, 8);
    const std::vector<SkinBone> bones = {bone("a", {0, 0, 0}, {{2, 0, 0}})};
    skin::BindOptions options;
    options.progress = [](double fraction) { return fraction < 0.25; };
    auto cancelled = skin::bindMesh(mesh, bones, options);
    ASSERT_FALSE(cancelled.ok());
    EXPECT_NE(formatAll(cancelled.diagnostics()).find("cancelled"), std::string::npos);
    options = {};
    options.maxInfluences = 0;
    EXPECT_FALSE(skin::bindMesh(mesh, bones, options).ok());
    EXPECT_FALSE(skin::bindMesh(mesh, {}, {}).ok()) << "no bone";
}

TEST(AutoWeights, TheBipedsSkinJointsAreItsBones)
{
    const model::Rig rig = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    auto bones = skin::skinBones(rig);
    ASSERT_TRUE(bones.ok()) << formatAll(bones.diagnostics());
    EXPECT_EQ(bones->size(), rig.skinJointCount());
    for (const SkinBone& b : *bones)
        EXPECT_EQ(rig.nodes[b.node].kind, model::RigNodeKind::Joint);
}

TEST(AutoWeights, WeightsFollowTheirJointsIntoAnotherBuildAndAGoneJointGivesItsShareToItsAncestor)
{
    const model::Mesh mesh = tube(2.0, 0.1, 21, 8);
    const std::vector<SkinBone> before = {bone("root", {0, 0, 0}, {{0.7, 0, 0}}), bone("mid", {0.7, 0, 0}, {{1.4, 0, 0}}),
                                          bone("tip", {1.4, 0, 0}, {{2, 0, 0}})};
    std::vector<SkinBone> bones = before;
    bones[1].parent = 0;
    bones[2].parent = 1;
    auto weights = skin::bindMesh(mesh, bones, {});
    ASSERT_TRUE(weights.ok());
    EXPECT_EQ(weights->parents, (std::vector<std::int32_t>{-1, 0, 1}));

    // The next build lists the joints in another order: nothing changes but the indices.
    std::vector<SkinBone> reordered = {bones[2], bones[0], bones[1]};
    reordered[0].parent = 2;
    reordered[1].parent = -1;
    reordered[2].parent = 1;
    auto moved = skin::retargetWeights(*weights, reordered, "tube");
    ASSERT_TRUE(moved.ok());
    EXPECT_TRUE(moved.diagnostics().empty());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
        EXPECT_EQ(moved->joints[dominant(*moved, v)], weights->joints[dominant(*weights, v)]);

    // "mid" is gone: its share goes to "root", its parent, and a note says so.
    const std::vector<SkinBone> without = {bones[0], [&] { SkinBone t = bones[2]; t.parent = 0; return t; }()};
    auto kept = skin::retargetWeights(*weights, without, "tube");
    ASSERT_TRUE(kept.ok());
    expectWellFormed(mesh, *kept, 4, "mid gone");
    ASSERT_EQ(kept.diagnostics().size(), 1u);
    EXPECT_NE(kept.diagnostics().front().message.find("its ancestor"), std::string::npos);
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v) {
        if (std::abs(mesh.positions[v].x - 1.05f) < 0.06f)
            EXPECT_EQ(kept->joints[dominant(*kept, v)].tag, "root") << "the middle of the gone bone";
        float tipBefore = 0.0f, tipAfter = 0.0f;
        for (auto* i = weights->begin(v); i != weights->end(v); ++i)
            if (weights->joints[i->joint].tag == "tip") tipBefore = i->weight;
        for (auto* i = kept->begin(v); i != kept->end(v); ++i)
            if (kept->joints[i->joint].tag == "tip") tipAfter = i->weight;
        EXPECT_NEAR(tipAfter, tipBefore, 1e-6f) << "the surviving joints keep their shares";
    }
}
