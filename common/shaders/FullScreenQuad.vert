// Full-screen quad vertex shader shared by every post-process pass: the quad's corners are already
// in clip space, and fragment shaders compute their UV from gl_FragCoord and v2InvResolution.
#version 430 core

layout(location = 0) in vec2 v2VertexPos;

void main() {
    gl_Position = vec4(v2VertexPos, 0.0f, 1.0f);
}
