// The full-screen quad: two triangles covering clip space, indexed with GLubyte as the tutorial's
// glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_BYTE, 0) expects.
#include "t10/quad.hpp"

#include <array>

namespace t10 {

FullScreenQuad::FullScreenQuad() : vao_(makeVertexArray()), vertices_(makeBuffer()), indices_(makeBuffer()) {
    constexpr std::array<GLfloat, 8> kCorners = {-1.0f, -1.0f, 1.0f, -1.0f, 1.0f, 1.0f, -1.0f, 1.0f};
    constexpr std::array<GLubyte, 6> kIndices = {0, 1, 2, 0, 2, 3};
    glBindVertexArray(vao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, vertices_.get());
    glBufferData(GL_ARRAY_BUFFER, sizeof kCorners, kCorners.data(), GL_STATIC_DRAW);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glEnableVertexAttribArray(0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices_.get());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, sizeof kIndices, kIndices.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
}

void FullScreenQuad::bind() const { glBindVertexArray(vao_.get()); }

} // namespace t10
