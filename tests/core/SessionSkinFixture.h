#pragma once
// The core session with a character for tests: the biped sample built, a
// fake model loader serving a sleeve tube along the left arm (kArm), and a
// bind through skin::bindModels as one undo step.
#include "TestSupport.h"

#include "session/Session.h"
#include "skin/BindModels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace rs::test::sessionskin {

inline const std::string kArm = "/virtual/models/arm.obj";

// A tube of radius 4 cm around the segment a-b: `rings` rings of 12 vertices.
inline model::Mesh tube(const std::string& name, Vec3 a, Vec3 b, int rings)
{
    model::Mesh mesh;
    mesh.name = name;
    const Vec3 axis = glm::normalize(b - a);
    const Vec3 side = glm::normalize(glm::cross(axis, std::abs(axis.y) < 0.9 ? Vec3(0, 1, 0) : Vec3(1, 0, 0)));
    const Vec3 up = glm::cross(axis, side);
    constexpr int kSides = 12;
    for (int r = 0; r < rings; ++r) {
        const Vec3 centre = a + (b - a) * (double(r) / (rings - 1));
        for (int s = 0; s < kSides; ++s) {
            const double t = 2.0 * 3.14159265358979 * s / kSides;
            mesh.positions.emplace_back(centre + 0.04 * (std::cos(t) * side + std::sin(t) * up));
        }
    }
    for (int r = 0; r + 1 < rings; ++r)
        for (int s = 0; s < kSides; ++s) {
            const std::uint32_t i = r * kSides + s, j = r * kSides + (s + 1) % kSides;
            mesh.indices.insert(mesh.indices.end(), {i, j, i + kSides, j, j + kSides, i + kSides});
        }
    return mesh;
}

struct FakeFiles {
    std::map<std::string, model::Model> files;
    int reads = 0;
    session::Session::ModelLoader loader()
    {
        return [this](const std::string& path) {
            ++reads;
            auto it = files.find(path);
            if (it == files.end())
                return Result<model::Model>::failure(makeError({path, 0, 0}, "no such file"));
            return Result<model::Model>(it->second);
        };
    }
};

struct Fixture {
    session::Session s{std::make_shared<templates::TemplateRegistry>(test::builtinTemplates())};
    FakeFiles files;
    Diagnostics reported;
    Fixture()
    {
        s.replaceDocument(test::loadSample("biped"));
        s.setModelLoader(files.loader());
        s.setReporter([this](const Diagnostics& d) { reported.insert(reported.end(), d.begin(), d.end()); });
        s.build();
        const Vec3 shoulder = translationOf(s.rig()->nodes[*s.rig()->findPath("arm.L::skin.limb.0")].worldMatrix);
        const Vec3 wrist = translationOf(s.rig()->nodes[*s.rig()->findPath("arm.L::skin.limb.2")].worldMatrix);
        model::Model arm;
        arm.meshes.push_back(tube("sleeve", shoulder, wrist, 16));
        files.files[kArm] = arm;
    }
    bool saidSomething(const std::string& text) const
    {
        return std::any_of(reported.begin(), reported.end(), [&](const Diagnostic& d) { return d.message.find(text) != std::string::npos; });
    }
    void bind()
    {
        std::vector<skin::ModelToBind> models;
        for (const auto& m : s.models())
            models.push_back({m.path, m.model});
        auto bound = skin::bindModels(models, s.skinBones(), {});
        ASSERT_TRUE(bound.ok());
        ASSERT_TRUE(test::succeeded(s.setBindings(bound.take(), "Bind skin")));
    }
};

inline std::size_t boneOf(const session::Session& s, const std::string& path)
{
    const auto node = *s.rig()->findPath(path);
    for (std::size_t b = 0; b < s.skinBones().size(); ++b)
        if (s.skinBones()[b].node == node)
            return b;
    ADD_FAILURE() << path << " is not a skin bone";
    return 0;
}

} // namespace rs::test::sessionskin
