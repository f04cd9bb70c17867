#pragma once
// shaders/*.glsl, embedded at build time (EmbedShaders.cmake): the generator reads no files.

#include <optional>
#include <string_view>
#include <vector>

namespace px::shader {

struct EmbeddedFile {
    std::string_view path; // relative to shaders/, e.g. "trace/pom.glsl"
    std::string_view text;
};

const std::vector<EmbeddedFile>& embeddedFiles();

inline std::optional<std::string_view> embeddedFile(std::string_view path) {
    for (const EmbeddedFile& f : embeddedFiles()) {
        if (f.path == path)
            return f.text;
    }
    return std::nullopt;
}

} // namespace px::shader
