#pragma once
// A headless OSMesa context with GL errors reported (any GL error makes render() throw) and a
// Renderer for it, destroyed first: the render tests' usual fixture.
#include <volsg/context/OSMesaContext.h>
#include <volsg/gl/GlDebug.h>
#include <volsg/render/Renderer.h>

namespace volsg::test {

struct Offscreen {
    OSMesaContext context;
    bool errorChecking = enableGlErrorChecking();
    Renderer renderer;
};

} // namespace volsg::test
