// The exact scene key: a two-pass compute reduction of the luminance texture's level 0.
#include "t10/exact_key.hpp"

#include "t10/error.hpp"

namespace t10 {

namespace {

// Its own shader folder (common/optional/shaders): an absolute name, which the search path keeps as it is.
constexpr const char* kShaderFile = T10_OPTIONAL_SHADER_DIR "/ExactKey.comp";
constexpr int kTile = 16; // the work group is kTile x kTile (ExactKey.comp)
constexpr GLint kPassLocation = 0;
constexpr GLint kSizeLocation = 1;
constexpr GLint kPartialCountLocation = 2;

} // namespace

ExactKey::ExactKey(const ShaderManager& shaders)
    : program_(shaders.createProgram({kShaderFile})), result_(makeBuffer()) {
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, result_.get());
    glBufferData(GL_SHADER_STORAGE_BUFFER, sizeof(float), nullptr, GL_DYNAMIC_COPY);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
}

void ExactKey::reduce(GLuint texture, int width, int height) {
    if (width < 1 || height < 1) throw Error("ExactKey: the luminance texture must be at least 1x1");
    const GLuint groupsX = static_cast<GLuint>((width + kTile - 1) / kTile);
    const GLuint groupsY = static_cast<GLuint>((height + kTile - 1) / kTile);
    const auto partialCount = static_cast<GLsizeiptr>(groupsX) * static_cast<GLsizeiptr>(groupsY);
    if (!partials_ || partialsSize_ < partialCount) {
        partials_ = makeBuffer();
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, partials_.get());
        glBufferData(GL_SHADER_STORAGE_BUFFER, partialCount * static_cast<GLsizeiptr>(sizeof(float)), nullptr,
                     GL_DYNAMIC_COPY);
        glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
        partialsSize_ = partialCount;
    }

    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    glActiveTexture(GL_TEXTURE0);
    GLint previous = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
    glBindTexture(GL_TEXTURE_2D, texture);
    GLint program = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &program);

    glUseProgram(program_.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, partials_.get());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, result_.get());
    glUniform2i(kSizeLocation, width, height);
    glUniform1i(kPartialCountLocation, static_cast<GLint>(partialCount));
    glUniform1i(kPassLocation, 0);
    glDispatchCompute(groupsX, groupsY, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glUniform1i(kPassLocation, 1);
    glDispatchCompute(1, 1, 1);

    glUseProgram(static_cast<GLuint>(program));
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
    glActiveTexture(static_cast<GLenum>(active));
}

void ExactKey::store(GLuint texture, int width, int height, int lastLevel) {
    reduce(texture, width, height);
    glMemoryBarrier(GL_PIXEL_BUFFER_BARRIER_BIT);
    GLint active = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    glActiveTexture(GL_TEXTURE0);
    GLint previous = 0;
    glGetIntegerv(GL_TEXTURE_BINDING_2D, &previous);
    GLint unpack = 0;
    glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpack);
    glBindTexture(GL_TEXTURE_2D, texture);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, result_.get());
    // From the buffer, at offset 0: GL converts the float to the texture's format (R16: clamped and
    // rounded to 1/65535; R16F: rounded to half).
    glTexSubImage2D(GL_TEXTURE_2D, lastLevel, 0, 0, 1, 1, GL_RED, GL_FLOAT, nullptr);
    glBindBuffer(GL_PIXEL_UNPACK_BUFFER, static_cast<GLuint>(unpack));
    glBindTexture(GL_TEXTURE_2D, static_cast<GLuint>(previous));
    glActiveTexture(static_cast<GLenum>(active));
}

float ExactKey::readMean() const {
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    float mean = 0.0f;
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, result_.get());
    glGetBufferSubData(GL_SHADER_STORAGE_BUFFER, 0, sizeof(float), &mean);
    glBindBuffer(GL_SHADER_STORAGE_BUFFER, 0);
    return mean;
}

} // namespace t10
