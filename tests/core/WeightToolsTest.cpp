// Weight painting tools (issue 19 item 5): brush dabs keep weights normalised
// and locked joints untouched, reach along the surface without bleeding over
// a gap, treat seam-split vertices as one point; smoothing, pruning,
// normalising, limiting and mirroring across a plane.
#include "skin/WeightTools.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace rs;
using model::Influence;

namespace {

// A vertical tube of `rings` rings of 8 around x = `x`, from y 0 to 2, with a
// seam: the first column is duplicated (a UV seam splits it in the file).
void addTube(model::Mesh& mesh, double x, int rings = 21)
{
    const std::uint32_t base = std::uint32_t(mesh.positions.size());
    constexpr int kSides = 8;
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s <= kSides; ++s) { // s == kSides: the seam copy of s == 0
            const double t = 2.0 * M_PI * (s % kSides) / kSides;
            mesh.positions.emplace_back(x + 0.1 * std::cos(t), 2.0 * r / (rings - 1), 0.1 * std::sin(t));
        }
    for (int r = 0; r + 1 < rings; ++r)
        for (int s = 0; s < kSides; ++s) {
            const std::uint32_t i = base + r * (kSides + 1) + s, j = i + 1;
            mesh.indices.insert(mesh.indices.end(), {i, j, i + kSides + 1, j, j + kSides + 1, i + kSides + 1});
        }
}

// Joints: 0 root (parent -1), 1 lower (parent 0), 2 upper (parent 1). Below y
// = 1 a vertex is all `lower`, above all `upper`.
model::MeshWeights hardWeights(const model::Mesh& mesh, std::uint32_t lower = 1, std::uint32_t upper = 2)
{
    model::MeshWeights w;
    w.joints = {{1, "", "skin.root"}, {1, "", "skin.lower"}, {1, "", "skin.upper"}};
    w.parents = {-1, 0, 1};
    w.offsets = {0};
    for (const glm::vec3& p : mesh.positions) {
        w.influences.push_back({p.y < 1.0 ? lower : upper, 1.0f});
        w.offsets.push_back(std::uint32_t(w.influences.size()));
    }
    return w;
}

model::MeshWeights applied(const model::MeshWeights& w, const std::vector<skin::VertexInfluences>& changes)
{
    model::MeshWeights out = w;
    out.influences.clear();
    out.offsets = {0};
    auto next = changes.begin();
    for (std::uint32_t v = 0; v < w.vertexCount(); ++v) {
        if (next != changes.end() && next->vertex == v) {
            out.influences.insert(out.influences.end(), next->influences.begin(), next->influences.end());
            ++next;
        } else
            out.influences.insert(out.influences.end(), w.begin(v), w.end(v));
        out.offsets.push_back(std::uint32_t(out.influences.size()));
    }
    return out;
}

double share(const model::MeshWeights& w, std::uint32_t v, std::uint32_t joint)
{
    for (const Influence* i = w.begin(v); i != w.end(v); ++i)
        if (i->joint == joint)
            return i->weight;
    return 0.0;
}

void expectNormalised(const std::vector<skin::VertexInfluences>& changes)
{
    for (const auto& c : changes) {
        double sum = 0.0;
        for (const Influence& i : c.influences) {
            EXPECT_GT(i.weight, 0.0f);
            sum += i.weight;
        }
        EXPECT_NEAR(sum, 1.0, 1e-5) << "vertex " << c.vertex;
    }
}

struct Tube {
    model::Mesh mesh;
    skin::Surface surface;
    model::MeshWeights weights;
    explicit Tube(double gap = -1.0)
    {
        addTube(mesh, 0.0);
        if (gap > 0.0)
            addTube(mesh, 0.2 + gap); // a second tube beside the first, `gap` between their surfaces
        surface = skin::makeSurface(mesh);
        weights = hardWeights(mesh);
    }
    skin::WeightContext context(std::vector<bool> locked = {}) const { return {&mesh, &surface, &weights, std::move(locked)}; }
    // The file vertex nearest `p`.
    std::uint32_t nearest(Vec3 p) const
    {
        std::uint32_t best = 0;
        for (std::uint32_t v = 1; v < mesh.positions.size(); ++v)
            if (glm::length(Vec3(mesh.positions[v]) - p) < glm::length(Vec3(mesh.positions[best]) - p))
                best = v;
        return best;
    }
};

} // namespace

TEST(WeightTools, AnAddDabRaisesTheJointNearItsCentreOnlyAndKeepsSeamsTogether)
{
    Tube t;
    skin::Brush brush;
    brush.mode = skin::BrushMode::Add;
    brush.joint = 2;
    brush.radius = 0.3;
    brush.strength = 0.5;
    brush.vertex = t.nearest({0.1, 0.8, 0.0}); // on the seam column
    brush.centre = Vec3(t.mesh.positions[brush.vertex]);
    const auto changes = skin::brushDab(t.context(), brush);
    ASSERT_FALSE(changes.empty());
    expectNormalised(changes);
    const model::MeshWeights after = applied(t.weights, changes);
    EXPECT_NEAR(share(after, brush.vertex, 2), 0.5, 1e-5) << "the centre goes halfway to 1";
    const std::uint32_t seamTwin = brush.vertex + 8; // the seam copy in the same ring
    EXPECT_EQ(std::vector<Influence>(after.begin(seamTwin), after.end(seamTwin)),
              std::vector<Influence>(after.begin(brush.vertex), after.end(brush.vertex)))
        << "seam-split vertices are one point";
    for (const auto& c : changes)
        EXPECT_LE(glm::length(Vec3(t.mesh.positions[c.vertex]) - brush.centre), 0.3 + 1e-9) << "nothing beyond the radius";
    const std::uint32_t far = t.nearest({-0.1, 0.3, 0.0});
    EXPECT_EQ(share(after, far, 1), 1.0);

    brush.mode = skin::BrushMode::Subtract;
    brush.strength = 1.0;
    brush.falloff = skin::Falloff::Constant;
    const model::MeshWeights back = applied(after, skin::brushDab({&t.mesh, &t.surface, &after, {}}, brush));
    EXPECT_EQ(share(back, brush.vertex, 2), 0.0) << "subtracting all of it hands the share back";
    EXPECT_NEAR(share(back, brush.vertex, 1), 1.0, 1e-6);
}

TEST(WeightTools, LockedJointsKeepTheirSharesAndAJointAloneGivesToItsParent)
{
    Tube t;
    // A vertex shared 0.3 root (locked), 0.7 lower.
    const std::uint32_t v = t.nearest({0.1, 0.5, 0.0});
    model::MeshWeights w = t.weights;
    w.influences.clear();
    w.offsets = {0};
    for (std::uint32_t i = 0; i < t.weights.vertexCount(); ++i) {
        if (i == v)
            w.influences.insert(w.influences.end(), {{1, 0.7f}, {0, 0.3f}});
        else
            w.influences.insert(w.influences.end(), t.weights.begin(i), t.weights.end(i));
        w.offsets.push_back(std::uint32_t(w.influences.size()));
    }
    const skin::WeightContext locked{&t.mesh, &t.surface, &w, {true, false, false}};
    auto out = skin::setShare({w.begin(v), w.end(v)}, 2, 1.0, locked);
    double root = 0.0, upper = 0.0, sum = 0.0;
    for (const Influence& i : out) {
        sum += i.weight;
        if (i.joint == 0) root = i.weight;
        if (i.joint == 2) upper = i.weight;
    }
    EXPECT_NEAR(root, 0.3, 1e-6) << "the locked root keeps its share";
    EXPECT_NEAR(upper, 0.7, 1e-6) << "the painted joint takes what is left, not more";
    EXPECT_NEAR(sum, 1.0, 1e-6);

    // `lower` alone (root locked at 0.3) reduced to 0.2: its parent (the root) is locked, so it cannot drop.
    out = skin::setShare({{1, 0.7f}, {0, 0.3f}}, 1, 0.2, locked);
    EXPECT_EQ(out, (std::vector<Influence>{{1, 0.7f}, {0, 0.3f}}));
    // Unlocked: the parent takes the rest.
    const skin::WeightContext open{&t.mesh, &t.surface, &w, {}};
    out = skin::setShare({{2, 1.0f}}, 2, 0.25, open);
    EXPECT_EQ(out, (std::vector<Influence>{{1, 0.75f}, {2, 0.25f}}));
    EXPECT_EQ(skin::setShare({{1, 1.0f}}, 1, 0.5, {&t.mesh, &t.surface, &w, {false, true, false}}), (std::vector<Influence>{{1, 1.0f}}))
        << "a locked joint is not painted";
}

TEST(WeightTools, ASurfaceBrushDoesNotBleedAcrossAGapButAVolumeBrushDoes)
{
    Tube t(0.02); // two tubes 2 cm apart
    skin::Brush brush;
    brush.joint = 0;
    brush.radius = 0.15;
    brush.strength = 1.0;
    brush.vertex = t.nearest({0.1, 1.5, 0.0}); // on the first tube, facing the second
    brush.centre = Vec3(t.mesh.positions[brush.vertex]);
    const std::uint32_t firstTubeVertices = t.mesh.vertexCount() / 2;
    auto touchesSecond = [&](const std::vector<skin::VertexInfluences>& changes) {
        return std::any_of(changes.begin(), changes.end(), [&](const auto& c) { return c.vertex >= firstTubeVertices; });
    };
    brush.surface = true;
    const auto alongSurface = skin::brushDab(t.context(), brush);
    ASSERT_FALSE(alongSurface.empty());
    EXPECT_FALSE(touchesSecond(alongSurface));
    brush.surface = false;
    EXPECT_TRUE(touchesSecond(skin::brushDab(t.context(), brush)));
}

TEST(WeightTools, SmoothBlendsAHardBoundaryAndPruneNormaliseLimitTidyUp)
{
    Tube t;
    const auto smoothed = skin::smoothWeights(t.context(), {}, 0.5, 3);
    expectNormalised(smoothed);
    const model::MeshWeights soft = applied(t.weights, smoothed);
    const std::uint32_t boundary = t.nearest({0.1, 0.9, 0.0}); // the last ring below the boundary
    EXPECT_GT(share(soft, boundary, 2), 0.05);
    EXPECT_GT(share(soft, boundary, 1), 0.5);
    EXPECT_EQ(share(soft, t.nearest({0.1, 0.0, 0.0}), 1), 1.0) << "far from the boundary nothing changes";
    EXPECT_TRUE(skin::smoothWeights(t.context({false, true, true}), {}, 0.5, 3).empty()) << "locked joints stay";

    const skin::WeightContext c{&t.mesh, &t.surface, &soft, {}};
    const model::MeshWeights pruned = applied(soft, skin::pruneWeights(c, {}, 0.1));
    for (std::uint32_t v = 0; v < pruned.vertexCount(); ++v)
        for (const Influence* i = pruned.begin(v); i != pruned.end(v); ++i)
            EXPECT_GE(i->weight, 0.1f);
    const model::MeshWeights single = applied(soft, skin::limitWeights(c, {}, 1));
    for (std::uint32_t v = 0; v < single.vertexCount(); ++v) {
        ASSERT_EQ(single.end(v) - single.begin(v), 1);
        EXPECT_EQ(single.begin(v)->weight, 1.0f);
    }
    model::MeshWeights unnormalised = t.weights;
    unnormalised.influences[0].weight = 0.5f;
    const auto fixed = skin::normaliseWeights({&t.mesh, &t.surface, &unnormalised, {}}, {});
    ASSERT_EQ(fixed.size(), 1u);
    EXPECT_EQ(fixed[0].influences, (std::vector<Influence>{{1, 1.0f}}));
}

TEST(WeightTools, MirrorCopiesOneSideOntoTheOtherWithMirroredJoints)
{
    model::Mesh mesh;
    addTube(mesh, 0.5);
    addTube(mesh, -0.5);
    const skin::Surface surface = skin::makeSurface(mesh);
    model::MeshWeights w;
    w.joints = {{1, "", "skin.root"}, {2, "L", "skin.arm"}, {2, "R", "skin.arm"}};
    w.parents = {-1, 0, 0};
    w.offsets = {0};
    for (const glm::vec3& p : mesh.positions) {
        if (p.x > 0.0) // left side: painted; its top half shared with the root
            w.influences.insert(w.influences.end(), p.y > 1.0 ? std::initializer_list<Influence>{{1, 0.6f}, {0, 0.4f}}
                                                             : std::initializer_list<Influence>{{1, 1.0f}});
        else
            w.influences.push_back({0, 1.0f}); // right side: not painted yet
        w.offsets.push_back(std::uint32_t(w.influences.size()));
    }
    const auto result = skin::mirrorWeights({&mesh, &surface, &w, {}}, {0, 2, 1}, 0, true);
    EXPECT_EQ(result.unmatched, 0u);
    expectNormalised(result.vertices);
    const model::MeshWeights after = applied(w, result.vertices);
    for (std::uint32_t v = 0; v < mesh.vertexCount(); ++v) {
        const Vec3 p(mesh.positions[v]);
        if (p.x < 0.0) {
            EXPECT_NEAR(share(after, v, 2), p.y > 1.0 ? 0.6 : 1.0, 1e-6);
            EXPECT_EQ(share(after, v, 1), 0.0);
        } else {
            EXPECT_NEAR(share(after, v, 1), p.y > 1.0 ? 0.6 : 1.0, 1e-6) << "the source side is untouched";
        }
    }
    mesh.positions.back().x -= 0.01; // an asymmetric vertex has no mirror
    const skin::Surface moved = skin::makeSurface(mesh);
    EXPECT_GE(skin::mirrorWeights({&mesh, &moved, &w, {}}, {0, 2, 1}, 0, true).unmatched, 1u);
}
