// Scene surfaces (room and crates): passes the world-space position, the tangent frame (TBN) and the
// texture coordinates to Scene.frag, which does parallax occlusion mapping, normal mapping and
// Blinn-Phong lighting. The geometry is static and stored in world space, so there is no model matrix.
#version 430 core

layout(std140, binding = 0) uniform Camera {
    mat4 m4View;
    mat4 m4Projection;
    vec4 v4CameraPos; // xyz: eye position in world space
};

layout(location = 0) in vec3 v3VertexPos;
layout(location = 1) in vec3 v3VertexNormal;
layout(location = 2) in vec3 v3VertexTangent;   // direction of increasing u
layout(location = 3) in vec3 v3VertexBitangent; // direction of increasing v
layout(location = 4) in vec2 v2VertexUV;
layout(location = 5) in vec4 v4VertexUVBounds;  // the face's UV rectangle: (u min, v min, u max, v max)

layout(location = 0) out vec3 v3Position;
layout(location = 1) out vec3 v3Normal;
layout(location = 2) out vec3 v3Tangent;
layout(location = 3) out vec3 v3Bitangent;
layout(location = 4) out vec2 v2UV;
layout(location = 5) flat out vec4 v4UVBounds;

void main() {
    v3Position = v3VertexPos;
    v3Normal = v3VertexNormal;
    v3Tangent = v3VertexTangent;
    v3Bitangent = v3VertexBitangent;
    v2UV = v2VertexUV;
    v4UVBounds = v4VertexUVBounds;
    gl_Position = m4Projection * m4View * vec4(v3VertexPos, 1.0f);
}
