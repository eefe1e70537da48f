#pragma once
// Shader programs for the renderers (render/ only; needs a current GL context).
#include <epoxy/gl.h>

#include <string>

namespace rs::viewport {

// Compiles and links a vertex and a fragment shader; 0 with `error` set
// ("<what> shader compilation failed: <log>" or "<what> shader link failed: <log>").
GLuint linkProgram(const char* vertexSource, const char* fragmentSource, const std::string& what, std::string& error);

} // namespace rs::viewport
