#pragma once
// The keyed clip tests' fixture (KeyedClipTest, KeyedClipExportTest): the
// biped sample built once, its left arm keyed in FK at three poses (the
// shoulder and elbow at 0, 0.4 and 1 s), the export scene of such clips
// (optionally with the range of motion) and a clip of it by name.
#include "core/TestSupport.h"
#include "io/ClipFile.h"
#include "io/ExportScene.h"
#include "rigging/RigBuilder.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rs::test::keyed {

inline const model::GuideDocument& bipedGuide()
{
    static const model::GuideDocument guide = test::loadSample("biped");
    return guide;
}

inline const model::Rig& biped()
{
    static const model::Rig rig = rigging::buildRig(bipedGuide(), test::builtinTemplates());
    return rig;
}

// The left arm in FK: the shoulder and elbow keyed at 0, 0.4 and 1 s.
inline std::vector<io::KeyedClip> armWave()
{
    const model::Rig& rig = biped();
    const auto& shoulder = test::node(rig, "arm.L::ctrls.fk.0");
    const auto& elbow = test::node(rig, "arm.L::ctrls.fk.1");
    const auto& settings = test::node(rig, "arm.L::ctrls.switch");
    io::KeyedClip clip;
    clip.name = "wave";
    clip.times = {0.0, 0.4, 1.0};
    const double shoulderZ[3] = {0.0, 50.0, 10.0}, elbowZ[3] = {0.0, 40.0, 80.0};
    for (int k = 0; k < 3; ++k) {
        model::PoseValues pose;
        pose[settings.key]["ik_blend"] = 0.0;
        pose[shoulder.key]["rz"] = shoulderZ[k];
        pose[elbow.key]["rz"] = elbowZ[k];
        clip.poses.push_back(pose);
    }
    return {clip};
}

inline io::ExportScene keyedScene(const std::vector<io::KeyedClip>& clips, bool rangeOfMotion = false)
{
    io::ExportOptions options;
    options.keyedClips = &clips;
    options.rangeOfMotion = rangeOfMotion;
    auto prepared = io::prepareExport(biped(), options);
    EXPECT_TRUE(prepared.scene) << formatAll(prepared.report);
    return prepared.scene ? *prepared.scene : io::ExportScene{};
}

inline const io::ExportClip* clipNamed(const io::ExportScene& scene, const std::string& name)
{
    for (const auto& clip : scene.clips)
        if (clip.name == name)
            return &clip;
    return nullptr;
}

} // namespace rs::test::keyed
