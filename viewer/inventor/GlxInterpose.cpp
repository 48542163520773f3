// Coin finds OpenGL functions beyond 1.1 (buffer objects, texture objects, multitexture) with
// glXGetProcAddress before anything else. Debian's libGLX (glvnd) answers with dispatch stubs
// that go to the current *GLX* context; with OSMesa current there is none, so every such call
// silently does nothing: vertex buffer objects stay empty (large shapes vanish) and textures are
// never bound. These two definitions, exported by the executable (ENABLE_EXPORTS), come first in
// the dynamic symbol lookup and hand Coin Mesa's own entry points for the current OSMesa
// context instead. GLX's own functions (glX*) still come from libGLX: Mesa would answer a
// glX name with a stub that raises GL_INVALID_OPERATION. volsg never calls these (it loads GL
// through OSMesaGetProcAddress or EGL).
#include <GL/osmesa.h>

#include <cstring>

#include <dlfcn.h>

extern "C" {

using ProcAddress = void (*)();
using GetProcAddress = ProcAddress (*)(const GLubyte*);

namespace {

ProcAddress lookUp(const GLubyte* name, const char* glxFunction) {
    const char* text = reinterpret_cast<const char*>(name);
    if (!text) return nullptr;
    if (std::strncmp(text, "glX", 3) == 0) {
        auto next = reinterpret_cast<GetProcAddress>(dlsym(RTLD_NEXT, glxFunction));
        return next ? next(name) : nullptr;
    }
    return reinterpret_cast<ProcAddress>(OSMesaGetProcAddress(text));
}

} // namespace

__attribute__((visibility("default"))) ProcAddress glXGetProcAddressARB(const GLubyte* name) {
    return lookUp(name, "glXGetProcAddressARB");
}

__attribute__((visibility("default"))) ProcAddress glXGetProcAddress(const GLubyte* name) {
    return lookUp(name, "glXGetProcAddress");
}
}
