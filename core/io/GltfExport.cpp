#include "io/GltfExport.h"

#include "io/AtomicFile.h"
#include "io/GltfParts.h"

#include <nlohmann/json.hpp>

#include <tiny_gltf.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <filesystem>
#include <sstream>

namespace rs::io {

namespace {

using gltf::addMaterials;
using gltf::addMesh;
using gltf::GltfBuilder;

// Two animation values this close are one held value (below float resolution near 1: lossless).
constexpr float kSameKey = 1e-7f;

void setTrs(tinygltf::Node& node, const Mat4& local)
{
    Vec3 t, s;
    Quat r;
    decompose(local, t, r, s);
    if (glm::length(t) > 0.0)
        node.translation = {t.x, t.y, t.z};
    if (std::abs(r.w) < 1.0 - 1e-15)
        node.rotation = {r.x, r.y, r.z, r.w};
    if (glm::length(s - Vec3(1.0)) > 1e-12)
        node.scale = {s.x, s.y, s.z};
}

tinygltf::Value controllerExtras(const ExportController& c)
{
    tinygltf::Value::Object rig{{"kind", tinygltf::Value(std::string("controller"))},
                                {"id", tinygltf::Value(c.id)}};
    if (!c.shape.empty())
        rig["shape"] = tinygltf::Value(c.shape);
    if (!c.defaults.empty()) { // cleanup's record: what reset returns to
        tinygltf::Value::Object defaults;
        for (const auto& [channel, value] : c.defaults)
            defaults[channel] = tinygltf::Value(value);
        rig["defaults"] = tinygltf::Value(defaults);
    }
    if (!c.attributes.empty()) {
        tinygltf::Value::Object attributes;
        for (const auto& a : c.attributes) {
            tinygltf::Value::Object o{{"value", tinygltf::Value(a.value)},
                                      {"min", tinygltf::Value(a.min)},
                                      {"max", tinygltf::Value(a.max)}};
            if (!a.labels.empty()) {
                tinygltf::Value::Array labels;
                for (const auto& label : a.labels)
                    labels.push_back(tinygltf::Value(label));
                o["labels"] = tinygltf::Value(labels);
            }
            attributes[a.name] = tinygltf::Value(o);
        }
        rig["attributes"] = tinygltf::Value(attributes);
    }
    return tinygltf::Value(tinygltf::Value::Object{{"rig", tinygltf::Value(rig)}});
}

// The keys of an animated channel worth writing: the first, the last, and
// every key where the value changes before or after it (a key inside a run of
// equal values is what linear interpolation gives anyway).
std::vector<std::size_t> keptKeys(const std::vector<float>& values, std::size_t width)
{
    const std::size_t count = values.size() / width;
    auto same = [&](std::size_t a, std::size_t b) {
        for (std::size_t i = 0; i < width; ++i)
            if (std::abs(values[a * width + i] - values[b * width + i]) > kSameKey)
                return false;
        return true;
    };
    std::vector<std::size_t> kept;
    for (std::size_t k = 0; k < count; ++k)
        if (k == 0 || k + 1 == count || !same(k - 1, k) || !same(k, k + 1))
            kept.push_back(k);
    return kept;
}

// A camera node at the scene root: glTF's cameras look down their -Z with +Y
// up, as the rig's camera frame does, so the node takes the frame as it is.
// yfov from the lens across the film's height; the lens in extras (glTF core
// has no focal length, and cannot animate a camera's yfov).
int addCamera(tinygltf::Model& m, const ExportCamera& source, Diagnostics& report)
{
    tinygltf::Camera camera;
    camera.name = source.name;
    double zfar = source.farClip;
    if (!(source.farClip > source.nearClip)) { // glTF needs zfar > znear (tinygltf always writes zfar)
        zfar = 1000.0 * source.nearClip;
        report.push_back(makeWarning({}, "camera '" + source.name + "': its far clip (" + std::to_string(source.farClip) +
                                             ") is not beyond its near clip (" + std::to_string(source.nearClip) +
                                             "); the glTF's far plane is 1000 times the near clip"));
    }
    if (source.orthographic) { // half the width and height it sees, the film's aspect
        camera.type = "orthographic";
        camera.orthographic.xmag = 0.5 * source.orthoWidth;
        camera.orthographic.ymag = 0.5 * source.orthoWidth * source.filmHeight / source.filmWidth;
        camera.orthographic.znear = source.nearClip;
        camera.orthographic.zfar = zfar;
    } else {
        camera.type = "perspective";
        camera.perspective.aspectRatio = source.filmWidth / source.filmHeight;
        camera.perspective.yfov = verticalFieldOfView(source, source.focalLength);
        camera.perspective.znear = source.nearClip;
        camera.perspective.zfar = zfar;
    }
    m.cameras.push_back(camera);
    tinygltf::Node node;
    node.name = source.name;
    node.camera = int(m.cameras.size() - 1);
    setTrs(node, source.poseWorld);
    node.extras = tinygltf::Value(tinygltf::Value::Object{
        {"rig", tinygltf::Value(tinygltf::Value::Object{{"kind", tinygltf::Value(std::string("camera"))},
                                                        {"id", tinygltf::Value(source.id)},
                                                        {"focal_length", tinygltf::Value(source.focalLength)},
                                                        {"film_width", tinygltf::Value(source.filmWidth)},
                                                        {"film_height", tinygltf::Value(source.filmHeight)}})}});
    m.nodes.push_back(node);
    return int(m.nodes.size() - 1);
}

void addClip(tinygltf::Model& m, GltfBuilder& b, const ExportClip& clip, int firstController, int firstCamera)
{
    tinygltf::Animation animation;
    animation.name = clip.name;
    const std::vector<float> times(clip.times.begin(), clip.times.end());
    std::map<std::vector<std::size_t>, int> inputs; // one time accessor per set of kept keys
    // `slopes`: a cubic channel's slopes per key (every key kept, CUBICSPLINE:
    // in-tangent, value, out-tangent per key; the slopes are per second, the
    // player scales them by the key interval).
    auto channel = [&](int node, const char* path, const std::vector<float>& values, int type, std::size_t width,
                       bool held, const std::vector<float>* slopes) {
        std::vector<std::size_t> kept;
        if (held)
            kept = {0};
        else if (slopes)
            for (std::size_t k = 0; k < values.size() / width; ++k)
                kept.push_back(k);
        else
            kept = keptKeys(values, width);
        auto input = inputs.find(kept);
        if (input == inputs.end()) {
            std::vector<float> keptTimes;
            for (std::size_t k : kept)
                keptTimes.push_back(times[k]);
            input = inputs.emplace(kept, b.bounded(keptTimes, TINYGLTF_TYPE_SCALAR, 1)).first;
        }
        std::vector<float> keptValues;
        auto append = [&](const std::vector<float>& from, std::size_t k) {
            keptValues.insert(keptValues.end(), from.begin() + std::ptrdiff_t(k * width),
                              from.begin() + std::ptrdiff_t((k + 1) * width));
        };
        for (std::size_t k : kept) {
            if (slopes)
                append(*slopes, k);
            append(values, k);
            if (slopes)
                append(*slopes, k);
        }
        tinygltf::AnimationSampler sampler;
        sampler.input = input->second;
        sampler.interpolation = slopes ? "CUBICSPLINE" : "LINEAR";
        sampler.output = b.accessor(keptValues, TINYGLTF_COMPONENT_TYPE_FLOAT, type, kept.size() * (slopes ? 3 : 1));
        animation.samplers.push_back(sampler);
        tinygltf::AnimationChannel c;
        c.sampler = int(animation.samplers.size() - 1);
        c.target_node = node;
        c.target_path = path;
        animation.channels.push_back(c);
    };
    for (const auto& track : clip.tracks) {
        const int node = track.camera ? firstCamera + track.node : track.controller ? firstController + track.node : track.node;
        auto vec3s = [](const std::vector<Vec3>& from) {
            std::vector<float> out;
            for (const Vec3& v : from)
                out.insert(out.end(), {float(v.x), float(v.y), float(v.z)});
            return out;
        };
        auto quats = [](const std::vector<Quat>& from) {
            std::vector<float> out;
            for (const Quat& q : from)
                out.insert(out.end(), {float(q.x), float(q.y), float(q.z), float(q.w)});
            return out;
        };
        // Animated channels get every key (cubic ones with their slopes), held
        // ones their first, constant ones nothing.
        auto write = [&](unsigned bit, const char* path, const std::vector<float>& values, const std::vector<float>& slopes,
                         int type, std::size_t width) {
            const bool cubic = (track.cubic & bit) && slopes.size() == values.size();
            if (track.animated & bit)
                channel(node, path, values, type, width, false, cubic ? &slopes : nullptr);
            else if (track.held & bit)
                channel(node, path, values, type, width, true, nullptr);
        };
        write(kTranslationChannel, "translation", vec3s(track.translations), vec3s(track.translationSlopes), TINYGLTF_TYPE_VEC3, 3);
        write(kRotationChannel, "rotation", quats(track.rotations), quats(track.rotationSlopes), TINYGLTF_TYPE_VEC4, 4);
        write(kScaleChannel, "scale", vec3s(track.scales), vec3s(track.scaleSlopes), TINYGLTF_TYPE_VEC3, 3);
    }
    // The clip's frame rate and named ranges, for tools that read extras.
    tinygltf::Value::Array markers;
    for (const auto& marker : clip.markers) {
        tinygltf::Value::Object o;
        o["name"] = tinygltf::Value(marker.name);
        o["control"] = tinygltf::Value(marker.control);
        o["start"] = tinygltf::Value(marker.start);
        o["end"] = tinygltf::Value(marker.end);
        markers.push_back(tinygltf::Value(o));
    }
    tinygltf::Value::Object extras;
    if (clip.framesPerSecond > 0.0)
        extras["fps"] = tinygltf::Value(clip.framesPerSecond);
    if (!markers.empty())
        extras["markers"] = tinygltf::Value(markers);
    if (!extras.empty())
        animation.extras = tinygltf::Value(extras);
    if (!animation.channels.empty())
        m.animations.push_back(animation);
}

tinygltf::Model buildModel(const ExportScene& scene, const std::string& generator, Diagnostics& report)
{
    tinygltf::Model m;
    m.asset.version = "2.0";
    m.asset.generator = generator;
    GltfBuilder b(m);
    tinygltf::Scene root;
    root.name = scene.name;

    for (const auto& joint : scene.joints) {
        tinygltf::Node node;
        node.name = joint.name;
        setTrs(node, joint.poseLocal);
        m.nodes.push_back(node);
    }
    for (std::size_t i = 0; i < scene.joints.size(); ++i)
        if (scene.joints[i].parent >= 0)
            m.nodes[std::size_t(scene.joints[i].parent)].children.push_back(int(i));
    root.nodes.push_back(0);

    const int firstController = int(m.nodes.size());
    for (const auto& c : scene.controllers) {
        tinygltf::Node node;
        node.name = c.name;
        setTrs(node, c.poseLocal);
        node.extras = controllerExtras(c);
        m.nodes.push_back(node);
    }
    for (std::size_t i = 0; i < scene.controllers.size(); ++i) {
        const int parent = scene.controllers[i].parent;
        (parent < 0 ? root.nodes : m.nodes[std::size_t(firstController + parent)].children).push_back(firstController + int(i));
    }

    const int firstCamera = int(m.nodes.size());
    for (const auto& camera : scene.cameras)
        root.nodes.push_back(addCamera(m, camera, report));

    // Inverse bind matrices, column-major MAT4 float (no bufferView target).
    std::vector<float> ibms;
    for (const auto& joint : scene.joints) {
        const glm::mat4 ibm(glm::inverse(joint.bindWorld));
        ibms.insert(ibms.end(), &ibm[0][0], &ibm[0][0] + 16);
    }
    tinygltf::Skin skin;
    skin.name = scene.name;
    skin.inverseBindMatrices = b.accessor(ibms, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_MAT4, scene.joints.size());
    skin.skeleton = 0;
    for (std::size_t i = 0; i < scene.joints.size(); ++i)
        skin.joints.push_back(int(i));
    m.skins.push_back(skin);

    addMaterials(m, b, scene, report);
    for (const auto& mesh : scene.meshes) {
        tinygltf::Node node;
        node.name = mesh.name;
        node.mesh = addMesh(m, b, mesh, scene.joints.size());
        node.skin = 0;
        m.nodes.push_back(node);
        root.nodes.push_back(int(m.nodes.size() - 1));
    }
    for (const auto& clip : scene.clips)
        addClip(m, b, clip, firstController, firstCamera);
    m.scenes.push_back(root);
    m.defaultScene = 0;
    return m;
}

} // namespace

Diagnostics writeGltf(const ExportScene& scene, const std::string& path, const std::string& generator)
{
    Diagnostics report;
    tinygltf::Model m = buildModel(scene, generator, report);
    for (auto& d : report)
        d.where.file = path;
    tinygltf::TinyGLTF writer;
    std::ostringstream stream;
    auto withReport = [&](Diagnostics written) {
        report.insert(report.end(), written.begin(), written.end());
        return report;
    };
    if (std::filesystem::path(path).extension() == ".glb") {
        if (!writer.WriteGltfSceneToStream(&m, stream, false, true))
            return withReport({makeError({path, 0, 0}, "glTF serialisation failed")});
        return withReport(writeFileAtomically(path, stream.str()).takeDiagnostics());
    }
    // Text glTF: the JSON names the .bin beside it. tinygltf would write both
    // itself, unchecked and in place, so both are made in memory here (the
    // buffer taken out first, so it is not base64-encoded into the JSON) and
    // written together: neither replaces its file unless both were written.
    const std::filesystem::path gltfPath(path);
    const std::string binName = gltfPath.stem().string() + ".bin";
    const std::vector<unsigned char> bin = std::move(m.buffers[0].data);
    m.buffers[0].data.clear();
    if (!writer.WriteGltfSceneToStream(&m, stream, true, false))
        return withReport({makeError({path, 0, 0}, "glTF serialisation failed")});
    nlohmann::json json = nlohmann::json::parse(stream.str(), nullptr, false);
    if (json.is_discarded() || !json.contains("buffers"))
        return withReport({makeError({path, 0, 0}, "glTF serialisation failed")});
    json["buffers"][0]["uri"] = binName;
    json["buffers"][0]["byteLength"] = bin.size();
    const std::string text = json.dump(2);
    const std::string_view binBytes(reinterpret_cast<const char*>(bin.data()), bin.size());
    return withReport(writeFilesAtomically({{path, text}, {(gltfPath.parent_path() / binName).string(), binBytes}}).takeDiagnostics());
}

} // namespace rs::io
