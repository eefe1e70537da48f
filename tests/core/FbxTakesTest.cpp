// Takes read one after another (issue: the robot with non_rolling arms,
// Export.robot-rolling-arm.BlenderMidKeys): Blender 3.4's FBX importer keeps
// one transform per model across the takes it reads and sets from each take
// only the components that take has curves for, so a component a take leaves
// out plays the previous take's last value instead of the model's own. The
// file must play the same whichever way a reader fills the gaps.
#include "core/FbxReader.h"
#include "core/TestSupport.h"
#include "io/ExportScene.h"
#include "io/FbxExport.h"
#include "io/GltfExport.h"
#include "rigging/RigBuilder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <set>

using namespace rs;

namespace {

using LclValues = std::array<Vec3, 3>; // Lcl Translation, Lcl Rotation (XYZ degrees), Lcl Scaling
const char* const kProperties[3] = {"Lcl Translation", "Lcl Rotation", "Lcl Scaling"};

int propertyIndex(const std::string& name)
{
    for (int p = 0; p < 3; ++p)
        if (name == kProperties[p])
            return p;
    return -1;
}

int channelIndex(const std::string& name) { return name == "d|X" ? 0 : name == "d|Y" ? 1 : name == "d|Z" ? 2 : -1; }

Quat fromEulerXyzDegrees(const Vec3& e)
{
    const Vec3 r = glm::radians(e);
    return glm::angleAxis(r.z, Vec3(0, 0, 1)) * glm::angleAxis(r.y, Vec3(0, 1, 0)) * glm::angleAxis(r.x, Vec3(1, 0, 0));
}

struct Curve {
    int property = 0, channel = 0;
    std::vector<double> times, values;
    double at(double t) const // linear, held beyond the ends
    {
        if (t <= times.front())
            return values.front();
        for (std::size_t k = 1; k < times.size(); ++k)
            if (t <= times[k])
                return values[k - 1] + (values[k] - values[k - 1]) * (t - times[k - 1]) / (times[k] - times[k - 1]);
        return values.back();
    }
};

// The model's Lcl values from its Properties70.
LclValues modelTransform(const test::FbxRecord& model)
{
    LclValues out{Vec3(0.0), Vec3(0.0), Vec3(1.0)};
    for (const test::FbxRecord* p : model.find("Properties70")->all("P")) {
        const int index = propertyIndex(p->properties[0].text);
        if (index >= 0)
            out[std::size_t(index)] = Vec3(p->properties[4].number, p->properties[5].number, p->properties[6].number);
    }
    return out;
}

// How far apart two readers play `bytes` at every key of every take: one
// starting each take from the models' values (three.js, Assimp), one from
// what the previous take left (Blender 3.4).
struct Carried {
    std::size_t compared = 0, takes = 0;
    double worstDegrees = 0.0, worstOffset = 0.0;
    std::string worstWhere;
};

Carried playTakesBothWays(const std::string& bytes)
{
    Carried out;
    const test::FbxFile file = test::readFbx(bytes);
    EXPECT_TRUE(file.error.empty()) << file.error;
    const test::FbxObjects objects(file);

    // Curves by take (stack, in file order) and model.
    std::map<std::int64_t, std::int64_t> stackOfLayer;
    for (const auto& [child, link] : objects.parents)
        if (objects.byId.at(child)->name == "AnimationLayer")
            stackOfLayer[child] = link.first;
    std::map<std::int64_t, std::map<std::int64_t, std::vector<Curve>>> curves; // stack -> model -> curves
    for (const auto& [curveId, link] : objects.parents) {
        const test::FbxRecord& curve = *objects.byId.at(curveId);
        if (curve.name != "AnimationCurve")
            continue;
        Curve c;
        c.channel = channelIndex(link.second);
        c.times = curve.find("KeyTime")->properties[0].array;
        c.values = curve.find("KeyValueFloat")->properties[0].array;
        std::int64_t model = 0, stack = 0;
        for (auto [at, end] = objects.parents.equal_range(link.first); at != end; ++at) {
            if (objects.byId.at(at->second.first)->name == "Model") {
                model = at->second.first;
                c.property = propertyIndex(at->second.second);
            } else if (stackOfLayer.count(at->second.first))
                stack = stackOfLayer.at(at->second.first);
        }
        if (model != 0 && c.property >= 0 && c.channel >= 0)
            curves[stack][model].push_back(std::move(c));
    }
    out.takes = curves.size();

    std::map<std::int64_t, LclValues> carried;
    for (const auto& [stack, models] : curves) {
        const std::string take = test::fbxObjectName(*objects.byId.at(stack));
        for (const auto& [model, modelCurves] : models) {
            const LclValues own = modelTransform(*objects.byId.at(model));
            LclValues& left = carried.try_emplace(model, own).first->second;
            std::set<double> times;
            for (const Curve& c : modelCurves)
                times.insert(c.times.begin(), c.times.end());
            for (double t : times) {
                LclValues fresh = own;
                for (const Curve& c : modelCurves) {
                    fresh[std::size_t(c.property)][c.channel] = c.at(t);
                    left[std::size_t(c.property)][c.channel] = c.at(t);
                }
                const double degrees = glm::degrees(glm::angle(glm::inverse(fromEulerXyzDegrees(fresh[1])) *
                                                               fromEulerXyzDegrees(left[1])));
                const double offset = std::max(glm::length(fresh[0] - left[0]), glm::length(fresh[2] - left[2]));
                ++out.compared;
                if (std::min(degrees, 360.0 - degrees) > out.worstDegrees || offset > out.worstOffset) {
                    out.worstDegrees = std::max(out.worstDegrees, std::min(degrees, 360.0 - degrees));
                    out.worstOffset = std::max(out.worstOffset, offset);
                    out.worstWhere = test::fbxObjectName(*objects.byId.at(model)) + " in " + take;
                }
            }
        }
    }
    return out;
}

} // namespace

TEST(FbxExport, EveryTakePlaysItsKeysWhenAReaderCarriesComponentsAcrossTakes)
{
    const model::Rig rig = rigging::buildRig(test::loadGuide("Export/robot-rolling-arm/guide.yml"), test::builtinTemplates());
    io::ExportOptions options;
    options.rangeOfMotion = true;
    const auto prepared = io::prepareExport(rig, options);
    ASSERT_TRUE(prepared.scene);
    ASSERT_GT(prepared.scene->clips.size(), 2u) << "several takes in file order";
    const io::Convention convention = io::conventionFor(io::ExportPreset::Gltf, true);
    const auto bytes = io::fbxBytes(io::converted(*prepared.scene, convention), convention);
    ASSERT_TRUE(bytes);
    const Carried played = playTakesBothWays(*bytes);
    EXPECT_EQ(played.takes, prepared.scene->clips.size());
    EXPECT_GT(played.compared, 1000u);
    EXPECT_LT(played.worstDegrees, 1e-3) << played.worstWhere;
    EXPECT_LT(played.worstOffset, 1e-5) << played.worstWhere;
}

// A take that leaves a whole property out of a model it animates: the first
// take moves a joint's translation and ends away from the joint's own (an
// authored clip need not end at rest), the second only turns it. A reader
// carrying the first take's values would play the second take translated.
// With $RIGSMITH_CARRIED_TAKES_DIR set, the .glb and .fbx also go there for
// Blender (ctest Export.CarriedTakes.BlenderMidKeys).
TEST(FbxExport, ATakeRestoresThePropertiesOtherTakesMoveOnItsModels)
{
    const model::Rig rig = rigging::buildRig(test::loadGuide("Export/robot-rolling-arm/guide.yml"), test::builtinTemplates());
    io::ExportOptions options;
    options.rangeOfMotion = true;
    auto prepared = io::prepareExport(rig, options);
    ASSERT_TRUE(prepared.scene);
    io::ExportScene scene = std::move(*prepared.scene);
    ASSERT_GE(scene.clips.size(), 2u);
    scene.clips.resize(2);
    scene.clips[1] = scene.clips[0];
    scene.clips[1].name += "_turn";
    io::ExportTrack* moved = nullptr;
    for (std::size_t t = 0; t < scene.clips[0].tracks.size() && !moved; ++t) {
        io::ExportTrack& track = scene.clips[0].tracks[t];
        // A joint the range of motion already moves and turns (Blender leaves its bone unconnected).
        const unsigned both = io::kRotationChannel | io::kTranslationChannel;
        double travel = 0.0;
        for (const Vec3& t : track.translations)
            travel = std::max(travel, glm::length(t - track.translations.front()));
        if (track.controller || track.camera || (track.animated & both) != both || travel < 1e-2)
            continue;
        moved = &track;
        for (std::size_t k = 0; k < track.translations.size(); ++k) // drifts 0.1 m away by the end
            track.translations[k] += Vec3(0.0, 0.1 * double(k) / double(track.translations.size() - 1), 0.0);
        io::ExportTrack& turn = scene.clips[1].tracks[t];
        turn.animated = io::kRotationChannel;
        turn.held = 0;
    }
    ASSERT_NE(moved, nullptr);
    const io::Convention convention = io::conventionFor(io::ExportPreset::Gltf, true);
    const io::ExportScene fbxScene = io::converted(scene, convention);
    const auto bytes = io::fbxBytes(fbxScene, convention);
    ASSERT_TRUE(bytes);
    if (const char* dir = std::getenv("RIGSMITH_CARRIED_TAKES_DIR")) { // for Blender: ctest Export.CarriedTakes.BlenderMidKeys
        std::filesystem::create_directories(dir);
        ASSERT_TRUE(io::writeFbx(fbxScene, std::string(dir) + "/carried-takes.fbx", convention).empty());
        const io::ExportScene gltfScene = io::converted(scene, io::conventionFor(io::ExportPreset::Gltf, false));
        ASSERT_TRUE(io::writeGltf(gltfScene, std::string(dir) + "/carried-takes.glb", "test").empty());
    }
    const Carried played = playTakesBothWays(*bytes);
    EXPECT_EQ(played.takes, 2u);
    EXPECT_LT(played.worstDegrees, 1e-3) << played.worstWhere;
    EXPECT_LT(played.worstOffset, 1e-5) << played.worstWhere;
}
