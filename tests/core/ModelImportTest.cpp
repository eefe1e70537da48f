// Character models (io/ModelImport.h) and their place in the guide (`models:`,
// relative to the guide file).
#include "TestSupport.h"

#include "io/GuideFile.h"
#include "io/ModelImport.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using namespace rs;

namespace {
const std::string kModels = "/usr/share/assimp/models";
}

TEST(ModelImport, TheHumanKeepsItsMeshesNamesAndVertexOrder)
{
    auto human = io::importModel(kModels + "/Collada/human.zae");
    ASSERT_TRUE(human.ok()) << formatAll(human.diagnostics()) << " (run.sh installs assimp-testmodels)";
    ASSERT_EQ(human->meshes.size(), 2u);
    EXPECT_EQ(human->meshes[0].name, "human-baseMesh");
    EXPECT_EQ(human->meshes[0].vertexCount(), 53512u);
    EXPECT_EQ(human->meshes[1].name, "human-highpolyeyesMesh");
    EXPECT_EQ(human->meshes[1].normals.size(), human->meshes[1].vertexCount());
    // Stable: a second import gives the same vertices in the same order.
    auto again = io::importModel(kModels + "/Collada/human.zae");
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(again->meshes[0].positions, human->meshes[0].positions);
    EXPECT_EQ(model::topologyFingerprint(again->meshes[0]), model::topologyFingerprint(human->meshes[0]));
    // Metres, Y-up: about 1.66 m tall, standing on the ground.
    float top = -1e9f, bottom = 1e9f;
    for (const auto& p : human->meshes[0].positions) {
        top = std::max(top, p.y);
        bottom = std::min(bottom, p.y);
    }
    EXPECT_NEAR(top - bottom, 1.66f, 0.02f);
    // The eyes' texture is inside the .zae: the material carries its bytes for the viewport.
    const int eyes = human->meshes[1].material;
    ASSERT_GE(eyes, 0);
    const auto& image = human->materials[std::size_t(eyes)].image;
    ASSERT_TRUE(image) << "texture '" << human->materials[std::size_t(eyes)].texture << "' not found embedded";
    const bool png = image->rfind("\x89PNG", 0) == 0, jpeg = image->rfind("\xFF\xD8", 0) == 0;
    EXPECT_TRUE(png || jpeg) << "encoded image bytes";
}

TEST(ModelImport, ABlenderFileIsTurnedFromZUpToYUp)
{
    auto human = io::importModel(kModels + "/BLEND/HUMAN.blend");
    ASSERT_TRUE(human.ok()) << formatAll(human.diagnostics());
    EXPECT_TRUE(human->zUp);
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (const auto& mesh : human->meshes)
        for (const auto& p : mesh.positions) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    EXPECT_GT(hi.y - lo.y, 2.0f * (hi.z - lo.z)) << "standing: taller (Y) than deep (Z)";
}

TEST(ModelImport, MissingAndTriangleLessFilesAreErrorsNamingTheFile)
{
    auto missing = io::importModel("/nonexistent/body.fbx");
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(formatAll(missing.diagnostics()).find("/nonexistent/body.fbx: error: no such file"), std::string::npos);
    const std::string lines = test::temporaryPath("lines.obj");
    std::ofstream(lines) << "v 0 0 0\nv 1 0 0\nl 1 2\n";
    auto none = io::importModel(lines);
    ASSERT_FALSE(none.ok());
    EXPECT_NE(formatAll(none.diagnostics()).find("no triangles"), std::string::npos);
}

TEST(ModelImport, TheGuideKeepsItsModelsRelativeToItself)
{
    const std::filesystem::path folder = test::temporaryPath("models-guide");
    std::filesystem::create_directories(folder / "meshes");
    std::ofstream(folder / "meshes" / "body.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    model::GuideDocument guide;
    guide.name = "character";
    guide.models = {(folder / "meshes" / "body.obj").string()};
    const std::string path = (folder / "character.yml").string();
    ASSERT_TRUE(io::saveGuideFile(guide, path).ok());
    const std::string text = test::readText(path);
    EXPECT_NE(text.find("models:\n  - meshes/body.obj\n"), std::string::npos) << text;
    auto read = io::readGuideFile(path);
    ASSERT_TRUE(read.ok()) << formatAll(read.diagnostics());
    EXPECT_EQ(read->models, guide.models) << "absolute again in memory";
    // An empty entry is an error at its line.
    std::ofstream(path) << "rigsmith_guide: 2\nmodels:\n  - ''\ninstances: []\n";
    auto bad = io::readGuideFile(path);
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(formatAll(bad.diagnostics()).find(":3:"), std::string::npos) << formatAll(bad.diagnostics());
}
