// Light cubes: one instance per point light, a small cube at the light's position. The instance
// reads its position and HDR colour from the Lights block, the same data the surfaces are lit by.
#version 430 core

const int kMaxLights = 8; // must match Scene's kMaxLights on the host

layout(std140, binding = 0) uniform Camera {
    mat4 m4View;
    mat4 m4Projection;
    vec4 v4CameraPos;
};

layout(std140, binding = 1) uniform Lights {
    vec4 v4LightPos[kMaxLights];
    vec4 v4LightColour[kMaxLights];
    int iLightCount;
};

layout(location = 0) uniform float fHalfSize; // half the cube's edge, in world units

layout(location = 0) in vec3 v3VertexPos; // corner of a cube spanning [-1, 1]

layout(location = 0) flat out vec3 v3Colour;

void main() {
    v3Colour = v4LightColour[gl_InstanceID].rgb;
    vec3 v3World = v4LightPos[gl_InstanceID].xyz + v3VertexPos * fHalfSize;
    gl_Position = m4Projection * m4View * vec4(v3World, 1.0f);
}
