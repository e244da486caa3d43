// The exact mean of level 0 of the luminance texture, for t10::ExactKey
// (common/optional/src/exact_key.cpp, the optional library t10_exact_key: extras and the bench).
// Pass 0: each 16x16 work group sums its tile into one partial sum. Pass 1: one work group adds the
// partial sums and writes their mean. Each sum is a tree of float additions over at most a few
// hundred terms, so the relative error stays near 1e-6, unlike a mip chain at odd sizes, whose
// filter may skip or down-weight rows and columns.
#version 430 core

layout(local_size_x = 16, local_size_y = 16) in;

layout(binding = 0) uniform sampler2D s2Luminance;
layout(std430, binding = 0) buffer Partials { float fPartials[]; };
layout(std430, binding = 1) buffer Result { float fMean; };

layout(location = 0) uniform int iPass;
layout(location = 1) uniform ivec2 i2Size;
layout(location = 2) uniform int iPartialCount;

shared float fShared[256];

void reduceShared(uint uIndex) {
    for (uint uStride = 128u; uStride > 0u; uStride >>= 1u) {
        barrier();
        if (uIndex < uStride) fShared[uIndex] += fShared[uIndex + uStride];
    }
    barrier();
}

void main() {
    uint uIndex = gl_LocalInvocationIndex;
    if (iPass == 0) {
        ivec2 i2Texel = ivec2(gl_GlobalInvocationID.xy);
        bool bInside = all(lessThan(i2Texel, i2Size));
        fShared[uIndex] = bInside ? texelFetch(s2Luminance, i2Texel, 0).r : 0.0f;
        reduceShared(uIndex);
        if (uIndex == 0u) fPartials[gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x] = fShared[0];
    } else {
        float fSum = 0.0f;
        for (int i = int(uIndex); i < iPartialCount; i += 256) fSum += fPartials[i];
        fShared[uIndex] = fSum;
        reduceShared(uIndex);
        if (uIndex == 0u) fMean = fShared[0] / (float(i2Size.x) * float(i2Size.y));
    }
}
