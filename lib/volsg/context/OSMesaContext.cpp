// glad first: GL/osmesa.h includes GL/gl.h, which glad's header refuses to follow.
#include <glad/gl.h>

#include <GL/osmesa.h>

#include <volsg/context/OSMesaContext.h>
#include <volsg/core/Error.h>
#include <volsg/gl/GlLoader.h>

namespace volsg {

OSMesaContext::OSMesaContext() : buffer_(std::size_t(bufferSize) * std::size_t(bufferSize) * 4, 0) {
    // Asking for 3.3 core gives Mesa's highest core version (4.5); asking for 4.6 fails.
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_STENCIL_BITS,
                              0,
                              OSMESA_ACCUM_BITS,
                              0,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (!context_) throw Error("osmesa: could not create an OpenGL 3.3 core profile context");
    try {
        makeCurrent();
        requireCoreGl33("osmesa");
    } catch (...) {
        OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
        OSMesaDestroyContext(context_);
        throw;
    }
}

OSMesaContext::~OSMesaContext() {
    if (OSMesaGetCurrentContext() == context_) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(context_);
}

void OSMesaContext::makeCurrent() {
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, bufferSize, bufferSize))
        throw Error("osmesa: OSMesaMakeCurrent failed");
    loadGlFunctions(OSMesaGetProcAddress, "osmesa");
}

} // namespace volsg
