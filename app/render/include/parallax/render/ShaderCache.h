#pragma once
// Compiles each variant once per context (or per group of sharing contexts) and keeps it: keys are
// canonicalised first, so keys that generate the same shader share one program. A variant that
// fails to build keeps its error and is not retried.

#include "parallax/render/ShaderProgram.h"

#include <map>
#include <memory>

namespace px {

class ShaderCache {
public:
    Result<const ShaderProgram*> program(const VariantKey& key);
    std::size_t size() const { return m_programs.size(); }
    void clear() { m_programs.clear(); }

private:
    std::map<std::uint32_t, Result<std::unique_ptr<ShaderProgram>>> m_programs;
};

} // namespace px
