#pragma once
// Our binary FBX writer (7.4 by default, 7.5 on request; io/FbxBinary.h is the
// container). Assimp is not involved. What a file holds:
//  - FBXHeaderExtension, FileId, CreationTime, Creator: fixed (a 1970 time and
//    a constant id) so the same scene gives byte-identical files, unless
//    FbxWriteOptions::creationTime is set;
//  - GlobalSettings: UpAxis / FrontAxis / CoordAxis for the convention (Y-up:
//    1, 2, 0; Z-up: 2, -1, 0) and UnitScaleFactor = centimetres per file unit
//    (100 for metres, so Blender imports at scale 1; 1 for Unreal's cm);
//    30 fps (TimeMode 6);
//  - Documents, References, Definitions (the object counts per kind);
//  - Objects: every joint a `LimbNode` Model with a LimbNode NodeAttribute
//    (an armature imports with or without a mesh), at its current pose
//    (poseLocal; Lcl Translation, Lcl Rotation as XYZ Euler degrees, Lcl
//    Scaling); controllers `Null` Models with user properties rig_kind,
//    rig_id, rig_shape; each camera a `Camera` Model (its frame turned to
//    FBX's +X look) with a Camera NodeAttribute (lens, film back, clip
//    planes: io/FbxScene.cpp); each mesh a Mesh Model at the origin with its Geometry
//    (Vertices, PolygonVertexIndex with the negated last index, normals by
//    vertex, UVs by polygon vertex, one material for all), a Skin Deformer
//    with one Cluster per weighing joint (Indexes, Weights, Transform =
//    inverse(joint bind world), TransformLink = joint bind world), its
//    Material (DiffuseColor) with a Texture / Video, the image embedded or
//    (FbxWriteOptions::embedTextures false) beside the file; one `BindPose`
//    Pose with the bind world matrix of every joint and mesh (so a posed
//    export keeps its rest pose in importers);
//  - animation: io/FbxAnimation.h, FbxAnimation.cpp; one Take per clip;
//  - Connections (OO, OP for properties).
// Matrices are 16 doubles, column-major. Arrays are written raw (encoding 0).
#include "base/Diagnostic.h"
#include "base/Result.h"
#include "io/ExportScene.h"

#include <cstdint>
#include <ctime>
#include <optional>
#include <string>

namespace rs::io {

struct FbxWriteOptions {
    std::uint32_t version = 7400;           // 7400 or 7500 (64-bit record offsets)
    std::optional<std::time_t> creationTime; // stamped in the header; none: the fixed time
    std::string generator = "Rigsmith";
    // True: each texture's image inside the file (the Video's Content). False:
    // writeFbx writes each image beside the file (atomically, under the name
    // the FBX gives it: io/FbxDocument.h imageFileNames), which the FBX names
    // by RelativeFilename; an existing file of that name is replaced.
    bool embedTextures = true;
};

// The file's bytes for `scene` in the file's convention (converted()); `convention` is declared.
Result<std::string> fbxBytes(const ExportScene& scene, const Convention& convention, const FbxWriteOptions& options = {});
// Writes them atomically (io/AtomicFile.h), with the images beside them unless
// embedded; errors name `path` (or the image's file).
Diagnostics writeFbx(const ExportScene& scene, const std::string& path, const Convention& convention,
                     const FbxWriteOptions& options = {});

} // namespace rs::io
