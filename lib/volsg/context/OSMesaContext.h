#pragma once
// Offscreen GL through Mesa's OSMesa: no window system, no X server.

#include <vector>

#include <volsg/context/Context.h>

struct osmesa_context; // GL/osmesa.h's context, kept out of this header

namespace volsg {

/// An OSMesa 3.3+ core-profile context (Mesa gives 4.5). Its own framebuffer is a small
/// 16x16 RGBA8 buffer: renders go to framebuffer objects. Made current on construction.
class OSMesaContext final : public Context {
public:
    OSMesaContext();
    ~OSMesaContext() override;
    OSMesaContext(const OSMesaContext&) = delete;
    OSMesaContext& operator=(const OSMesaContext&) = delete;

    void makeCurrent() override;
    std::string backendName() const override { return "osmesa"; }

    static constexpr int bufferSize = 16; ///< width and height of the context's own buffer

private:
    osmesa_context* context_ = nullptr;
    std::vector<unsigned char> buffer_;
};

} // namespace volsg
