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
#include <volsg/editors/RegionHistogram.h>
#include <volsg/editors/TransferFunctionEditor.h>
#include <volsg/editors/panels/FieldPanel.h>
#include <volsg/editors/panels/RegionHistogramPanel.h>
#include <volsg/editors/panels/TransferFunctionPanel.h>
#include <volsg/gl/Framebuffer.h>
#include <volsg/gl/Renderbuffer.h>
#include <volsg/gl/Texture.h>
#include <volsg/manipulators/ExaminerNavigation.h>
#include <volsg/manipulators/FlyNavigation.h>
#include <volsg/manipulators/Manipulator.h>
#include <volsg/manipulators/WalkNavigation.h>
#include <volsg/math/Box3.h>
#include <volsg/render/StereoRenderer.h>
#include <volsg/volumescene/SceneForFile.h>

#include "InteractiveQuality.h"
#include "SectionViews.h"
#include "SeriesPanel.h"
#include "ViewModes.h"
#include "ViewerScript.h"

namespace volsg {

class GlfwWindow;
class Renderer;

struct ViewerOptions {
    std::string scenePath;  ///< a scene file, or any data file volsg opens (SceneForFile.h)
    OpenFileOptions open;   ///< what a raw data file cannot say about itself
    std::string scriptPath; ///< empty: interactive only
    int width = 1280, height = 800;
    glm::vec3 background{0.1f, 0.1f, 0.12f};
    Antialias antialias = Antialias::Off; ///< of the 3D view
    double seekTime = 0.5; ///< seconds a seek flies (Inventor's SoSeekTime); 0: at once
    bool panels = true;    ///< the editor panels (F1 toggles them)
    ViewLayout layout = ViewLayout::Single;
    NavigationMode navigation = NavigationMode::Examiner;
    StereoOptions stereo{StereoMode::Off}; ///< of the 3D view
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
    enum class Drag { None, Pending, Rotate, Pan, Dolly, Manipulator, ActiveObject, Walk, Tilt };
    /// A view's place in the window: pixels, origin top-left.
    struct ViewRect {
        int x = 0, y = 0, width = 1, height = 1;
        bool contains(const glm::dvec2& p) const {
            return p.x >= x && p.y >= y && p.x < x + width && p.y < y + height;
        }
    };
    static constexpr int kView3D = 0; ///< views: 0 the 3D view, 1 + SectionViews::Section
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
    ViewRect viewRect(int view) const;
    int viewAt(const glm::dvec2& pixel) const; ///< -1 outside every view
    void renderViews();
    /// Renders `root` seen by options.camera into `rect` of the window (supersampled when
    /// `antialias`, else as options.samples says); the 3D view goes through the stereo renderer
    /// when stereo is on.
    void renderIntoRect(Node& root, RenderOptions options, const ViewRect& rect, bool antialias,
                        bool stereo);
    void drawImageIntoRect(const Image& image, const ViewRect& rect);
    void drawViewOverlays();
    void setLayout(ViewLayout layout);
    void setNavigationMode(NavigationMode mode);
    void stepNavigation();
    void attachSections();
    void followSceneEdits();
    void setCursor(const glm::ivec3& voxel);
    void setCursorFromPick(const Ray& ray);
    void updateRegion();
    void drawPanels();
    void drawViewControls();
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
    std::unique_ptr<FlyNavigation> fly_;   ///< on navigation_'s camera while flying
    std::unique_ptr<WalkNavigation> walk_; ///< on navigation_'s camera while walking
    std::chrono::steady_clock::time_point lastNavigationStep_{};
    SectionViews sections_;
    bool cursorSet_ = false; ///< a click (or the script) placed the cursor
    std::optional<RegionHistogram> region_;
    RegionHistogramPanelState regionPanel_;
    InteractiveQuality quality_;
    SeriesPanel seriesPanel_; ///< the first VolumeSeries of the scene
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

    Framebuffer viewTarget_; ///< a view drawn off the window, then copied into its rectangle
    Renderbuffer viewColor_;
    glm::ivec2 viewTargetSize_{0};
    Texture stereoImage_; ///< a stereo image on its way into the window
    Framebuffer stereoSource_;
    double lastFrameMs_ = 0.0;
    double lastRenderMs_ = 0.0;
    std::string statusText_;
    std::map<std::string, std::pair<glm::vec2, glm::vec2>> canvases_; ///< scripted UI places
    bool showTf_ = true, showPlane_ = true, showMaterial_ = true, showFields_ = true,
         showRegion_ = true;
    int screenshotCount_ = 0;
};

} // namespace volsg
