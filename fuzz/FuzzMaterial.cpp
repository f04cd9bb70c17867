// Fuzz target: the material file reader. Any bytes must give a material or a message, never a
// crash; a material that loads must save and load back to the same text.

#include "parallax/material/MaterialFile.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    for (const px::MaterialCheck check : {px::MaterialCheck::Complete, px::MaterialCheck::Preset}) {
        px::Result<px::Material> material = px::parseMaterial(text, "fuzz.json", check);
        if (!material) {
            if (material.error().message.rfind("fuzz.json: ", 0) != 0) {
                std::fprintf(stderr, "error without its file name: %s\n",
                             material.error().message.c_str());
                std::abort();
            }
            continue;
        }
        const std::string saved = px::materialToJson(*material);
        px::Result<px::Material> again = px::parseMaterial(saved, "saved.json", check);
        if (!again || px::materialToJson(*again) != saved) {
            std::fprintf(stderr, "round trip changed the material:\n%s\n", saved.c_str());
            std::abort();
        }
    }
    return 0;
}
