#include "rigging/RigBuilder.h"
#include "core/TestSupport.h"
#include "io/RigExport.h"
#include "model/Skeleton.h"

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <filesystem>
#include <fstream>
#include <map>

using namespace rs;

namespace {

Mat4 nodeMatrix(const tinygltf::Node& n)
{
    Mat4 m(1.0);
    if (!n.translation.empty()) m = translationMatrix(Vec3(n.translation[0], n.translation[1], n.translation[2]));
    if (!n.rotation.empty()) m = m * glm::mat4_cast(Quat(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]));
    if (!n.scale.empty()) m = m * glm::scale(Mat4(1.0), Vec3(n.scale[0], n.scale[1], n.scale[2]));
    return m;
}

} // namespace

TEST(GltfExport, WritesOneSkeletonWithConsistentBindMatrices)
{
    const model::Rig rig = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    const std::string path = test::temporaryPath("biped.glb");
    ASSERT_TRUE(io::exportRig(rig, path).empty());

    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadBinaryFromFile(&m, &error, &warning, path)) << error;
    ASSERT_EQ(m.skins.size(), 1u);
    const auto& skin = m.skins[0];
    const auto skeleton = model::extractSkeleton(rig);
    ASSERT_EQ(skin.joints.size(), skeleton->joints.size());
    EXPECT_EQ(skin.skeleton, skin.joints[0]);
    ASSERT_EQ(m.scenes[0].nodes, std::vector<int>{skin.skeleton}) << "a single root";

    // World matrices from the node tree must invert the inverse bind matrices.
    std::map<int, Mat4> world;
    std::map<int, int> parent;
    for (int i = 0; i < int(m.nodes.size()); ++i)
        for (int c : m.nodes[std::size_t(i)].children) parent[c] = i;
    const auto& view = m.bufferViews[std::size_t(m.accessors[std::size_t(skin.inverseBindMatrices)].bufferView)];
    const float* ibm = reinterpret_cast<const float*>(m.buffers[0].data.data() + view.byteOffset);
    for (std::size_t k = 0; k < skin.joints.size(); ++k) {
        const int j = skin.joints[k];
        world[j] = (parent.count(j) ? world[parent[j]] : Mat4(1.0)) * nodeMatrix(m.nodes[std::size_t(j)]);
        EXPECT_EQ(m.nodes[std::size_t(j)].name, skeleton->joints[k].name);
        const Mat4 inverseBind(glm::make_mat4(ibm + 16 * k));
        EXPECT_LT(maxAbsDifference(world[j] * inverseBind, Mat4(1.0)), 1e-5) << m.nodes[std::size_t(j)].name;
        EXPECT_LT(glm::length(translationOf(world[j]) - translationOf(skeleton->joints[k].bindWorld)), 1e-9);
    }
}

TEST(GltfExport, RefusesASkeletonWithSeveralRootsAndWritesNothing)
{
    model::GuideDocument guide = test::loadSample("biped");
    guide.takeInstance(guide.instanceNamed("world")->id);
    for (const char* n : {"spine"})
        guide.instance(guide.instanceNamed(n)->id)->parent = 0, guide.instance(guide.instanceNamed(n)->id)->parentJoint = 0;
    model::TemplateInstance loose = *guide.instanceNamed("neck");
    guide.takeInstance(loose.id);
    loose.parent = loose.parentJoint = 0;
    guide.insertInstance(loose, guide.instances().size());
    const model::Rig rig = rigging::buildRig(guide, test::builtinTemplates());
    const std::string path = test::temporaryPath("roots.glb");
    std::filesystem::remove(path);
    const auto d = io::exportRig(rig, path);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].format(), path + ": error: the skin hierarchy has 2 roots, an export skeleton needs one: "
                                    "sk_spine_hips (spine::skin.0), sk_neck1 (neck::skin.0)");
    EXPECT_FALSE(std::filesystem::exists(path));
}

// Issue 18 item 2: the .gltf + .bin pair is written whole or not at all.
TEST(GltfExport, ATextGltfOnAFullDiskFailsAndKeepsThePreviousPair)
{
    const model::Rig rig = rigging::buildRig(test::loadSample("biped"), test::builtinTemplates());
    const std::filesystem::path folder = test::temporaryPath("gltf-full");
    std::filesystem::remove_all(folder);
    std::filesystem::create_directories(folder);
    const std::string gltf = (folder / "rig.gltf").string(), bin = (folder / "rig.bin").string();
    ASSERT_TRUE(io::exportRig(rig, gltf).empty());
    tinygltf::Model m;
    tinygltf::TinyGLTF loader;
    std::string error, warning;
    ASSERT_TRUE(loader.LoadASCIIFromFile(&m, &error, &warning, gltf)) << error;
    ASSERT_EQ(m.buffers.size(), 1u);
    EXPECT_EQ(m.buffers[0].uri, "rig.bin");
    EXPECT_EQ(m.buffers[0].data.size(), std::filesystem::file_size(bin));
    EXPECT_EQ(m.skins.size(), 1u);

    // Room for the smaller of the two files, not the larger.
    const std::size_t limit = (std::filesystem::file_size(gltf) + std::filesystem::file_size(bin)) / 2;
    std::ofstream(gltf, std::ios::binary) << "previous gltf\n";
    std::ofstream(bin, std::ios::binary) << "previous bin\n";
    const bool reported = test::runWithFileSizeLimit(limit, [&] { return hasErrors(io::exportRig(rig, gltf)); });
    EXPECT_TRUE(reported) << "the write error is reported";
    EXPECT_EQ(test::readText(gltf), "previous gltf\n");
    EXPECT_EQ(test::readText(bin), "previous bin\n");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(folder), std::filesystem::directory_iterator()), 2)
        << "no temp file is left behind";
}
