// What a program's shaders need set after linking that GLSL ES 3.00 cannot say in the source: the
// one description of it, which the translator (common/content glsl_es.hpp) writes for each shader and
// the browser build's GL layer (gl_web.hpp) applies to the linked program. GL-free and in the
// platform layer, the lowest that both see.
#pragma once
#include <string>
#include <vector>

namespace t10 {

// A shader's stage, as GLSL names it (the translator's input, a subroutine uniform's stage).
enum class GlslStage { Vertex, Fragment, Compute, Other };

struct NamedValue {
    std::string name; // as declared in the translated source (an array: its name, or "name[i]")
    int value;
};

struct SubroutineUniform {
    GlslStage stage;         // the shader that declares it
    int location;            // the subroutine uniform's layout(location = L) in the GLSL 4.30 source
    std::string uniformName; // the `uniform int` the translation declared for it: holds the chosen layout(index = N)
    std::vector<NamedValue> functions; // the subroutine functions it may call: name -> layout(index = N)
};

struct ProgramLayout {
    std::vector<NamedValue> samplerUnits;     // sampler uniform -> texture unit (arrays: one per element, "name[i]")
    std::vector<NamedValue> blockBindings;    // uniform block (its block name) -> binding point
    std::vector<NamedValue> uniformLocations; // uniform -> explicit location (an array: its first; element i at value + i)
    std::vector<SubroutineUniform> subroutineUniforms;

    // Adds another shader's layout (a program's is its shaders' together).
    void append(const ProgramLayout& shader) {
        samplerUnits.insert(samplerUnits.end(), shader.samplerUnits.begin(), shader.samplerUnits.end());
        blockBindings.insert(blockBindings.end(), shader.blockBindings.begin(), shader.blockBindings.end());
        uniformLocations.insert(uniformLocations.end(), shader.uniformLocations.begin(), shader.uniformLocations.end());
        subroutineUniforms.insert(subroutineUniforms.end(), shader.subroutineUniforms.begin(), shader.subroutineUniforms.end());
    }
};

} // namespace t10
