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
#include <volsg/editors/FileBrowser.h>
#include <volsg/editors/MaterialEditor.h>
#include <volsg/editors/PlaneOpacityEditor.h>
#include <volsg/editors/RegionHistogram.h>
#include <volsg/editors/TransferFunctionEditor.h>
#include <volsg/editors/panels/FieldPanel.h>
#include <volsg/editors/panels/FileBrowserPanel.h>
#include <volsg/editors/panels/RegionHistogramPanel.h>
#include <volsg/editors/panels/TransferFunctionPanel.h>
#include <volsg/engines/Evaluator.h>
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
#include "PatientOrientation.h"
#include "RecentFiles.h"
#include "SceneTextSave.h"
#include "SectionViews.h"
#include "SeriesPanel.h"
#include "ViewModes.h"
#include "ViewerScript.h"
#include "WindowLayout.h"

struct ImDrawList;

namespace volsg {

class GlfwWindow;
class Renderer;

/// `volsg-view-N.png` in `folder` with N the first number whose file does not exist: a
/// screenshot never overwrites one.
std::string uniqueScreenshotName(const std::string& folder);

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
    /// Files dropped on the window (GLFW's drop callback, or the script's `drop`): the first
    /// opens as the open dialog would open it.
    void onDrop(const std::vector<std::string>& paths);

private:
    enum class Drag {
        None,
        Pending,
        Rotate,
        Pan,
        Dolly,
        Manipulator,
        ActiveObject,
        Walk,
        Tilt,
        SectionPending, ///< pressed in a section view: a click (cursor) or window/level
        WindowLevel,
    };
    using ViewRect = PixelRect;       ///< a view's place in the window (WindowLayout)
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

    /// Opening a file, from the command line, the open dialog, a drop, the recent files or the
    /// script: reads it (SceneForFile.h), and only when that worked replaces the scene, as a
    /// fresh start of the viewer on it would (camera, panels, history, cursor, patient axes
    /// from the file's geometry), and puts it first in the recent files. Throws Error (naming
    /// the file) and keeps the old scene when the file cannot be read.
    void openFile(const std::string& path, const OpenFileOptions& open);
    /// openFile for the UI: a scene with unsaved edits asks first (save, discard or cancel);
    /// a failure is one status line naming the file.
    void requestOpen(const std::string& path, const OpenFileOptions& open);
    /// Opens what requestOpen asked for (at the start of a frame).
    void openRequested();
    /// A raw file (no layout in its name) opens through the dialog's layout form.
    void requestOpenOrAskLayout(const std::string& path);
    /// Edits since the scene was opened or saved.
    bool sceneEdited() const { return history_.changeCount() != savedChangeCount_; }
    void showOpenDialog(const std::string& selectPath = {});
    void openFromDialog(const std::string& path);
    void drawOpenDialog();
    void drawUnsavedQuestion();
    void answerUnsavedQuestion(int answer); ///< 0 cancel, 1 save then open, 2 discard
    void drawMenuBar();
    void openRecent(int index); ///< index into recent_.entries()
    /// The patient axes from the first volume's file geometry (the convention without one),
    /// keeping the user's reversals.
    void patientAxesFromData();
    void loadScene();
    /// One frame with `message` in the middle of the window (before the scene can be drawn).
    void showMessageFrame(const std::string& message);
    /// "loading FILE (N MB)..." for the scene's volume files.
    std::string loadingMessage() const;
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
    /// Where the panel column and the views are this frame (WindowLayout).
    WindowLayout layout() const;
    ViewRect viewRect(int view) const;
    int viewAt(const glm::dvec2& pixel) const; ///< -1 outside every view
    void renderViews();
    /// What the views show: when it is the same as for the last still frame, the views are
    /// not drawn again (ViewerRedraw.cpp).
    struct ViewSignature {
        std::uint64_t newestNode = 0; ///< the largest node version in the scene (edits raise it)
        std::size_t nodes = 0;
        glm::ivec2 window{0};
        WindowLayout layout;
        std::vector<float> camera; ///< the 3D camera's fields
        glm::ivec3 cursor{0};
        bool cursorShown = false, flipped = false;
        glm::dmat3 patientAxes{1.0};
        int antialias = 0, stereo = 0;
        double eyeSeparation = 0.0;
        glm::vec3 background{0.0f};
        bool alwaysDraw = false; ///< never equal: something changes without an edit
        bool operator==(const ViewSignature&) const;
    };
    ViewSignature viewSignature() const;
    /// Copies the window's freshly drawn views aside, or back into the window (false when there
    /// is nothing of this size to copy back).
    void keepViews();
    bool restoreViews();
    /// Renders `root` seen by options.camera into `rect` of the window at `scale` times its size
    /// (2: 2x2 supersampling; below 1: a coarse frame scaled up), multisampled as
    /// options.samples says; the 3D view goes through the stereo renderer when stereo is on.
    void renderIntoRect(Node& root, RenderOptions options, const ViewRect& rect, double scale,
                        bool stereo);
    void drawImageIntoRect(const Image& image, const ViewRect& rect);
    void drawViewOverlays();
    void drawAxesMarker(ImDrawList* draw, const ViewRect& view);
    void drawScaleBar(ImDrawList* draw, const ViewRect& view);
    /// The 3D view's world units per pixel at the camera's focal distance.
    double worldUnitsPerPixel() const;
    /// A patient direction (RAS) in world coordinates: through the patient axes and the first
    /// volume's model matrix.
    glm::dvec3 patientDirectionInWorld(const glm::dvec3& ras) const;
    /// The 3D camera looks at the scene from that side of the patient (view all).
    void setAnatomicalView(AnatomicalView view);
    void setPatientAxes(const PatientAxes& axes);
    void setLayout(ViewLayout layout);
    void setNavigationMode(NavigationMode mode);
    void stepNavigation();
    void attachSections();
    void followSceneEdits();
    void setCursor(const glm::ivec3& voxel);
    void setCursorFromPick(const Ray& ray);
    void updateRegion();
    void drawPanels();
    /// A collapsible section of the panel column; opens (and scrolls to) it when the script
    /// asked for `scriptName`. Returns whether it is open.
    bool panelSection(const char* title, bool& open, const char* scriptName);
    void drawScenePanel();
    void drawVolumeQuality();
    void drawViewControls();
    void drawOrientationControls();
    void drawSceneTree(Node& node, int depth);
    /// Saves to `path` (the scene's own file, or another: Save As, after which saves go there):
    /// only the changed parts of the file's text are rewritten (SceneTextSave.h), else the
    /// whole scene; the view goes into the scene's first camera, or a new one.
    void saveScene(const std::string& path);
    void writeViewToSceneCamera();
    /// The snapshot of the scene file's text, taken when it is read (and after each save).
    void takeSceneText();
    void screenshot(const std::string& path, bool sceneOnly);
    void checkReload();
    Box3 sceneBox();
    bool isInteracting() const;
    void status(const std::string& message);

    ViewerOptions options_;
    std::unique_ptr<GlfwWindow> window_;
    std::unique_ptr<Renderer> renderer_;
    ref_ptr<Node> root_;
    ConnectionEvaluator
        engines_; ///< engines, connections and animated nodes, on the viewer's clock
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
    int dragView_ = 0; ///< the view the drag started in
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

    std::optional<ViewSignature> lastShown_; ///< of the still frame in keptViews_
    bool idle_ = false;                      ///< the last frame drew nothing new
    long long framesTotal_ = 0, framesDrawn_ = 0;
    Framebuffer keptViews_; ///< the window's views as last drawn still
    Renderbuffer keptViewsColor_;
    glm::ivec2 keptViewsSize_{0};
    Framebuffer viewTarget_; ///< a view drawn off the window, then copied into its rectangle
    Renderbuffer viewColor_;
    glm::ivec2 viewTargetSize_{0};
    Texture stereoImage_; ///< a stereo image on its way into the window
    Framebuffer stereoSource_;
    double lastFrameMs_ = 0.0;
    double lastRenderMs_ = 0.0;
    std::string statusText_;
    std::string progressText_; ///< shown in the 3D view while loading or refining
    /// The first image of a scene is drawn at this fraction of the 3D view's width and height
    /// (with the volumes' interactive planes), the next one in full.
    static constexpr double kFirstImageResolution = 0.25;
    int refineStage_ = 0; ///< frames since the scene was loaded, up to 2
    std::chrono::steady_clock::time_point startTime_; ///< of the viewer, then of the last open
    double sceneSeconds_ = 0.0; ///< the scene time of this frame (engines_, on the viewer's clock)
    bool sceneChanges_ = false; ///< engines or animated nodes have changed a field
    PatientAxes patientAxes_;   ///< how the first volume's axes run in patient coordinates
    std::map<std::string, std::pair<glm::vec2, glm::vec2>> canvases_; ///< scripted UI places
    /// Which sections of the panel column are open; `revealPanel_` names one the script opened
    /// (it is opened and scrolled into view on the next frame).
    bool showScene_ = true, showTf_ = true, showPlane_ = false, showMaterial_ = false,
         showFields_ = false, showRegion_ = false;
    std::string revealPanel_;
    std::optional<SceneTextSnapshot> sceneText_;
    char saveAsPath_[512] = "";

    // Opening files (ViewerOpening.cpp).
    RecentFiles recent_{RecentFiles::defaultPath()};
    FileBrowser browser_{openableFileSuffixes()};
    FileBrowserPanelState browserPanel_;
    bool openDialogRequested_ = false, openDialogShown_ = false;
    std::string dialogError_;
    struct RawForm {
        bool use = false; ///< open the file as raw voxels with this layout
        int dimensions[3] = {0, 0, 0};
        int type = 0; ///< VoxelType
        float spacing[3] = {1.0f, 1.0f, 1.0f};
        bool bigEndian = false;
        int headerSkip = 0;
    } rawForm_;
    std::optional<std::pair<std::string, OpenFileOptions>> pendingOpen_; ///< awaiting an answer
    std::optional<std::pair<std::string, OpenFileOptions>> openNext_;    ///< at the next frame
    bool unsavedQuestionRequested_ = false;
    std::uint64_t savedChangeCount_ = 0;
    std::vector<std::string> dropped_;
    std::vector<std::pair<int, int>> scriptKeys_; ///< keys (and mods) the script pressed
    std::vector<int> scriptKeysDown_;             ///< released in ImGui on the next frame
    std::string scriptTyped_;                     ///< characters the script typed
    std::string errorLine_; ///< a failed open, over the 3D view until the next open
};

} // namespace volsg
