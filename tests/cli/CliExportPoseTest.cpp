// Issue 21 item 2's double pose: `build --posed --current-pose` rebuilt the
// rig in the guide's test pose and then put that pose on its nodes again.
// The nodes must carry the pose once: as `--current-pose` alone puts it.
#include "CliSupport.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <filesystem>
#include <fstream>
#include <map>

namespace fs = std::filesystem;
using rs::clitest::freshFolder;
using rs::clitest::readText;
using rs::clitest::runCli;

namespace {

// The biped with a test pose: the spine's cog turned, the left arm in FK and bent, a leg's IK goal moved.
fs::path posedBiped(const fs::path& folder)
{
    const fs::path guide = folder / "posed.yml";
    std::ofstream out(guide);
    out << readText(RIGSMITH_SOURCE_DIR "/resources/samples/biped.yml")
        << "pose:\n"
           "  - {instance: 2, node: ctrls.cog, values: {ry: 25, tx: 0.05}}\n"
           "  - {instance: 4, branch: L, node: ctrls.switch, values: {ik_blend: 0}}\n"
           "  - {instance: 4, branch: L, node: ctrls.fk.1, values: {rz: 45}}\n"
           "  - {instance: 5, branch: R, node: ctrls.ik, values: {ty: 0.2, tz: 0.1}}\n";
    return guide;
}

struct Trs {
    glm::dvec3 t{0.0}, s{1.0};
    glm::dquat r{1.0, 0.0, 0.0, 0.0};
};

std::map<std::string, Trs> nodeTransforms(const fs::path& glb)
{
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    EXPECT_TRUE(loader.LoadBinaryFromFile(&m, &error, &warning, glb.string())) << error;
    std::map<std::string, Trs> out;
    for (const auto& n : m.nodes) {
        Trs trs;
        if (n.translation.size() == 3)
            trs.t = {n.translation[0], n.translation[1], n.translation[2]};
        if (n.rotation.size() == 4)
            trs.r = glm::dquat(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]);
        if (n.scale.size() == 3)
            trs.s = {n.scale[0], n.scale[1], n.scale[2]};
        out[n.name] = trs;
    }
    return out;
}

} // namespace

TEST(Cli, PosedWithCurrentPoseCarriesThePoseOnce)
{
    const fs::path folder = freshFolder("double-pose");
    const fs::path guide = posedBiped(folder);
    const fs::path once = folder / "current-pose.glb", both = folder / "posed-current-pose.glb", rest = folder / "rest.glb";
    const auto a = runCli({"build", guide.string(), "--current-pose", "-o", once.string(), "--no-meshes"}, folder);
    ASSERT_EQ(a.exitCode, 0) << a.errors;
    const auto b = runCli({"build", guide.string(), "--posed", "--current-pose", "-o", both.string(), "--no-meshes"}, folder);
    ASSERT_EQ(b.exitCode, 0) << b.errors;
    const auto c = runCli({"build", guide.string(), "-o", rest.string(), "--no-meshes"}, folder);
    ASSERT_EQ(c.exitCode, 0) << c.errors;

    const auto expected = nodeTransforms(once), actual = nodeTransforms(both), unposed = nodeTransforms(rest);
    ASSERT_EQ(expected.size(), actual.size());
    double worstMetres = 0.0, worstRotation = 0.0, posedBy = 0.0;
    for (const auto& [name, e] : expected) {
        ASSERT_TRUE(actual.count(name)) << name;
        const Trs& x = actual.at(name);
        worstMetres = std::max({worstMetres, glm::length(x.t - e.t), glm::length(x.s - e.s)});
        worstRotation = std::max(worstRotation, 1.0 - std::abs(glm::dot(x.r, e.r)));
        posedBy = std::max(posedBy, glm::length(unposed.at(name).t - e.t) + (1.0 - std::abs(glm::dot(unposed.at(name).r, e.r))));
    }
    EXPECT_GT(posedBy, 1e-2) << "the test pose moves the nodes";
    EXPECT_LT(worstMetres, 1e-5);
    EXPECT_LT(worstRotation, 1e-9);
}
