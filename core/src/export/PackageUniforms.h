#pragma once
// The meaning and value of each uniform and texture binding of the package's shader (README.txt).

#include "parallax/material/Material.h"
#include "parallax/shader/ShaderGenerator.h"

#include <string>

namespace px::exporter {

struct UniformValue {
    std::string meaning;  // empty: not a uniform the package documents
    std::string value;    // the material's value, or where it comes from
    bool mustSet = false; // false: the default in the README is safe
};

UniformValue uniformValue(const std::string& name, const Material& material, float heightMax);

// The texture format and filtering a binding unit expects.
const char* unitFormat(int unit);

} // namespace px::exporter
