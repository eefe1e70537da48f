// The mesh shaders (see MeshShaders.h).
#include "MeshShaders.h"

namespace rs::viewport {

extern const char* const kMeshVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 3) in uvec4 joints;  // the 4 largest influences, largest first
layout(location = 4) in vec4 weights;  // summing to 1, or all 0 (no influence)
layout(location = 5) in vec3 overlayColor; // SceneMesh::vertexColors
uniform mat4 viewProjection;
uniform samplerBuffer palette; // linear: 4 texels (matrix columns) per bone; dual quaternion: 2 (real, dual)
uniform int skinning;          // 0 bind pose, 1 linear blend, 2 dual quaternion
uniform int weightDisplay;     // 0 material, 1 one bone's weight, 2 dominant bone, 3 a colour per vertex
uniform int weightBone;
out vec3 worldNormal;
out vec2 texCoord;
out vec3 weightColor;

mat4 boneMatrix(uint j) {
    int i = int(j) * 4;
    return mat4(texelFetch(palette, i), texelFetch(palette, i + 1), texelFetch(palette, i + 2), texelFetch(palette, i + 3));
}
vec3 rotate(vec4 q, vec3 v) { return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v); }
vec3 heat(float w) { return clamp(vec3(4.0 * w - 2.0, 2.0 - abs(4.0 * w - 2.0), 2.0 - 4.0 * w), 0.0, 1.0); } // blue, cyan, green, yellow, red
vec3 boneColor(uint j) { // golden-ratio hues: neighbouring bones differ
    float h = fract(float(j) * 0.618034) * 6.0;
    vec3 rgb = clamp(abs(mod(h + vec3(0.0, 4.0, 2.0), 6.0) - 3.0) - 1.0, 0.0, 1.0);
    return mix(vec3(1.0), rgb, 0.75) * 0.95;
}

void main() {
    vec3 p = position;
    vec3 n = normal;
    bool weighted = dot(weights, vec4(1.0)) > 1e-6;
    if (skinning == 1 && weighted) {
        mat4 m = weights.x * boneMatrix(joints.x) + weights.y * boneMatrix(joints.y) +
                 weights.z * boneMatrix(joints.z) + weights.w * boneMatrix(joints.w);
        p = (m * vec4(position, 1.0)).xyz;
        n = mat3(m) * normal;
    } else if (skinning == 2 && weighted) {
        vec4 first = texelFetch(palette, int(joints.x) * 2);
        vec4 real = vec4(0.0), dual = vec4(0.0);
        for (int k = 0; k < 4; ++k) {
            int i = int(joints[k]) * 2;
            vec4 r = texelFetch(palette, i);
            float w = dot(r, first) < 0.0 ? -weights[k] : weights[k]; // antipodality: blend the shorter way round
            real += w * r;
            dual += w * texelFetch(palette, i + 1);
        }
        float len = max(length(real), 1e-8);
        real /= len;
        dual /= len;
        vec3 t = 2.0 * (real.w * dual.xyz - dual.w * real.xyz + cross(real.xyz, dual.xyz));
        p = rotate(real, position) + t;
        n = rotate(real, normal);
    }
    if (weightDisplay == 1) {
        float w = 0.0;
        for (int k = 0; k < 4; ++k)
            if (int(joints[k]) == weightBone) w += weights[k];
        weightColor = heat(w);
    } else if (weightDisplay == 2) {
        weightColor = weighted ? boneColor(joints.x) : vec3(0.35);
    } else if (weightDisplay == 3) {
        weightColor = overlayColor;
    } else {
        weightColor = vec3(0.0);
    }
    worldNormal = n;
    texCoord = uv;
    gl_Position = viewProjection * vec4(p, 1.0);
}
)";

extern const char* const kMeshFragmentShader = R"(#version 330 core
in vec3 worldNormal;
in vec2 texCoord;
in vec3 weightColor;
uniform vec3 baseColor;
uniform sampler2D baseTexture;
uniform bool hasTexture;
uniform int weightDisplay;
uniform vec3 viewDirection;
uniform float alpha;
out vec4 fragmentColor;
void main() {
    float l = length(worldNormal);
    float facing = l > 1e-8 ? abs(dot(worldNormal / l, viewDirection)) : 1.0;
    float light = 0.35 + 0.65 * facing; // a headlight; both faces lit (open meshes, see-through passes)
    vec3 albedo = weightDisplay != 0 ? weightColor
                                     : baseColor * (hasTexture ? texture(baseTexture, texCoord).rgb : vec3(1.0));
    fragmentColor = vec4(albedo * light, alpha);
}
)";

} // namespace rs::viewport
