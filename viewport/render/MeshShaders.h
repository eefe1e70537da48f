#pragma once
// GLSL 3.30 sources of the mesh pass (MeshRenderer): the vertex shader skins
// on the GPU from a palette buffer (linear blend: 4 texels per bone; dual
// quaternion: 2) with the 4 largest influences per vertex, and colours a
// vertex by a weight heat ramp, its bone or an overlay; the fragment shader
// lights it with a head light and the material's texture.
namespace rs::viewport {

extern const char* const kMeshVertexShader;
extern const char* const kMeshFragmentShader;

} // namespace rs::viewport
