// The FBX objects of an export scene: models, attributes, meshes, skins,
// materials, textures and the bind pose (see io/FbxExport.h for the choices).
#include "io/FbxAnimation.h"
#include "io/FbxDocument.h"

#include <cmath>
#include <set>

namespace rs::io::fbx {

namespace {

constexpr std::int32_t kModelVersion = 232;

// A model's transform properties: the node's local transform as FBX's
// Lcl Translation / Lcl Rotation (XYZ Euler, degrees) / Lcl Scaling, parent
// scale inherited as plain matrix products (InheritType 1, eInheritRSrs).
void addTransform(Node& p70, const Mat4& local)
{
    Vec3 t, s;
    Quat r;
    decompose(local, t, r, s);
    propertyInt(p70, "InheritType", "enum", 1);
    propertyInt(p70, "DefaultAttributeIndex", "int", 0);
    propertyVector(p70, "Lcl Translation", "Lcl Translation", t);
    propertyVector(p70, "Lcl Rotation", "Lcl Rotation", eulerXyzDegrees(r));
    propertyVector(p70, "Lcl Scaling", "Lcl Scaling", s);
}

std::int64_t addModel(Document& doc, const std::string& name, const std::string& type, const Mat4& local,
                      Node** properties = nullptr)
{
    const std::int64_t id = doc.newId();
    Node& model = doc.addObject("Model", id, name, "Model", type);
    model.child("Version").addInt32(kModelVersion);
    Node& p70 = model.child("Properties70");
    addTransform(p70, local);
    if (properties)
        *properties = &p70;
    model.child("Shading").addBool(true);
    model.child("Culling").addString("CullingOff");
    return id;
}

// A LimbNode or Null attribute for `model`: what makes importers see a bone or an empty.
void addAttribute(Document& doc, std::int64_t model, const std::string& name, bool limb)
{
    const std::int64_t id = doc.newId();
    Node& attribute = doc.addObject("NodeAttribute", id, name, "NodeAttribute", limb ? "LimbNode" : "Null");
    if (limb)
        propertyDouble(attribute.child("Properties70"), "Size", 1.0);
    attribute.child("TypeFlags").addString(limb ? "Skeleton" : "Null");
    doc.connect(id, model);
}

void addGeometry(Document& doc, std::int64_t id, const SkinnedMesh& mesh, bool hasMaterial)
{
    Node& geometry = doc.addObject("Geometry", id, mesh.name, "Geometry", "Mesh");
    geometry.child("GeometryVersion").addInt32(124);
    std::vector<double> values;
    values.reserve(3 * mesh.vertexCount());
    for (const auto& p : mesh.positions)
        values.insert(values.end(), {double(p.x), double(p.y), double(p.z)});
    geometry.child("Vertices").addDoubles(values);
    // Polygon vertex indices: each polygon's last index is stored as -(index + 1).
    std::vector<std::int32_t> polygons(mesh.indices.begin(), mesh.indices.end());
    for (std::size_t i = 2; i < polygons.size(); i += 3)
        polygons[i] = -polygons[i] - 1;
    geometry.child("PolygonVertexIndex").addInt32s(polygons);

    Node layer("Layer");
    layer.addInt32(0);
    layer.child("Version").addInt32(100);
    auto addElement = [&](const char* kind, const char* mapping, const char* reference) -> Node& {
        Node& element = geometry.child(kind);
        element.addInt32(0);
        element.child("Version").addInt32(101);
        element.child("Name").addString(std::string(kind) == "LayerElementUV" ? "UVMap" : "");
        element.child("MappingInformationType").addString(mapping);
        element.child("ReferenceInformationType").addString(reference);
        Node& entry = layer.child("LayerElement");
        entry.child("Type").addString(kind);
        entry.child("TypedIndex").addInt32(0);
        return element;
    };
    if (!mesh.normals.empty()) {
        values.clear();
        for (const auto& n : mesh.normals)
            values.insert(values.end(), {double(n.x), double(n.y), double(n.z)});
        addElement("LayerElementNormal", "ByVertice", "Direct").child("Normals").addDoubles(values);
    }
    if (!mesh.uvs.empty()) { // one UV per vertex, indexed per polygon vertex
        values.clear();
        for (const auto& uv : mesh.uvs)
            values.insert(values.end(), {double(uv.x), double(uv.y)});
        Node& uv = addElement("LayerElementUV", "ByPolygonVertex", "IndexToDirect");
        uv.child("UV").addDoubles(values);
        const std::vector<std::int32_t> uvIndex(mesh.indices.begin(), mesh.indices.end());
        uv.child("UVIndex").addInt32s(uvIndex);
    }
    if (hasMaterial) {
        const std::int32_t first = 0;
        addElement("LayerElementMaterial", "AllSame", "IndexToDirect").child("Materials").addInt32s({&first, 1});
    }
    geometry.append(std::move(layer));
}

// A Skin deformer on the geometry with one Cluster per joint that weighs any
// vertex: its vertex indexes and weights, Transform = the mesh's bind world
// relative to the joint's (meshes sit at the origin: inverse(joint bind world)),
// TransformLink = the joint's bind world.
void addSkin(Document& doc, std::int64_t geometry, const SkinnedMesh& mesh, const ExportScene& scene,
             const std::vector<std::int64_t>& jointModels)
{
    std::vector<std::vector<std::int32_t>> indexes(scene.joints.size());
    std::vector<std::vector<double>> weights(scene.joints.size());
    for (std::size_t v = 0; v < mesh.vertexCount(); ++v)
        for (std::size_t k = 0; k < mesh.influenceCount(v); ++k) {
            const Influence& in = mesh.influencesOf(v)[k];
            indexes[std::size_t(in.joint)].push_back(std::int32_t(v));
            weights[std::size_t(in.joint)].push_back(double(in.weight));
        }
    const std::int64_t skin = doc.newId();
    Node& skinNode = doc.addObject("Deformer", skin, mesh.name, "Deformer", "Skin");
    skinNode.child("Version").addInt32(101);
    skinNode.child("Link_DeformAcuracy").addDouble(50.0);
    doc.connect(skin, geometry);
    for (std::size_t j = 0; j < scene.joints.size(); ++j) {
        if (indexes[j].empty())
            continue;
        const std::int64_t id = doc.newId();
        Node& cluster = doc.addObject("Deformer", id, scene.joints[j].name, "SubDeformer", "Cluster");
        cluster.child("Version").addInt32(100);
        cluster.child("UserData").addString("").addString("");
        cluster.child("Indexes").addInt32s(indexes[j]);
        cluster.child("Weights").addDoubles(weights[j]);
        cluster.child("Transform").addDoubles(matrixArray(glm::inverse(scene.joints[j].bindWorld)));
        cluster.child("TransformLink").addDoubles(matrixArray(scene.joints[j].bindWorld));
        doc.connect(id, skin);
        doc.connect(jointModels[j], id);
    }
}

// An image's name in the file: its file name, made unique among the scene's.
std::string uniqueImageName(const std::string& name, std::set<std::string>& taken)
{
    std::string out = name.empty() ? "texture.png" : name;
    for (int n = 2; !taken.insert(out).second; ++n)
        out = std::to_string(n) + "_" + (name.empty() ? "texture.png" : name);
    return out;
}

// Materials (diffuse colour) with their base colour texture: a Texture linked
// to the material's DiffuseColor and a Video holding the image's bytes as its
// Content when embedded, else naming the file beside the FBX. Texture and
// Video carry the same file name (Blender pairs them by it).
std::vector<std::int64_t> addMaterials(Document& doc, const ExportScene& scene, bool embedTextures)
{
    std::vector<std::int64_t> ids;
    const std::vector<std::string> files = imageFileNames(scene);
    for (std::size_t m = 0; m < scene.materials.size(); ++m) {
        const ExportMaterial& source = scene.materials[m];
        const std::int64_t id = doc.newId();
        ids.push_back(id);
        Node& material = doc.addObject("Material", id, source.name, "Material", "");
        material.child("Version").addInt32(102);
        material.child("ShadingModel").addString("phong");
        material.child("MultiLayer").addInt32(0);
        Node& p70 = material.child("Properties70");
        propertyVector(p70, "DiffuseColor", "Color", Vec3(source.baseColor), "A");
        propertyDouble(p70, "DiffuseFactor", 1.0, "A");
        if (source.image.empty())
            continue;
        const std::string& file = files[m];
        const std::int64_t texture = doc.newId(), video = doc.newId();
        Node& t = doc.addObject("Texture", texture, file, "Texture", "");
        t.child("Type").addString("TextureVideoClip");
        t.child("Version").addInt32(202);
        t.child("TextureName").addString(objectName(file, "Texture"));
        t.child("Media").addString(objectName(file, "Video"));
        t.child("FileName").addString(file);
        t.child("RelativeFilename").addString(file);
        Node& v = doc.addObject("Video", video, file, "Video", "Clip");
        v.child("Type").addString("Clip");
        v.child("UseMipMap").addInt32(0);
        v.child("Filename").addString(file);
        v.child("RelativeFilename").addString(file);
        if (embedTextures)
            v.child("Content").addRaw(source.image);
        doc.connect(video, texture);
        doc.connect(texture, id, "DiffuseColor");
    }
    return ids;
}

// A camera: a `Camera` Model (the frame turned to FBX's +X look) with its
// Camera NodeAttribute: the lens as Blender's exporter writes it (focal
// length in mm, film back in inches, FieldOfView across the film's width in
// degrees, which Assimp reads), clip planes in file units, perspective or
// orthographic.
void addCamera(Document& doc, const ExportCamera& camera, ModelIds& ids)
{
    const std::int64_t model = addModel(doc, camera.name, "Camera", camera.poseWorld * glm::mat4_cast(fbxCameraTurn()));
    const std::int64_t id = doc.newId();
    Node& attribute = doc.addObject("NodeAttribute", id, camera.name, "NodeAttribute", "Camera");
    Node& p70 = attribute.child("Properties70");
    const double width = camera.filmWidth, height = camera.filmHeight;
    propertyVector(p70, "Position", "Vector", Vec3(0.0), "");
    propertyVector(p70, "UpVector", "Vector", Vec3(0.0, 1.0, 0.0), "");
    propertyVector(p70, "InterestPosition", "Vector", Vec3(1.0, 0.0, 0.0), "");
    propertyInt(p70, "AspectRatioMode", "enum", 0); // window size
    propertyDouble(p70, "AspectWidth", width);
    propertyDouble(p70, "AspectHeight", height);
    propertyDouble(p70, "FilmWidth", width);
    propertyDouble(p70, "FilmHeight", height);
    propertyDouble(p70, "FilmAspectRatio", width / height);
    propertyInt(p70, "ApertureMode", "enum", 3); // focal length
    propertyInt(p70, "GateFit", "enum", 2);      // horizontal
    p70.child("P").addString("FieldOfView").addString("FieldOfView").addString("").addString("A")
        .addDouble(glm::degrees(horizontalFieldOfView(camera, camera.focalLength)));
    p70.child("P").addString("FocalLength").addString("Number").addString("").addString("A").addDouble(camera.focalLength);
    propertyDouble(p70, "NearPlane", camera.nearClip);
    propertyDouble(p70, "FarPlane", camera.farClip);
    propertyInt(p70, "CameraProjectionType", "enum", camera.orthographic ? 1 : 0); // perspective, orthographic
    if (camera.orthographic) // the width it sees, metres whatever the file's unit: Blender's ortho_scale
        propertyDouble(p70, "OrthoZoom", camera.orthoWidth);
    attribute.child("TypeFlags").addString("Camera");
    attribute.child("GeometryVersion").addInt32(124);
    attribute.child("Position").addDouble(0.0).addDouble(0.0).addDouble(0.0);
    attribute.child("Up").addDouble(0.0).addDouble(1.0).addDouble(0.0);
    attribute.child("LookAt").addDouble(1.0).addDouble(0.0).addDouble(0.0);
    doc.connect(id, model);
    doc.connect(model, 0);
    ids.cameras.push_back(model);
    ids.cameraAttributes.push_back(id);
}

void addBindPose(Document& doc, const ExportScene& scene, const std::vector<std::int64_t>& jointModels,
                 const std::vector<std::int64_t>& meshModels)
{
    const std::int64_t id = doc.newId();
    Node& pose = doc.addObject("Pose", id, scene.name.empty() ? "BindPose" : scene.name, "Pose", "BindPose");
    pose.child("Type").addString("BindPose");
    pose.child("Version").addInt32(100);
    pose.child("NbPoseNodes").addInt32(std::int32_t(jointModels.size() + meshModels.size()));
    auto poseNode = [&](std::int64_t model, const Mat4& world) {
        Node& node = pose.child("PoseNode");
        node.child("Node").addInt64(model);
        node.child("Matrix").addDoubles(matrixArray(world));
    };
    for (std::size_t j = 0; j < jointModels.size(); ++j)
        poseNode(jointModels[j], scene.joints[j].bindWorld);
    for (std::int64_t mesh : meshModels)
        poseNode(mesh, Mat4(1.0));
}

} // namespace

Quat fbxCameraTurn() { return glm::angleAxis(glm::radians(90.0), Vec3(0.0, 1.0, 0.0)); }

std::vector<std::string> imageFileNames(const ExportScene& scene)
{
    std::vector<std::string> names;
    std::set<std::string> taken;
    for (const ExportMaterial& material : scene.materials)
        names.push_back(material.image.empty() ? std::string() : uniqueImageName(material.imageName, taken));
    return names;
}

ModelIds addSceneObjects(Document& doc, const ExportScene& scene, bool embedTextures)
{
    ModelIds ids;
    for (const ExportJoint& joint : scene.joints) {
        const std::int64_t id = addModel(doc, joint.name, "LimbNode", joint.poseLocal);
        addAttribute(doc, id, joint.name, true);
        doc.connect(id, joint.parent < 0 ? 0 : ids.joints[std::size_t(joint.parent)]);
        ids.joints.push_back(id);
    }
    for (const ExportController& controller : scene.controllers) {
        Node* p70 = nullptr;
        const std::int64_t id = addModel(doc, controller.name, "Null", controller.poseLocal, &p70);
        // User properties ("U"): custom properties in Blender, metadata in Assimp.
        propertyString(*p70, "rig_kind", "controller", "U");
        if (!controller.id.empty())
            propertyString(*p70, "rig_id", controller.id, "U");
        if (!controller.shape.empty())
            propertyString(*p70, "rig_shape", controller.shape, "U");
        for (const auto& [channel, value] : controller.defaults) // cleanup's record: what reset returns to
            propertyDouble(*p70, "rig_default_" + channel, value, "U");
        for (const auto& a : controller.attributes) { // the channel box's custom attributes, as Maya writes them
            if (a.labels.empty()) {
                propertyDouble(*p70, a.name, a.value, "A+U");
                continue;
            }
            std::string labels;
            for (const auto& label : a.labels)
                labels += (labels.empty() ? "" : "~") + label;
            p70->child("P").addString(a.name).addString("enum").addString("").addString("A+U")
                .addInt32(std::int32_t(std::lround(a.value))).addString(labels);
        }
        addAttribute(doc, id, controller.name, false);
        doc.connect(id, controller.parent < 0 ? 0 : ids.controllers[std::size_t(controller.parent)]);
        ids.controllers.push_back(id);
    }
    for (const ExportCamera& camera : scene.cameras)
        addCamera(doc, camera, ids);
    const std::vector<std::int64_t> materials = addMaterials(doc, scene, embedTextures);
    std::vector<std::int64_t> meshModels;
    for (const SkinnedMesh& mesh : scene.meshes) {
        const bool hasMaterial = mesh.material >= 0 && std::size_t(mesh.material) < materials.size();
        const std::int64_t model = addModel(doc, mesh.name, "Mesh", Mat4(1.0)), geometry = doc.newId();
        addGeometry(doc, geometry, mesh, hasMaterial);
        doc.connect(model, 0);
        doc.connect(geometry, model);
        if (hasMaterial)
            doc.connect(materials[std::size_t(mesh.material)], model);
        addSkin(doc, geometry, mesh, scene, ids.joints);
        meshModels.push_back(model);
    }
    if (!scene.joints.empty())
        addBindPose(doc, scene, ids.joints, meshModels);
    return ids;
}

} // namespace rs::io::fbx
