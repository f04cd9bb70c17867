#pragma once
// Every uniform and sampler a generated shader may declare. The generator declares one only if
// the code it keeps reads it (see ShaderGenerator.h); the renderer sets them by these names.

#include <string>
#include <vector>

namespace px::shader {

struct Binding {
    const char* name;
    const char* type; // GLSL type; "int[32]" style for arrays
    int unit;         // samplers: texture unit; else -1
};

const std::vector<Binding>& bindings();

// The GLSL declaration of a binding.
std::string declaration(const Binding& binding);

} // namespace px::shader
