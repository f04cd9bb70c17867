#include "parallax/render/HeadlessContext.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GL/gl.h>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace px {

namespace {

bool hasExtension(const char* list, const char* name) {
    if (!list)
        return false;
    const std::size_t n = std::strlen(name);
    for (const char* p = std::strstr(list, name); p; p = std::strstr(p + 1, name)) {
        if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0'))
            return true;
    }
    return false;
}

std::string eglErrorName() {
    switch (eglGetError()) {
    case EGL_NOT_INITIALIZED:
        return "EGL_NOT_INITIALIZED";
    case EGL_BAD_ACCESS:
        return "EGL_BAD_ACCESS";
    case EGL_BAD_ALLOC:
        return "EGL_BAD_ALLOC";
    case EGL_BAD_ATTRIBUTE:
        return "EGL_BAD_ATTRIBUTE";
    case EGL_BAD_CONFIG:
        return "EGL_BAD_CONFIG";
    case EGL_BAD_CONTEXT:
        return "EGL_BAD_CONTEXT";
    case EGL_BAD_DISPLAY:
        return "EGL_BAD_DISPLAY";
    case EGL_BAD_MATCH:
        return "EGL_BAD_MATCH";
    case EGL_BAD_PARAMETER:
        return "EGL_BAD_PARAMETER";
    default:
        return "an EGL error";
    }
}

struct Candidate {
    std::string name;
    EGLDisplay display;
};

// Hardware devices first, then Mesa's surfaceless platform, then software devices.
std::vector<Candidate> candidates(std::string& notes) {
    std::vector<Candidate> hardware, software, surfaceless;
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    auto queryDevices =
        reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
    auto queryDeviceString = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(
        eglGetProcAddress("eglQueryDeviceStringEXT"));
    const char* forced = std::getenv("PX_EGL_PLATFORM");
    const std::string force = forced ? forced : "";
    if (!force.empty() && force != "device" && force != "surfaceless") {
        notes += "PX_EGL_PLATFORM is \"" + force + "\", expected device or surfaceless; ";
        return {};
    }
    if (!getPlatformDisplay) {
        notes += "EGL has no eglGetPlatformDisplayEXT; ";
        return {{"the default EGL display", eglGetDisplay(EGL_DEFAULT_DISPLAY)}};
    }
    if (force != "surfaceless" && queryDevices && hasExtension(client, "EGL_EXT_platform_device")) {
        EGLDeviceEXT devices[16];
        EGLint count = 0;
        if (queryDevices(16, devices, &count)) {
            for (EGLint i = 0; i < count; ++i) {
                const char* ext =
                    queryDeviceString ? queryDeviceString(devices[i], EGL_EXTENSIONS) : nullptr;
                const bool isSoftware = hasExtension(ext, "EGL_MESA_device_software");
                EGLDisplay d = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                if (d == EGL_NO_DISPLAY)
                    continue;
                const std::string name =
                    "EGL device " + std::to_string(i) + (isSoftware ? " (software)" : "");
                (isSoftware ? software : hardware).push_back({name, d});
            }
        }
    }
    if (force != "device" && hasExtension(client, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d =
            getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY)
            surfaceless.push_back({"surfaceless Mesa", d});
    }
    std::vector<Candidate> all = hardware;
    all.insert(all.end(), surfaceless.begin(), surfaceless.end());
    all.insert(all.end(), software.begin(), software.end());
    if (all.empty())
        notes += "no EGL device or surfaceless platform; ";
    return all;
}

} // namespace

Result<std::unique_ptr<HeadlessContext>> HeadlessContext::create() {
    std::string tried;
    for (const Candidate& c : candidates(tried)) {
        std::unique_ptr<HeadlessContext> made;
        // Returns why the candidate is unusable, or "" with `made` set.
        auto attempt = [&]() -> std::string {
            EGLint major = 0, minor = 0;
            if (!eglInitialize(c.display, &major, &minor))
                return "eglInitialize failed (" + eglErrorName() + ")";
            if (!eglBindAPI(EGL_OPENGL_API))
                return "no desktop OpenGL (" + eglErrorName() + ")";
            const char* ext = eglQueryString(c.display, EGL_EXTENSIONS);
            EGLConfig config = EGL_NO_CONFIG_KHR;
            const bool noConfig = hasExtension(ext, "EGL_KHR_no_config_context") ||
                                  hasExtension(ext, "EGL_MESA_configless_context");
            const bool surfaceless = hasExtension(ext, "EGL_KHR_surfaceless_context");
            if (!noConfig || !surfaceless) {
                const EGLint wanted[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                         EGL_OPENGL_BIT, EGL_NONE};
                EGLint n = 0;
                if (!eglChooseConfig(c.display, wanted, &config, 1, &n) || n < 1)
                    return "no OpenGL config (" + eglErrorName() + ")";
            }
            const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         4,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         3,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
            EGLContext context = eglCreateContext(c.display, config, EGL_NO_CONTEXT, attributes);
            const bool versioned = context != EGL_NO_CONTEXT;
            if (!versioned) // learn what there is, to say so
                context = eglCreateContext(c.display, config, EGL_NO_CONTEXT, nullptr);
            if (context == EGL_NO_CONTEXT)
                return "no OpenGL context (" + eglErrorName() + ")";
            EGLSurface surface = EGL_NO_SURFACE;
            if (!surfaceless) {
                const EGLint size[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
                surface = eglCreatePbufferSurface(c.display, config, size);
            }
            if (!eglMakeCurrent(c.display, surface, surface, context)) {
                eglDestroyContext(c.display, context);
                return "cannot make the context current (" + eglErrorName() + ")";
            }
            GlInfo info = currentGlInfo();
            if (!versioned || !requireGl43(info)) {
                eglMakeCurrent(c.display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
                if (surface != EGL_NO_SURFACE)
                    eglDestroySurface(c.display, surface);
                eglDestroyContext(c.display, context);
                return "found " + info.summary();
            }
            made.reset(new HeadlessContext);
            made->m_display = c.display;
            made->m_context = context;
            made->m_surface = surface;
            made->m_info = std::move(info);
            made->m_platform = c.name;
            return {};
        };
        const std::string failure = attempt();
        if (failure.empty())
            return made;
        tried += c.name + ": " + failure + "; ";
    }
    if (tried.size() >= 2)
        tried.resize(tried.size() - 2);
    return Error{"no usable OpenGL 4.3 context without a display (" + tried + ")"};
}

HeadlessContext::~HeadlessContext() {
    if (!m_display)
        return;
    if (eglGetCurrentContext() == m_context)
        eglMakeCurrent(m_display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (m_surface != EGL_NO_SURFACE)
        eglDestroySurface(m_display, m_surface);
    eglDestroyContext(m_display, m_context);
    // No eglTerminate: the display is shared by every context on this platform in the process.
}

bool HeadlessContext::makeCurrent() {
    return eglMakeCurrent(m_display, m_surface, m_surface, m_context) == EGL_TRUE;
}

} // namespace px
