#pragma once
// volsg-view: a GLFW window showing a scene with examiner navigation, manipulators, the editor
// panels and an input-script player (viewer/view/ViewerScript.h).

#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/core/Node.h>
#include <volsg/editors/ActiveObjectDrag.h>
#include <volsg/editors/EditHistory.h>
#include <volsg/editors/FieldPanelModel.h>
#include <volsg/editors/MaterialEditor.h>
#include <volsg/editors/PlaneOpacityEditor.h>
#include <volsg/editors/TransferFunctionEditor.h>
#include <volsg/editors/panels/FieldPanel.h>
#include <volsg/editors/panels/TransferFunctionPanel.h>
#include <volsg/gl/Framebuffer.h>
#include <volsg/gl/Renderbuffer.h>
#include <volsg/manipulators/ExaminerNavigation.h>
#include <volsg/manipulators/Manipulator.h>
#include <volsg/math/Box3.h>

#include "InteractiveQuality.h"
#include "ViewerScript.h"

namespace volsg {

class GlfwWindow;
class Renderer;

struct ViewerOptions {
    std::string scenePath;
    std::string scriptPath; ///< empty: interactive only
    int width = 1280, height = 800;
    glm::vec3 background{0.1f, 0.1f, 0.12f};
    bool antialias = false; ///< 2x2 supersampling of the scene
    bool panels = true;     ///< the editor panels (F1 toggles them)
};

class Viewer {
public:
    explicit Viewer(ViewerOptions options);
    ~Viewer();
    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    /// Runs until the window closes or the script says quit; returns the exit status.
    int run();

    // Input, from GLFW callbacks or the script player.
    void onMouseMove(glm::dvec2 position);
    void onMouseButton(int button, bool pressed, int mods);
    void onScroll(double dy);
    void onKey(int key, int mods);

private:
    enum class Drag { None, Pending, Rotate, Pan, Dolly, Manipulator, ActiveObject };
    struct Attached {
        ref_ptr<Node> node; ///< the manipulator
        Manipulator* manipulator = nullptr;
        std::uint64_t originalVersion = 0;
    };
    struct PendingEvent {
        enum class Kind { Move, Button, Scroll, Key } kind;
        glm::dvec2 position{0.0};
        int button = 0, mods = 0, key = 0;
        bool pressed = false;
        double scroll = 0.0;
    };

    void loadScene();
    void setupCamera();
    void frame();
    void runScriptStep();
    glm::dvec2 resolvePoint(const ScriptPoint& point) const;
    void handleSceneEvents();
    void beginSceneDrag(int button, int mods);
    void continueSceneDrag();
    void endSceneDrag();
    void select(Node* node);
    void toggleManipulator();
    void detachAll();
    void reattach(const std::vector<ref_ptr<Node>>& originals);
    void syncManipulators();
    void renderScene(int width, int height);
    void drawPanels();
    void drawSceneTree(Node& node, int depth);
    void saveScene(const std::string& path);
    void writeViewToSceneCamera();
    void screenshot(const std::string& path, bool sceneOnly);
    void checkReload();
    Box3 sceneBox();
    bool isInteracting() const;
    void status(const std::string& message);

    ViewerOptions options_;
    std::unique_ptr<GlfwWindow> window_;
    std::unique_ptr<Renderer> renderer_;
    ref_ptr<Node> root_;
    std::filesystem::file_time_type sceneTime_{};
    std::chrono::steady_clock::time_point lastReloadCheck_{};

    std::unique_ptr<ExaminerNavigation> navigation_;
    InteractiveQuality quality_;
    EditHistory history_;
    TransferFunctionEditor tfEditor_{history_};
    TransferFunctionPanelState tfPanel_;
    PlaneOpacityEditor planeEditor_{history_};
    CurveCanvasState planePanel_;
    MaterialEditor materialEditor_{history_};
    FieldPanelModel fieldPanel_{history_};
    FieldPanelState fieldPanelState_;
    ActiveObjectDrag activeDrag_{history_};
    std::vector<Attached> manipulators_;

    ref_ptr<Node> selected_;
    Drag drag_ = Drag::None;
    int dragButton_ = -1;
    Manipulator* draggedManipulator_ = nullptr;
    glm::dvec2 mouse_{0.0}, dragStart_{0.0}, lastMouse_{0.0};
    bool buttons_[3] = {false, false, false};
    bool justPressed_[3] = {false, false, false};
    double pendingScroll_ = 0.0;
    int mods_ = 0;
    bool seekMode_ = false;
    std::vector<PendingEvent> events_;

    std::vector<ScriptStep> script_;
    std::size_t scriptNext_ = 0;
    int scriptWait_ = 0;
    bool quit_ = false;
    int exitStatus_ = 0;

    Framebuffer supersampleTarget_;
    Renderbuffer supersampleColor_;
    glm::ivec2 supersampleSize_{0};
    double lastFrameMs_ = 0.0;
    double lastRenderMs_ = 0.0;
    std::string statusText_;
    std::map<std::string, std::pair<glm::vec2, glm::vec2>> canvases_; ///< scripted UI places
    bool showTf_ = true, showPlane_ = true, showMaterial_ = true, showFields_ = true;
    int screenshotCount_ = 0;
};

} // namespace volsg
