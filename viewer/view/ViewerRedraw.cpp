// Not drawing the same still image twice: the signature of what the views show (every node's
// version, the camera, the window and the view settings) and a copy of the window's views
// kept from the last still frame.
#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "Viewer.h"

#include <algorithm>
#include <cstring>
#include <unordered_set>

#include <volsg/context/GlfwWindow.h>
#include <volsg/nodes/Camera.h>

namespace volsg {

namespace {

/// The newest version among the nodes of `root` and how many there are (each once).
void scanNodes(const Node& root, std::uint64_t& newest, std::size_t& count) {
    std::unordered_set<const Node*> seen;
    std::vector<const Node*> stack{&root};
    while (!stack.empty()) {
        const Node* node = stack.back();
        stack.pop_back();
        if (!node || !seen.insert(node).second) continue;
        newest = std::max(newest, node->version());
        ++count;
        if (const auto* children = node->children())
            for (const auto& child : *children)
                stack.push_back(child.get());
    }
}

bool sameRects(const WindowLayout& a, const WindowLayout& b) {
    return a.panels == b.panels && a.viewCount == b.viewCount && a.views == b.views;
}

} // namespace

bool Viewer::ViewSignature::operator==(const ViewSignature& o) const {
    return !alwaysDraw && !o.alwaysDraw && newestNode == o.newestNode && nodes == o.nodes &&
           window == o.window && sameRects(layout, o.layout) && camera == o.camera &&
           cursor == o.cursor && cursorShown == o.cursorShown && flipped == o.flipped &&
           patientAxes == o.patientAxes && antialias == o.antialias && stereo == o.stereo &&
           eyeSeparation == o.eyeSeparation && background == o.background;
}

Viewer::ViewSignature Viewer::viewSignature() const {
    ViewSignature s;
    scanNodes(*root_, s.newestNode, s.nodes);
    if (sections_.valid())
        for (int v = 0; v < 3; ++v) // the section graphs' own slices (the cursor's planes)
            scanNodes(sections_.graph(v), s.newestNode, s.nodes);
    s.window = window_->size();
    s.layout = layout();
    const Camera& c = navigation_->camera();
    const glm::dquat q = c.orientation().quat();
    s.camera = {c.position().x,
                c.position().y,
                c.position().z,
                float(q.w),
                float(q.x),
                float(q.y),
                float(q.z),
                c.focalDistance(),
                c.nearDistance(),
                c.farDistance(),
                float(c.type().name()[0])};
    if (const auto* p = dynamic_cast<const PerspectiveCamera*>(&c))
        s.camera.push_back(p->heightAngle());
    if (const auto* o = dynamic_cast<const OrthographicCamera*>(&c))
        s.camera.push_back(o->height());
    s.cursor = sections_.valid() ? sections_.cursor() : glm::ivec3(0);
    s.cursorShown = cursorSet_;
    s.flipped = sections_.flipped();
    s.patientAxes = patientAxes_.localToRas();
    s.antialias = int(options_.antialias);
    s.stereo = int(options_.stereo.mode);
    s.eyeSeparation = options_.stereo.separationFraction;
    s.background = options_.background;
    // A playing or prefetching series changes what shows without an edit: always drawn.
    s.alwaysDraw = seriesPanel_.active();
    return s;
}

void Viewer::keepViews() {
    const glm::ivec2 size = window_->size();
    if (size != keptViewsSize_) {
        keptViewsColor_ = Renderbuffer(GL_RGBA8, size.x, size.y);
        keptViews_ = Framebuffer::create();
        keptViews_.attach(GL_COLOR_ATTACHMENT0, keptViewsColor_);
        keptViews_.requireComplete("kept views");
        keptViewsSize_ = size;
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    keptViews_.bind(GL_DRAW_FRAMEBUFFER);
    glBlitFramebuffer(0, 0, size.x, size.y, 0, 0, size.x, size.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

bool Viewer::restoreViews() {
    const glm::ivec2 size = window_->size();
    if (size != keptViewsSize_ || !keptViews_) return false;
    keptViews_.bind(GL_READ_FRAMEBUFFER);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, size.x, size.y, 0, 0, size.x, size.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, size.x, size.y);
    return true;
}

} // namespace volsg
