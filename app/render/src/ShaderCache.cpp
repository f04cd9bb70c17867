#include "parallax/render/ShaderCache.h"

namespace px {

Result<const ShaderProgram*> ShaderCache::program(const VariantKey& requested) {
    const VariantKey key = canonical(requested);
    auto it = m_programs.find(key.bits());
    if (it == m_programs.end()) {
        auto build = [&]() -> Result<std::unique_ptr<ShaderProgram>> {
            Result<GeneratedProgram> generated = generateProgram(key);
            if (!generated)
                return generated.error();
            Result<ShaderProgram> built = ShaderProgram::build(*generated);
            if (!built)
                return built.error();
            return std::make_unique<ShaderProgram>(std::move(*built));
        };
        it = m_programs.emplace(key.bits(), build()).first;
    }
    if (!it->second)
        return it->second.error();
    return static_cast<const ShaderProgram*>(it->second->get());
}

} // namespace px
