// The viewer's saving: the view into the scene's camera (or a new one), the scene written by
// rewriting only what changed in its file (SceneTextSave.h), Save As, and unique screenshot
// names.
#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "Viewer.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <glm/gtc/quaternion.hpp>

#include <volsg/actions/SearchAction.h>
#include <volsg/context/GlfwWindow.h>
#include <volsg/core/Error.h>
#include <volsg/io/AtomicFile.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/manipulators/DragMath.h>
#include <volsg/nodes/Camera.h>
#include <volsg/render/Renderer.h>

namespace volsg {

std::string uniqueScreenshotName(const std::string& folder) {
    for (int n = 1;; ++n) {
        const std::filesystem::path path =
            std::filesystem::path(folder) / ("volsg-view-" + std::to_string(n) + ".png");
        std::error_code ec;
        if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec)))
            return path.string();
    }
}

void Viewer::takeSceneText() {
    sceneText_.reset();
    std::ifstream in(options_.scenePath, std::ios::binary);
    if (!in) return;
    std::stringstream text;
    text << in.rdbuf();
    sceneText_ = SceneTextSnapshot::take(text.str(), *root_);
}

void Viewer::writeViewToSceneCamera() {
    const Camera& view = navigation_->camera();
    if (findAll(*root_, Camera::classType()).empty()) {
        // A scene without a camera gets the view as its first node, so that it opens as it was
        // saved. (A root that is not a group cannot hold one: the view is not saved then.)
        auto* children = root_->children();
        if (!children) {
            status("the scene's root is not a group: the view is not saved");
            return;
        }
        ref_ptr<Camera> camera;
        if (dynamic_cast<const OrthographicCamera*>(&view))
            camera = OrthographicCamera::create();
        else
            camera = PerspectiveCamera::create();
        children->insert(children->begin(), camera);
    }
    const SceneCamera scene = findOrMakeCamera(*root_, 1.0);
    Camera& target = *scene.camera;
    // World pose back into the camera's own coordinates (a rigid model matrix above it).
    const glm::dmat4 toLocal = glm::inverse(scene.model);
    const glm::dmat3 m(toLocal);
    const glm::dquat turn = glm::quat_cast(
        glm::dmat3(glm::normalize(m[0]), glm::normalize(m[1]), glm::normalize(m[2])));
    const auto set = [](auto& field, const auto& value) { // unchanged fields stay as read
        if (field() != value) field = value;
    };
    set(target.position, glm::vec3(toLocal * glm::dvec4(glm::dvec3(view.position()), 1.0)));
    const Rotation rotation = rotationFromQuat(turn * view.orientation().quat());
    if (glm::abs(glm::dot(target.orientation().quat(), glm::dquat(rotation.quat()))) < 1.0 - 1e-12)
        target.orientation = rotation;
    set(target.focalDistance, view.focalDistance());
    set(target.nearDistance, view.nearDistance());
    set(target.farDistance, view.farDistance());
    if (auto* p = dynamic_cast<PerspectiveCamera*>(&target))
        if (auto* v = dynamic_cast<const PerspectiveCamera*>(&view))
            set(p->heightAngle, v->heightAngle());
    if (auto* o = dynamic_cast<OrthographicCamera*>(&target))
        if (auto* v = dynamic_cast<const OrthographicCamera*>(&view)) set(o->height, v->height());
}

void Viewer::saveScene(const std::string& path) {
    std::vector<ref_ptr<Node>> originals;
    for (Attached& a : manipulators_)
        originals.emplace_back(a.manipulator->original());
    detachAll(); // the file holds the plain nodes, as Inventor's manipulators leave them
    try {
        writeViewToSceneCamera();
        // Only what changed, when the file on disk is still the one that was read.
        std::string reason = "the scene was not read from a text file";
        std::optional<std::string> text;
        if (sceneText_) {
            std::ifstream in(options_.scenePath, std::ios::binary);
            std::stringstream now;
            now << in.rdbuf();
            if (now.str() != sceneText_->text())
                reason = options_.scenePath + " changed on disk since it was read";
            else
                text = sceneText_->patched(*root_, reason);
        }
        if (text) {
            writeFileAtomically(path, *text);
            status("saved " + path + " (changed values only; comments and layout kept)");
        } else {
            writeSceneToFile(path, *root_);
            status("saved " + path + " (whole scene written: " + reason + ")");
        }
        if (path != options_.scenePath) { // Save As: from now on this is the scene's file
            options_.scenePath = path;
            glfwSetWindowTitle(window_->handle(), ("volsg-view " + path).c_str());
        }
        takeSceneText();
        savedChangeCount_ = history_.changeCount(); // nothing unsaved now
    } catch (const Error& e) {
        status(std::string("saving failed: ") + e.what());
        exitStatus_ = 1;
    }
    reattach(originals);
    std::error_code ec;
    sceneTime_ = std::filesystem::last_write_time(options_.scenePath, ec);
}

} // namespace volsg
