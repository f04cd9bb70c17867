#include "ImageModule.h"

#include "parallax/Version.h"

#include <atomic>
#include <cstdlib>
#include <dlfcn.h>
#include <filesystem>
#include <system_error>

namespace px {
namespace {

std::atomic<bool> g_loaded{false};

// Where to look, in order: PX_IMAGE_MODULE if set (then only there), next to the program as
// installed, where the build put it.
std::vector<std::string> candidates() {
    if (const char* named = std::getenv("PX_IMAGE_MODULE"); named && *named)
        return {named};
    std::vector<std::string> paths;
    std::error_code error;
    const std::filesystem::path program = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error)
        paths.push_back((program.parent_path() / PX_IMAGE_MODULE_INSTALLED).lexically_normal());
    paths.emplace_back(PX_IMAGE_MODULE_BUILT);
    return paths;
}

Result<const ImageModule*> load() {
    std::string tried;
    for (const std::string& path : candidates()) {
        if (!tried.empty())
            tried += "; ";
        std::error_code error;
        if (!std::filesystem::exists(path, error)) {
            tried += path + ": no such file";
            continue;
        }
        // RTLD_NOW: a module that does not resolve fails here, with dlerror's reason.
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* why = dlerror();
            tried += path + ": " + (why ? why : "cannot be loaded");
            continue;
        }
        using Entry = const ImageModule* (*)();
        auto entry = reinterpret_cast<Entry>(dlsym(handle, "pxImageModule"));
        const ImageModule* module = entry ? entry() : nullptr;
        if (!module || module->abi != kImageModuleAbi || std::string(module->version) != kVersion) {
            tried += path + ": built for another version of Parallax Studio";
            dlclose(handle);
            continue;
        }
        g_loaded = true;
        return module; // never unloaded: decoders and their vtables live in it
    }
    return Error{"the image library module (libparallax-oiio.so), which reads and writes every "
                 "format but PNG, cannot be loaded (" +
                 tried + ")"};
}

} // namespace

Result<const ImageModule*> imageModule() {
    static const Result<const ImageModule*> module = load();
    return module;
}

bool imageModuleLoaded() {
    return g_loaded;
}

} // namespace px
