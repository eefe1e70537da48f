#include "io/GltfExport.h"

#include "io/GuideFile.h"
#include "model/Skeleton.h"

#include <tiny_gltf.h>

#include <cstring>
#include <filesystem>
#include <sstream>

namespace rs::io {

namespace {

void appendFloats(std::vector<unsigned char>& bytes, const float* data, std::size_t count)
{
    const auto* raw = reinterpret_cast<const unsigned char*>(data);
    bytes.insert(bytes.end(), raw, raw + count * sizeof(float));
}

tinygltf::Node jointNode(const model::SkeletonJoint& joint)
{
    tinygltf::Node node;
    node.name = joint.name;
    Vec3 t, s;
    Quat r;
    decompose(joint.bindLocal, t, r, s);
    if (glm::length(t) > 0.0)
        node.translation = {t.x, t.y, t.z};
    if (std::abs(r.w) < 1.0 - 1e-15)
        node.rotation = {r.x, r.y, r.z, r.w};
    if (glm::length(s - Vec3(1.0)) > 1e-12)
        node.scale = {s.x, s.y, s.z};
    return node;
}

} // namespace

Diagnostics exportGltf(const model::Rig& rig, const std::string& path, const GltfExportOptions& options)
{
    auto skeleton = model::extractSkeleton(rig);
    if (!skeleton) {
        Diagnostics d = skeleton.takeDiagnostics();
        for (auto& item : d)
            item.where.file = path;
        return d;
    }
    if (options.names)
        *skeleton = applyNameMap(rig, skeleton.take(), *options.names);
    ExportCheck check = checkSkeleton(rig, *skeleton);
    if (options.fixNames && !check.renames.empty()) {
        *skeleton = applyRenames(skeleton.take(), check);
        check = checkSkeleton(rig, *skeleton);
    }
    Diagnostics report = check.problems;
    for (auto& item : report) {
        item.where.file = path;
        if (options.force && item.severity == Severity::Error) {
            item.severity = Severity::Warning;
            item.message = "exported anyway (forced): " + item.message;
        }
    }
    if (check.hasErrors() && !options.force)
        return report;
    const auto& joints = skeleton->joints;
    tinygltf::Model m;
    m.asset.version = "2.0";
    m.asset.generator = options.generator;

    for (const auto& joint : joints)
        m.nodes.push_back(jointNode(joint));
    for (std::size_t i = 0; i < joints.size(); ++i)
        if (joints[i].parent >= 0)
            m.nodes[std::size_t(joints[i].parent)].children.push_back(static_cast<int>(i));

    // Inverse bind matrices, column-major MAT4 float (no bufferView target).
    tinygltf::Buffer buffer;
    for (const auto& joint : joints) {
        const glm::mat4 ibm(glm::inverse(joint.bindWorld));
        appendFloats(buffer.data, &ibm[0][0], 16);
    }
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = 0;
    view.byteLength = buffer.data.size();
    m.bufferViews.push_back(view);
    tinygltf::Accessor ibms;
    ibms.bufferView = 0;
    ibms.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    ibms.type = TINYGLTF_TYPE_MAT4;
    ibms.count = joints.size();
    m.accessors.push_back(ibms);

    tinygltf::Skin skin;
    skin.name = rig.nodes.empty() ? "skeleton" : rig.nodes.front().name;
    skin.inverseBindMatrices = 0;
    skin.skeleton = 0;
    for (std::size_t i = 0; i < joints.size(); ++i)
        skin.joints.push_back(static_cast<int>(i));
    m.skins.push_back(skin);

    const bool binary = std::filesystem::path(path).extension() == ".glb";
    if (!binary)
        buffer.uri = std::filesystem::path(path).stem().string() + ".bin";
    m.buffers.push_back(buffer);

    tinygltf::Scene scene;
    scene.name = skin.name;
    scene.nodes.push_back(0);
    m.scenes.push_back(scene);
    m.defaultScene = 0;

    tinygltf::TinyGLTF writer;
    if (binary) {
        std::ostringstream stream;
        if (!writer.WriteGltfSceneToStream(&m, stream, false, true))
            return {makeError({path, 0, 0}, "glTF serialisation failed")};
        Diagnostics written = writeFileAtomically(path, stream.str());
        report.insert(report.end(), written.begin(), written.end());
        return report;
    }
    // Text glTF: tinygltf writes the JSON and the .bin named by buffers[0].uri.
    if (!writer.WriteGltfSceneToFile(&m, path, false, false, true, false))
        report.push_back(makeError({path, 0, 0}, "cannot write the glTF file or its .bin"));
    return report;
}

} // namespace rs::io
