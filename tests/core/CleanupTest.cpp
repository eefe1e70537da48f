// Issue 23 item 2: cleanup. On every controller of every sample only the
// channels its template declares animatable stay unlocked (the rest locked,
// not keyable, hidden), setup groups and joints are hidden, the default values
// of what is left are recorded; a rigger's lock record wins; without cleanup
// the rig is as before. The recorded defaults reach the glTF extras and the
// FBX user properties (Assimp reads those as node metadata).
#include "TestSupport.h"

#include "core/FbxReader.h"
#include "eval/Channels.h"
#include "io/FbxExport.h"
#include "io/RigDump.h"
#include "io/RigExport.h"
#include "rigging/RigBuilder.h"

#include <assimp/Importer.hpp>
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <filesystem>
#include <functional>

using namespace rs;
using model::ChannelSettings;

namespace {

model::Rig build(const model::GuideDocument& guide)
{
    model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    EXPECT_FALSE(hasErrors(rig.diagnostics)) << formatAll(rig.diagnostics);
    return rig;
}

model::GuideDocument cleaned(model::GuideDocument guide)
{
    guide.build.cleanup = true;
    return guide;
}

std::vector<std::string> sampleNames()
{
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(test::samplePath("biped")).parent_path()))
        if (entry.path().extension() == ".yml")
            names.push_back(entry.path().stem().string());
    std::sort(names.begin(), names.end());
    return names;
}

// What a template means its controls to animate, as a rigger reads the
// templates' docs (the test's own table, not the builders'): the transform
// channels an animator keeps on a controller of `tag`.
std::uint16_t expectedAnimatable(const model::GuideDocument& guide, const model::RigNode& node)
{
    constexpr std::uint16_t T = ChannelSettings::kTranslateChannels, R = ChannelSettings::kRotateChannels,
                            S = ChannelSettings::kScaleChannels;
    const std::string templateId = guide.instance(node.key.instance)->templateId;
    const std::string& tag = node.key.tag;
    if (templateId == "core.xform") { // a prop's part: what its do_* options leave on (all by default)
        const auto& options = guide.instance(node.key.instance)->options;
        auto off = [&](const char* option) { auto it = options.find(option); return it != options.end() && it->second == Value(false); };
        return std::uint16_t((off("do_translate") ? 0 : T) | (off("do_rotate") ? 0 : R) | (off("do_scale") ? 0 : S));
    }
    if (templateId == "core.bones")
        return R; // a bone turns about its head
    if (templateId == "core.joints" || tag == "ctrls.scale")
        return T | R | S; // props' parts and the one global scale control
    if (tag == "ctrls.switch" || tag == "ctrls.hand")
        return 0; // attribute holders
    const bool limb = templateId == "arm.limb" || templateId == "leg.limb" || templateId == "quad.leg";
    if (limb && (tag.rfind("ctrls.up.", 0) == 0 || tag.rfind("ctrls.dn.", 0) == 0))
        return T | R | S; // add_chains tweaks: the flesh moves, turns and bulges
    const auto& options = guide.instance(node.key.instance)->options;
    auto on = [&](const char* option) { auto it = options.find(option); return it != options.end() && it->second == Value(true); };
    if (templateId == "wheel.legacy" && tag == "ctrls.spin")
        return std::uint16_t(1u << model::channelIndex("rx")); // the manual spin about the axle
    if (templateId == "wheel.legacy" && tag == "ctrls.bank")
        return T | R | S; // banks, and flattens the wheel by its scale
    if (templateId == "rig.slide" && tag == "ctrls.slide") { // along the rail, the guides' line
        const auto& joints = guide.instance(node.key.instance)->joints;
        const Vec3 rail = glm::normalize(translationOf(guide.jointWorldMatrix(joints.back().id)) -
                                         translationOf(guide.jointWorldMatrix(joints.front().id)));
        int along = 0;
        for (int axis = 1; axis < 3; ++axis)
            if (std::abs(glm::dot(glm::normalize(Vec3(node.worldMatrix[axis])), rail)) >
                std::abs(glm::dot(glm::normalize(Vec3(node.worldMatrix[along])), rail)))
                along = axis;
        return std::uint16_t((on("do_translate") ? T : (1u << along)) | R | (on("do_scale") ? S : 0));
    }
    if (tag == "ctrls.pole" || tag == "ctrls.pin" || tag == "ctrls.target")
        return T; // points
    const bool fk = tag.rfind("ctrls.fk.", 0) == 0 && templateId != "face.brow";
    if (fk || tag == "ctrls.clavicle" || tag == "ctrls.pelvis" || tag == "ctrls.lid_up" || tag == "ctrls.lid_low")
        return R; // rotation-only FK controls
    if (tag == "ctrls.head") { // a spline neck (the default) follows the head wherever it goes
        const auto& options = guide.instance(node.key.instance)->options;
        const auto spline = options.find("spline");
        return spline == options.end() || spline->second == Value(true) ? T | R : R;
    }
    return T | R;
}

} // namespace

TEST(Cleanup, LeavesEveryControllerOfEverySampleOnlyItsAnimatableChannels)
{
    const std::vector<std::string> samples = sampleNames();
    ASSERT_GE(samples.size(), 4u);
    for (const std::string& sample : samples) {
        const model::GuideDocument guide = test::loadSample(sample);
        const model::Rig rig = build(cleaned(guide));
        const eval::ChannelLayout layout(rig);
        std::size_t controllers = 0;
        for (model::RigNodeIndex i = 0; i < rig.nodes.size(); ++i) {
            const model::RigNode& node = rig.nodes[i];
            const std::string where = sample + " " + node.path;
            if (node.kind != model::RigNodeKind::Controller) {
                EXPECT_EQ(node.hidden, i != 0) << where << ": groups and joints are hidden, the rig root is not";
                EXPECT_TRUE(node.defaultValues.empty()) << where;
                continue;
            }
            ASSERT_FALSE(node.hidden) << where;
            ++controllers;
            const std::uint16_t animatable = expectedAnimatable(guide, node);
            std::vector<std::pair<std::string, double>> defaults;
            for (int c = 0; c < ChannelSettings::kCount; ++c) {
                const bool kept = (animatable >> c) & 1u;
                EXPECT_EQ(node.channels.isLocked(c), !kept) << where << "." << model::channelName(c);
                EXPECT_EQ(node.channels.isHidden(c), !kept) << where << "." << model::channelName(c);
                EXPECT_EQ(node.channels.isKeyable(c), kept) << where << "." << model::channelName(c);
                const auto channel = layout.find(i, model::channelName(c));
                ASSERT_TRUE(channel);
                EXPECT_EQ(layout[*channel].locked, !kept) << where;
                EXPECT_EQ(layout[*channel].hidden, !kept) << where;
                if (kept)
                    defaults.emplace_back(model::channelName(c), node.channels.defaults[c]);
            }
            for (const model::RigAttribute& attribute : node.attributes) {
                EXPECT_FALSE(attribute.locked) << where << "." << attribute.name << ": custom channels stay the animator's";
                defaults.emplace_back(attribute.name, attribute.value);
            }
            EXPECT_FALSE(defaults.empty()) << where << " leaves the animator nothing to touch";
            EXPECT_EQ(node.defaultValues, defaults) << where;
        }
        EXPECT_GT(controllers, 5u) << sample;
        EXPECT_EQ(rig.count(model::RigNodeKind::Controller), controllers) << sample;
    }
}

TEST(Cleanup, HidesSkinJointsAndSetupGroups)
{
    const model::Rig plain = build(test::loadSample("biped"));
    const model::Rig rig = build(cleaned(test::loadSample("biped")));
    ASSERT_EQ(rig.nodes.size(), plain.nodes.size());
    EXPECT_FALSE(test::node(plain, "arm.L::skin.limb.0").hidden) << "without cleanup the skin is shown";
    EXPECT_TRUE(test::node(rig, "arm.L::skin.limb.0").hidden);
    EXPECT_TRUE(test::node(rig, "world::skin.root").hidden);
    for (const char* group : {"world::grps.setup", "world::grps.joint", "world::grps.post", "arm.L::roots.fk.0", "arm.L::spaces.ik",
                              "arm.L::ik.0", "leg.L::rfoot.heel"})
        EXPECT_TRUE(test::node(rig, group).hidden) << group;
    EXPECT_FALSE(rig.nodes[0].hidden);
    EXPECT_EQ(rig.skinJointCount(), plain.skinJointCount()) << "hidden, not removed: the export skeleton is the same";
    EXPECT_EQ(rig.sets.at("controllers"), plain.sets.at("controllers"));
}

TEST(Cleanup, ARiggersLockRecordWinsOverCleanup)
{
    model::GuideDocument guide = cleaned(test::loadSample("biped"));
    const NodeKey fk = test::node(build(guide), "arm.L::ctrls.fk.1").key, ik = test::node(build(guide), "arm.L::ctrls.ik").key;
    guide.overrides[fk].locks = {{"sx", {false, true}}};  // the rigger frees an FK control's scale
    guide.overrides[ik].locks = {{"ty", {true, true}}};   // and locks the IK control's height, shown
    guide.overrides[fk].defaults = {{"rz", 15.0}};
    const model::Rig rig = build(guide);
    const model::RigNode& fkNode = rig.nodes[*rig.find(fk)];
    const model::RigNode& ikNode = rig.nodes[*rig.find(ik)];
    EXPECT_FALSE(fkNode.channels.isLocked(6));
    EXPECT_FALSE(fkNode.channels.isHidden(6));
    EXPECT_TRUE(fkNode.channels.isLocked(7)) << "sy has no record: cleanup locks it";
    EXPECT_TRUE(ikNode.channels.isLocked(1));
    EXPECT_FALSE(ikNode.channels.isHidden(1)) << "the record says locked, not hidden";
    const auto& recorded = fkNode.defaultValues;
    EXPECT_NE(std::find(recorded.begin(), recorded.end(), std::pair<std::string, double>{"sx", 1.0}), recorded.end());
    EXPECT_NE(std::find(recorded.begin(), recorded.end(), std::pair<std::string, double>{"rz", 15.0}), recorded.end())
        << "the recorded default is the overridden one";
    EXPECT_EQ(std::find_if(ikNode.defaultValues.begin(), ikNode.defaultValues.end(), [](auto& d) { return d.first == "ty"; }),
              ikNode.defaultValues.end());
    // With the locks kind left out, cleanup decides alone.
    guide.build.restore.set(model::OverrideKind::Locks, false);
    const model::Rig without = build(guide);
    EXPECT_TRUE(without.nodes[*without.find(fk)].channels.isHidden(6));
    EXPECT_FALSE(without.nodes[*without.find(ik)].channels.isLocked(1));
}

TEST(Cleanup, OffBuildsTheRigAsBefore)
{
    for (const std::string& sample : sampleNames()) {
        const model::GuideDocument guide = test::loadSample(sample);
        ASSERT_FALSE(guide.build.cleanup) << sample << ": the samples are built for riggers";
        const std::string dump = io::writeRigDump(build(guide));
        EXPECT_EQ(dump.find("hidden: ["), std::string::npos) << sample;
        EXPECT_EQ(dump.find("defaults: {"), std::string::npos) << sample;
        const std::string cleanDump = io::writeRigDump(build(cleaned(guide)));
        EXPECT_NE(cleanDump.find(", hidden: [sx, sy, sz]}"), std::string::npos) << sample << ": the world control's scale";
        EXPECT_NE(cleanDump.find("defaults: {"), std::string::npos) << sample;
    }
}

TEST(Cleanup, RecordedDefaultsAreGltfExtrasAndFbxUserProperties)
{
    model::GuideDocument guide = cleaned(test::loadSample("biped"));
    const model::Rig probe = build(guide);
    const NodeKey ik = test::node(probe, "arm.L::ctrls.ik").key;
    guide.overrides[ik].defaults = {{"ty", 0.25}, {"soft_ik", 0.5}};
    const model::Rig rig = build(guide);
    const std::string name = rig.nodes[*rig.find(ik)].name;
    io::ExportOptions options;
    options.controllers = true;
    const std::string glb = test::temporaryPath("cleanup-defaults.glb");
    ASSERT_FALSE(hasErrors(io::exportRig(rig, glb, options)));
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&m, &error, &warning, glb)) << error;
    std::size_t withDefaults = 0;
    for (const auto& node : m.nodes) {
        if (!node.extras.Has("rig") || !node.extras.Get("rig").Has("defaults"))
            continue;
        ++withDefaults;
        if (node.name != name)
            continue;
        const tinygltf::Value& d = node.extras.Get("rig").Get("defaults");
        EXPECT_EQ(d.Get("ty").GetNumberAsDouble(), 0.25);
        EXPECT_EQ(d.Get("soft_ik").GetNumberAsDouble(), 0.5);
        EXPECT_EQ(d.Get("rx").GetNumberAsDouble(), 0.0);
        EXPECT_FALSE(d.Has("sx")) << "a locked channel has no default to reset to";
    }
    EXPECT_EQ(withDefaults, rig.count(model::RigNodeKind::Controller));

    const auto prepared = io::prepareExport(rig, options);
    ASSERT_TRUE(prepared.scene);
    const io::Convention convention = io::conventionFor(io::ExportPreset::Unreal, true);
    const auto bytes = io::fbxBytes(io::converted(*prepared.scene, convention), convention);
    ASSERT_TRUE(bytes);
    const test::FbxFile file = test::readFbx(*bytes);
    ASSERT_TRUE(file.error.empty()) << file.error;
    const test::FbxObjects objects(file);
    bool found = false;
    for (const auto* model : objects.ofKind("Model", "Null")) {
        if (test::fbxObjectName(*model) != name)
            continue;
        found = true;
        std::map<std::string, double> user;
        for (const auto& p : model->find("Properties70")->children)
            if (p.properties.at(3).text == "U" && p.properties.at(1).text == "double")
                user[p.properties[0].text] = p.properties.at(4).number;
        EXPECT_DOUBLE_EQ(user["rig_default_ty"], 25.0) << "centimetres in an Unreal FBX";
        EXPECT_EQ(user["rig_default_soft_ik"], 0.5);
        EXPECT_EQ(user.count("rig_default_sx"), 0u);
    }
    EXPECT_TRUE(found) << name;

    // Without cleanup the controllers carry no defaults: exports are as before.
    const std::string plain = test::temporaryPath("cleanup-off.glb");
    guide.build.cleanup = false;
    ASSERT_FALSE(hasErrors(io::exportRig(build(guide), plain, options)));
    EXPECT_EQ(test::readFileBytes(plain).find("\"defaults\""), std::string::npos);
}

TEST(Cleanup, TwoBuildsOfACleanedGuideExportByteIdenticalGlbAndFbx)
{
    const model::GuideDocument guide = cleaned(test::loadSample("biped"));
    io::ExportOptions options;
    options.controllers = true;
    for (const char* extension : {".glb", ".fbx"}) {
        std::string bytes[2];
        for (int k = 0; k < 2; ++k) {
            const std::string path = test::temporaryPath("cleaned-" + std::to_string(k) + extension);
            ASSERT_FALSE(hasErrors(io::exportRig(build(guide), path, options)));
            bytes[k] = test::readFileBytes(path);
        }
        EXPECT_FALSE(bytes[0].empty());
        EXPECT_TRUE(bytes[0] == bytes[1]) << extension;
        const std::string recorded = extension == std::string(".fbx") ? "rig_default_rx" : "\"defaults\"";
        EXPECT_NE(bytes[0].find(recorded), std::string::npos) << extension;
    }
}

TEST(Cleanup, AssimpReadsTheRecordedDefaultsAsNodeMetadata)
{
    const model::Rig rig = build(cleaned(test::loadSample("prop")));
    io::ExportOptions options;
    options.controllers = true;
    const std::string path = test::temporaryPath("cleanup-assimp.fbx");
    ASSERT_FALSE(hasErrors(io::exportRig(rig, path, options)));
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    std::size_t found = 0;
    std::function<void(const aiNode*)> walk = [&](const aiNode* node) {
        const auto index = rig.findPath("world::ctrls.scale");
        if (index && node->mName.C_Str() == rig.nodes[*index].name && node->mMetaData) {
            float sx = 0.f, rx = -1.f; // Assimp 5.2 keeps FBX double user properties as floats
            EXPECT_TRUE(node->mMetaData->Get("rig_default_sx", sx)) << "the world's scale control scales";
            EXPECT_TRUE(node->mMetaData->Get("rig_default_rx", rx));
            EXPECT_EQ(sx, 1.f);
            EXPECT_EQ(rx, 0.f);
            ++found;
        }
        for (unsigned c = 0; c < node->mNumChildren; ++c)
            walk(node->mChildren[c]);
    };
    walk(scene->mRootNode);
    EXPECT_EQ(found, 1u);
}
