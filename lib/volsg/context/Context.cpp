#include <volsg/context/Context.h>
#include <volsg/context/EglContext.h>
#include <volsg/context/OSMesaContext.h>
#include <volsg/core/Error.h>

namespace volsg {

std::unique_ptr<Context> Context::createOffscreen(Backend backend) {
    switch (backend) {
    case Backend::OSMesa:
        return std::make_unique<OSMesaContext>();
    case Backend::EGL:
        return std::make_unique<EglContext>();
    }
    throw Error("Context::createOffscreen: unknown backend");
}

Backend parseBackend(const std::string& name) {
    if (name == "osmesa") return Backend::OSMesa;
    if (name == "egl") return Backend::EGL;
    throw Error("unknown GL backend '" + name + "' (expected osmesa or egl)");
}

} // namespace volsg
