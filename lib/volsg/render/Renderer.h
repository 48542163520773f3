#pragma once
// Draws a scene graph into the current GL context: passes for opaque geometry, volumes and
// transparent geometry, into a floating-point target, read back as an Image.

#include <memory>

#include <glm/glm.hpp>

#include <volsg/core/Node.h>
#include <volsg/image/Image.h>

namespace volsg {

class Camera;

struct RenderOptions {
    int width = 512;
    int height = 512;
    glm::vec3 background{0.0f};
    bool interactive = false;  ///< the user is moving the view: volumes use their fast settings
    ref_ptr<Camera> camera;    ///< overrides the scene's camera when set (model matrix = identity)
};

/// Holds the GL resources (programs, meshes, targets) of one context across frames. Create
/// and use it with that context current.
class Renderer {
public:
    Renderer();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    /// Renders offscreen and reads the linear float result back.
    Image render(Node& root, const RenderOptions& options);
    /// Renders into the framebuffer bound now (a window's back buffer), same image.
    void renderToBoundFramebuffer(Node& root, const RenderOptions& options);

    struct Impl;

private:
    std::unique_ptr<Impl> impl_;
};

/// The camera a render of this scene uses: the first Camera in traversal order with the model
/// matrix above it, or, without one, a PerspectiveCamera that views the whole bounding box from
/// +Z (model matrix identity).
struct SceneCamera {
    ref_ptr<Camera> camera;
    glm::dmat4 model{1.0};
};
SceneCamera findOrMakeCamera(Node& root, double viewportAspect);

} // namespace volsg
