// Post-processing fragment shader: reads the HDR accumulation texture and writes it to the
// default framebuffer. In this stage it is a pass-through, so values above 1.0 clip.
#version 430 core

layout(binding = 7) uniform InvResolution {
    vec2 v2InvResolution;
};
layout(binding = 15) uniform sampler2D s2AccumulationTexture;

layout(location = 0) out vec3 v3ColourOut;

void main() {
    // Get UV coordinates
    vec2 v2UV = gl_FragCoord.xy * v2InvResolution;

    // Get colour data
    vec3 v3RetColour = texture(s2AccumulationTexture, v2UV).rgb;

    // Output the colour unchanged
    v3ColourOut = v3RetColour;
}
