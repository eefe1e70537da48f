// Incremental rebuild (rigging/BuildCache.h): a build with a cache replays
// every instance copy whose inputs did not change and generates the others;
// the rig must be exactly the one a build without a cache makes, on every
// sample and after every kind of guide edit.
#include "core/IncrementalCheck.h"
#include "TestSupport.h"

#include "io/RigDump.h"
#include "rigging/BuildCache.h"
#include "rigging/BuildContext.h"
#include "rigging/RigBuilder.h"

#include <gtest/gtest.h>

#include <algorithm>

#include <set>

using namespace rs;
using test::buildAndCompare;

namespace {

const char* const kSamples[] = {"biped", "quadruped", "prop", "face", "vehicle", "robot", "claw", "cart", "strider"};

// The branch copies (instance, branch) a full build makes of the instances in `ids`.
std::size_t copiesOf(const model::GuideDocument& guide, const std::vector<model::InstanceId>& ids)
{
    const std::set<model::InstanceId> wanted(ids.begin(), ids.end());
    std::set<CopyKey> copies;
    for (const model::RigNode& node : rigging::buildRig(guide, test::builtinTemplates()).nodes)
        if (wanted.count(node.key.instance))
            copies.insert(node.key.copy());
    return copies.size();
}

void moveFirstJoint(model::GuideDocument& guide, model::InstanceId id, double metres)
{
    guide.instance(id)->joints.front().local.translate.y += metres;
}

} // namespace

TEST(IncrementalBuild, ASecondBuildOfTheSameGuideReplaysEveryCopy)
{
    for (const std::string sample : kSamples) {
        const model::GuideDocument guide = test::loadSample(sample);
        rigging::BuildCache cache;
        const auto first = buildAndCompare(guide, cache, sample + " first");
        EXPECT_EQ(first.replayed, 0u) << sample;
        EXPECT_GT(first.generated, 3u) << sample;
        const auto second = buildAndCompare(guide, cache, sample + " second");
        EXPECT_EQ(second.generated, 0u) << sample;
        EXPECT_EQ(second.replayed, first.generated) << sample;
    }
}

TEST(IncrementalBuild, MovingAnInstanceGeneratesItAndWhatHangsBelowItOnly)
{
    for (const std::string sample : kSamples) {
        model::GuideDocument guide = test::loadSample(sample);
        rigging::BuildCache cache;
        buildAndCompare(guide, cache, sample);
        std::vector<model::InstanceId> ids;
        for (const auto& instance : guide.instances())
            ids.push_back(instance.id);
        for (model::InstanceId id : ids) {
            const std::string what = sample + ": move " + guide.instance(id)->name;
            moveFirstJoint(guide, id, 0.01);
            const auto moved = buildAndCompare(guide, cache, what);
            EXPECT_EQ(moved.generated, copiesOf(guide, guide.subtree(id))) << what;
            guide.instance(id)->joints.front().local.translate.y = test::loadSample(sample).instance(id)->joints.front().local.translate.y;
            buildAndCompare(guide, cache, what + " back");
        }
    }
}

TEST(IncrementalBuild, EveryKindOfGuideEditGivesTheFullBuildOnEverySample)
{
    for (const std::string sample : kSamples) {
        model::GuideDocument guide = test::loadSample(sample);
        rigging::BuildCache cache;
        buildAndCompare(guide, cache, sample);
        std::vector<model::InstanceId> ids;
        for (const auto& instance : guide.instances())
            ids.push_back(instance.id);

        for (model::InstanceId id : ids) {
            model::TemplateInstance& instance = *guide.instance(id);
            const std::string label = sample + ": " + instance.name + ": ";
            const templates::TemplateManifest* manifest = test::builtinTemplates().find(instance.templateId);
            ASSERT_NE(manifest, nullptr) << label;
            // Every boolean option flipped, then back.
            for (const auto& option : manifest->opts)
                if (std::holds_alternative<bool>(option.value)) {
                    guide.instance(id)->options[option.name] = Value(!std::get<bool>(option.value));
                    buildAndCompare(guide, cache, label + "option " + option.name);
                    guide.instance(id)->options.erase(option.name);
                    buildAndCompare(guide, cache, label + "option " + option.name + " back");
                }
            // The first float option and the first enum option set to another value, then back.
            const auto floatOption = std::find_if(manifest->opts.begin(), manifest->opts.end(), [](const auto& o) {
                return std::holds_alternative<double>(o.value);
            });
            if (floatOption != manifest->opts.end()) {
                const double v = std::get<double>(floatOption->value);
                const double other = floatOption->max && v + 0.25 > *floatOption->max ? v - 0.25 : v + 0.25;
                guide.instance(id)->options[floatOption->name] = Value(other);
                buildAndCompare(guide, cache, label + "float option " + floatOption->name);
                guide.instance(id)->options.erase(floatOption->name);
                buildAndCompare(guide, cache, label + "float option " + floatOption->name + " back");
            }
            const auto enumOption = std::find_if(manifest->opts.begin(), manifest->opts.end(), [](const auto& o) {
                return o.isEnum() && o.enumLabels.size() > 1 && std::holds_alternative<long long>(o.value);
            });
            if (enumOption != manifest->opts.end()) {
                const long long v = std::get<long long>(enumOption->value);
                const long long other = enumOption->enumLabels.front().first == v ? enumOption->enumLabels[1].first
                                                                                  : enumOption->enumLabels.front().first;
                guide.instance(id)->options[enumOption->name] = Value(other);
                buildAndCompare(guide, cache, label + "enum option " + enumOption->name);
                guide.instance(id)->options.erase(enumOption->name);
                buildAndCompare(guide, cache, label + "enum option " + enumOption->name + " back");
            }
            // A joint turned (not moved): the instance's frames change, its children's hooks too.
            guide.instance(id)->joints.back().local.rotateDegrees.z += 7.0;
            buildAndCompare(guide, cache, label + "joint turned");
            // Renamed, a name override, a shape edit.
            guide.instance(id)->name += "_x";
            buildAndCompare(guide, cache, label + "renamed");
            if (!manifest->names.empty()) {
                guide.instance(id)->names[manifest->names.begin()->first] = "other";
                buildAndCompare(guide, cache, label + "name override");
            }
            model::ShapeEdit shape;
            shape.transform.scale = Vec3(1.3);
            guide.overrides[{id, {}, "ctrls.fk.0"}].shape.emplace().edit = shape;
            buildAndCompare(guide, cache, label + "shape edit");
        }
        // Naming rules, an instance removed with what hangs below it, one put back
        // elsewhere (reparented), the guide's name.
        guide.naming.controller = "ctl_"; // every controller renamed
        buildAndCompare(guide, cache, sample + ": naming rules");
        const model::InstanceId last = ids.back();
        std::optional<model::TemplateInstance> taken = guide.takeInstance(last);
        ASSERT_TRUE(taken.has_value());
        model::TemplateInstance removed = std::move(*taken);
        buildAndCompare(guide, cache, sample + ": removed");
        if (removed.parent != model::kNoId) {
            const model::TemplateInstance& top = guide.instances().front();
            removed.parent = top.id;
            removed.parentJoint = top.joints.front().id;
            guide.insertInstance(std::move(removed), guide.instances().size());
            buildAndCompare(guide, cache, sample + ": reparented");
        }
        guide.name = "renamed_guide";
        buildAndCompare(guide, cache, sample + ": guide name");
    }
}

namespace {

// A builder that changes a node it did not make (its hook): it can never be
// replayed, since a replay would not repeat the change.
class HidesItsHook final : public rigging::TemplateBuilder {
public:
    std::vector<rigging::GuideJointSpec> createGuide(const templates::TemplateManifest&,
                                                     const std::map<std::string, Value>&) const override
    {
        return {rigging::GuideJointSpec{-1, {}, {}, {}}};
    }
    bool gather(const rigging::BuildContext&) const override { return true; }
    void generate(rigging::BuildContext& ctx) const override
    {
        if (ctx.hookNode() != 0)
            ctx.setHidden(ctx.hookNode());
        const model::JointId joint = ctx.instance().joints.front().id;
        ctx.createNode(model::RigNodeKind::Group, "grps.main", ctx.nodeName(model::NameRole::Group, "main"), model::kNoNode,
                       ctx.guideWorldMatrix(joint), joint);
    }
};

} // namespace

TEST(IncrementalBuild, ABuilderThatChangesAnotherInstancesNodeIsGeneratedEveryTime)
{
    model::GuideDocument guide = test::loadSample("biped");
    rigging::BuilderRegistry builders; // the others fall back to the generic joint-chain builder
    const model::TemplateInstance* neck = guide.instanceNamed("neck");
    ASSERT_NE(neck, nullptr);
    builders.add(neck->templateId, std::make_unique<HidesItsHook>());
    rigging::BuildCache cache;
    buildAndCompare(guide, cache, "first", builders);
    const auto second = buildAndCompare(guide, cache, "second", builders);
    EXPECT_EQ(second.generated, 1u) << "the neck, every time";
}

TEST(IncrementalBuild, AnotherTemplateLibraryStartsOver)
{
    const model::GuideDocument guide = test::loadSample("prop");
    rigging::BuildCache cache;
    const auto first = rigging::buildRig(guide, test::builtinTemplates(), rigging::BuilderRegistry::builtin(), {}, &cache);
    const std::size_t generated = cache.lastBuild().generated;
    const templates::TemplateRegistry reloaded = test::builtinTemplates(); // the same manifests, reloaded
    const auto second = rigging::buildRig(guide, reloaded, rigging::BuilderRegistry::builtin(), {}, &cache);
    EXPECT_EQ(cache.lastBuild().replayed, 0u);
    EXPECT_EQ(cache.lastBuild().generated, generated);
    EXPECT_EQ(io::writeRigDump(first), io::writeRigDump(second));
}
