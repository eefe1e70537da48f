#include "GlProgram.h"

namespace rs::viewport {

namespace {

GLuint compile(GLenum type, const char* source, const std::string& what, std::string& error)
{
    GLuint shader = glCreateShader(type);
    glShaderSource(shader, 1, &source, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetShaderInfoLog(shader, sizeof log, nullptr, log);
        error = what + " shader compilation failed: " + log;
        glDeleteShader(shader);
        return 0;
    }
    return shader;
}

} // namespace

GLuint linkProgram(const char* vertexSource, const char* fragmentSource, const std::string& what, std::string& error)
{
    const GLuint vs = compile(GL_VERTEX_SHADER, vertexSource, what, error);
    const GLuint fs = vs ? compile(GL_FRAGMENT_SHADER, fragmentSource, what, error) : 0;
    if (!vs || !fs) {
        if (vs)
            glDeleteShader(vs);
        return 0;
    }
    GLuint program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        char log[2048] = {};
        glGetProgramInfoLog(program, sizeof log, nullptr, log);
        error = what + " shader link failed: " + log;
        glDeleteProgram(program);
        return 0;
    }
    return program;
}

} // namespace rs::viewport
