// glad first; GLFW must not include a GL header of its own.
#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "Viewer.h"
#include "VolumeReport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <glm/gtc/quaternion.hpp>

#include <volsg/actions/BoundingBoxAction.h>
#include <volsg/actions/PickAction.h>
#include <volsg/actions/SearchAction.h>
#include <volsg/context/GlfwWindow.h>
#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>
#include <volsg/editors/ScenePicker.h>
#include <volsg/editors/panels/MaterialPanel.h>
#include <volsg/editors/panels/PlaneOpacityPanel.h>
#include <volsg/image/Image.h>
#include <volsg/io/RegularFile.h>
#include <volsg/io/SceneReader.h>
#include <volsg/io/SceneWriter.h>
#include <volsg/manipulators/BoxClipManip.h>
#include <volsg/manipulators/ClipPlaneManip.h>
#include <volsg/manipulators/DragMath.h>
#include <volsg/manipulators/TransformManip.h>
#include <volsg/nodes/BoxClip.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/OrthoSlice.h>
#include <volsg/nodes/Shape.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/Transform.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/nodes/VolumeSeries.h> // complete for SeriesPanel's ref_ptr
#include <volsg/render/Renderer.h>
#include <volsg/voxelfile/VoxelFileScene.h>

namespace volsg {

namespace {

constexpr double kClickSlop = 3.0; // pixels a press may move and still be a click

Viewer* viewerOf(GLFWwindow* w) {
    return static_cast<Viewer*>(glfwGetWindowUserPointer(w));
}

std::string readText(const std::string& path) {
    regularFileSize(path, "cannot read", limits::maxSceneFileSize); // never open a FIFO
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error("cannot open '" + path + "'");
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// The plain node a manipulator stands in for, or the node itself.
Node* originalOf(Node* node) {
    if (auto* m = dynamic_cast<Manipulator*>(node))
        if (m->original()) return m->original();
    return node;
}

std::vector<Field*> textFieldsOf(Node& node) {
    std::vector<Field*> out;
    for (std::size_t i = 0; i < node.fieldCount(); ++i)
        out.push_back(node.fieldAt(i));
    return out;
}

} // namespace

Viewer::Viewer(ViewerOptions options)
    : options_(std::move(options)), startTime_(std::chrono::steady_clock::now()) {
    if (!options_.scriptPath.empty())
        script_ = parseViewerScript(readText(options_.scriptPath), options_.scriptPath);
    // The file is told apart before a window opens, so a file volsg cannot open is one line
    // on the terminal and no window.
    fileKindOf(options_.scenePath, options_.open);

    GlfwWindowOptions windowOptions;
    windowOptions.width = options_.width;
    windowOptions.height = options_.height;
    windowOptions.title = "volsg-view " + options_.scenePath;
    window_ = std::make_unique<GlfwWindow>(windowOptions);
    glfwSwapInterval(0);
    renderer_ = std::make_unique<Renderer>();

    GLFWwindow* w = window_->handle();
    glfwSetWindowUserPointer(w, this);
    glfwSetCursorPosCallback(w, [](GLFWwindow* win, double x, double y) {
        viewerOf(win)->onMouseMove({x, y});
    });
    glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int button, int action, int mods) {
        viewerOf(win)->onMouseButton(button, action == GLFW_PRESS, mods);
    });
    glfwSetScrollCallback(w,
                          [](GLFWwindow* win, double, double dy) { viewerOf(win)->onScroll(dy); });
    glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int, int action, int mods) {
        if (action == GLFW_PRESS || action == GLFW_REPEAT) viewerOf(win)->onKey(key, mods);
    });
    glfwSetDropCallback(w, [](GLFWwindow* win, int count, const char** paths) {
        viewerOf(win)->onDrop(std::vector<std::string>(paths, paths + std::max(count, 0)));
    });

    // ImGui chains to the callbacks above (installed first).
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr; // the same layout on every run (and in tests)
    ImGui::GetIO().ConfigWindowsMoveFromTitleBarOnly = true; // drags in a panel never move it
    ImGui::StyleColorsDark();
    if (!ImGui_ImplGlfw_InitForOpenGL(w, true) || !ImGui_ImplOpenGL3_Init("#version 330 core"))
        throw Error("Dear ImGui could not start on this GL context");

    recent_.load();
    openFile(options_.scenePath, options_.open); // the same as opening it later
}

Viewer::~Viewer() {
    window_->makeCurrent();
    detachAll();
    viewTarget_ = Framebuffer();
    viewColor_ = Renderbuffer();
    stereoSource_ = Framebuffer();
    stereoImage_ = Texture();
    renderer_.reset();
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void Viewer::loadScene() {
    refineStage_ = 0; // a new scene: a coarse first image, then the full one
    manipulators_.clear();
    history_.clear();
    savedChangeCount_ = history_.changeCount();
    activeDrag_.end();
    select(nullptr);
    tfEditor_.setScene(root_.get());
    // The plane-opacity editor starts on the first volume, so it shows something at once.
    const auto volumes = findAll(*root_, Volume::classType());
    planeEditor_.setVolume(volumes.empty() ? nullptr : static_cast<Volume*>(volumes.front()));
    attachSections();
    patientAxesFromData();
    seriesPanel_.attach(root_.get());
}

void Viewer::setupCamera() {
    const ViewRect view = viewRect(kView3D);
    const double aspect = double(view.width) / double(view.height);
    SceneCamera scene = findOrMakeCamera(*root_, aspect);
    // A copy in world coordinates: navigation never changes the scene until it is saved.
    const bool sceneHasCamera = !findAll(*root_, Camera::classType()).empty();
    const ref_ptr<Camera> camera = sceneHasCamera ? worldSpaceCamera(scene) : scene.camera;
    navigation_ = std::make_unique<ExaminerNavigation>(camera, view.width, view.height);
    navigation_->adjustClipping(sceneBox());
    navigation_->saveHome();
}

Box3 Viewer::sceneBox() {
    try {
        return computeBoundingBox(*root_);
    } catch (const Error&) {
        return Box3{};
    }
}

void Viewer::status(const std::string& message) {
    statusText_ = message;
    std::fprintf(stderr, "volsg-view: %s\n", message.c_str());
}

// ---- input ----------------------------------------------------------------------------------

void Viewer::onMouseMove(glm::dvec2 position) {
    events_.push_back({PendingEvent::Kind::Move, position});
}

void Viewer::onMouseButton(int button, bool pressed, int mods) {
    PendingEvent e{PendingEvent::Kind::Button, mouse_};
    e.button = button;
    e.pressed = pressed;
    e.mods = mods;
    events_.push_back(e);
}

void Viewer::onScroll(double dy) {
    PendingEvent e{PendingEvent::Kind::Scroll, mouse_};
    e.scroll = dy;
    events_.push_back(e);
}

void Viewer::onKey(int key, int mods) {
    PendingEvent e{PendingEvent::Kind::Key, mouse_};
    e.key = key;
    e.mods = mods;
    events_.push_back(e);
}

bool Viewer::isInteracting() const {
    if (drag_ != Drag::None && drag_ != Drag::Pending && drag_ != Drag::SectionPending) return true;
    if (fly_ && fly_->speed() != 0.0) return true;            // the view moves every frame
    if (navigation_ && navigation_->isSeeking()) return true; // the seek flies every frame
    // Dragging in an editor canvas or on a slider counts too: the render should keep up.
    return ImGui::GetCurrentContext() && ImGui::IsAnyItemActive() && ImGui::IsMouseDown(0);
}

void Viewer::handleSceneEvents() {
    const ImGuiIO& io = ImGui::GetIO();
    for (const PendingEvent& e : events_) {
        switch (e.kind) {
        case PendingEvent::Kind::Move:
            break;
        case PendingEvent::Kind::Button:
            if (e.pressed && drag_ == Drag::None && !io.WantCaptureMouse) {
                mouse_ = e.position;
                const int view = viewAt(mouse_);
                if (view > kView3D && e.button == GLFW_MOUSE_BUTTON_LEFT) {
                    // A section view: a click moves the cursor there, a drag is window/level.
                    drag_ = Drag::SectionPending;
                    dragView_ = view;
                    dragButton_ = e.button;
                    dragStart_ = lastMouse_ = mouse_;
                } else if (view == kView3D) {
                    beginSceneDrag(e.button, e.mods);
                }
            } else if (!e.pressed && e.button == dragButton_) {
                endSceneDrag();
            }
            break;
        case PendingEvent::Kind::Scroll:
            if (io.WantCaptureMouse) break;
            if (const int view = viewAt(e.position); view > kView3D) {
                // Over a section view: the wheel steps its plane through the volume.
                glm::ivec3 voxel = sections_.cursor();
                voxel[sections_.axisOf(view - 1)] += e.scroll > 0.0 ? 1 : -1;
                setCursor(voxel);
                break;
            }
            if (glfwGetKey(window_->handle(), GLFW_KEY_LEFT_CONTROL) == GLFW_PRESS)
                navigation_->zoom(std::pow(0.9, e.scroll)); // the view angle, not the distance
            else
                navigation_->dolly(std::pow(0.9, e.scroll));
            break;
        case PendingEvent::Kind::Key:
            if (!io.WantCaptureKeyboard) {
                const bool ctrl = (e.mods & GLFW_MOD_CONTROL) != 0;
                const bool shift = (e.mods & GLFW_MOD_SHIFT) != 0;
                switch (e.key) {
                case GLFW_KEY_S:
                    if (ctrl)
                        saveScene(scenePathForSaving(options_.scenePath, options_.open));
                    else
                        seekMode_ = !seekMode_;
                    break;
                case GLFW_KEY_Z:
                    if (ctrl)
                        (shift ? history_.redo() : history_.undo());
                    else
                        navigation_->zoom(0.8);
                    break;
                case GLFW_KEY_X:
                    navigation_->zoom(1.25);
                    break;
                case GLFW_KEY_Y:
                    if (ctrl) history_.redo();
                    break;
                case GLFW_KEY_V:
                    navigation_->viewAll(sceneBox());
                    break;
                case GLFW_KEY_H:
                    navigation_->goHome();
                    break;
                case GLFW_KEY_O:
                    if (ctrl)
                        showOpenDialog();
                    else
                        navigation_->toggleProjection();
                    break;
                case GLFW_KEY_A:
                    // off, multisampling, 2x2 supersampling, off, ...
                    options_.antialias =
                        options_.antialias == Antialias::Off           ? Antialias::Multisample
                        : options_.antialias == Antialias::Multisample ? Antialias::Supersample
                                                                       : Antialias::Off;
                    break;
                case GLFW_KEY_L:
                    setLayout(options_.layout == ViewLayout::Single ? ViewLayout::Four
                                                                    : ViewLayout::Single);
                    break;
                case GLFW_KEY_E:
                    setNavigationMode(NavigationMode::Examiner);
                    break;
                case GLFW_KEY_F:
                    setNavigationMode(NavigationMode::Fly);
                    break;
                case GLFW_KEY_W:
                    setNavigationMode(NavigationMode::Walk);
                    break;
                case GLFW_KEY_T: // off, anaglyph, side-by-side, off, ...
                    options_.stereo.mode =
                        options_.stereo.mode == StereoMode::Off        ? StereoMode::Anaglyph
                        : options_.stereo.mode == StereoMode::Anaglyph ? StereoMode::SideBySide
                                                                       : StereoMode::Off;
                    break;
                case GLFW_KEY_M:
                    toggleManipulator();
                    break;
                case GLFW_KEY_P:
                    screenshot(uniqueScreenshotName(std::filesystem::current_path().string()),
                               false);
                    break;
                case GLFW_KEY_F1:
                    options_.panels = !options_.panels;
                    break;
                case GLFW_KEY_ESCAPE:
                    select(nullptr);
                    break;
                case GLFW_KEY_Q:
                    quit_ = true;
                    break;
                case GLFW_KEY_SPACE: // series: play/pause, step back and forth
                    seriesPanel_.togglePlay(glfwGetTime());
                    break;
                case GLFW_KEY_COMMA:
                case GLFW_KEY_PERIOD:
                    seriesPanel_.stepBy(e.key == GLFW_KEY_COMMA ? -1 : 1);
                    break;
                default:
                    break;
                }
            }
            break;
        }
    }
    if (drag_ != Drag::None && mouse_ != lastMouse_) continueSceneDrag();
}

void Viewer::beginSceneDrag(int button, int mods) {
    dragStart_ = lastMouse_ = mouse_;
    dragView_ = kView3D;
    dragButton_ = button;
    const Ray ray = navigation_->pixelRay(mouse_);
    const bool shift = mods & GLFW_MOD_SHIFT, ctrl = mods & GLFW_MOD_CONTROL,
               alt = mods & GLFW_MOD_ALT;
    if (fly_ && !shift && !ctrl && !alt) {
        // Inventor's fly viewer: left click faster, middle (here also right) click slower.
        if (button == GLFW_MOUSE_BUTTON_LEFT)
            fly_->speedUp();
        else
            fly_->slowDown();
        dragButton_ = -1;
        return;
    }
    if (walk_ && !shift && !ctrl && !alt) {
        // Inventor's walk viewer: hold left to walk and turn, middle to look up and down.
        drag_ = button == GLFW_MOUSE_BUTTON_LEFT ? Drag::Walk : Drag::Tilt;
        return;
    }
    if (button == GLFW_MOUSE_BUTTON_LEFT && !shift && !ctrl && !alt) {
        if (!manipulators_.empty()) {
            PickAction pick;
            pick.setRay(ray);
            pick.apply(*root_);
            if (pick.picked())
                for (Attached& a : manipulators_)
                    if (a.manipulator->beginDrag(ray, pick.picked()->path)) {
                        drag_ = Drag::Manipulator;
                        draggedManipulator_ = a.manipulator;
                        history_.begin(std::string("drag ") + a.node->type().name(),
                                       textFieldsOf(*a.manipulator->original()));
                        return;
                    }
        }
        if (seekMode_) {
            seekMode_ = false;
            if (const auto hit = pickScene(*root_, ray))
                navigation_->startSeek(hit->point, 0.5, options_.seekTime);
            dragButton_ = -1;
            return;
        }
        drag_ = Drag::Pending;
    } else if (button == GLFW_MOUSE_BUTTON_LEFT && ctrl) {
        // RTVR: drag on an object to change its opacity (vertical) and contrast (horizontal).
        const auto hit = pickScene(*root_, ray);
        if (hit && activeDrag_.begin(*root_, *hit->node)) {
            select(hit->node);
            drag_ = Drag::ActiveObject;
        } else {
            dragButton_ = -1;
        }
    } else if (button == GLFW_MOUSE_BUTTON_RIGHT && ctrl) {
        // Window/level (3D Slicer): horizontal = window width, vertical = level.
        drag_ = Drag::WindowLevel;
        dragView_ = kView3D;
        tfEditor_.beginWindowLevel();
    } else if (button == GLFW_MOUSE_BUTTON_MIDDLE || (button == GLFW_MOUSE_BUTTON_LEFT && shift)) {
        drag_ = Drag::Pan;
    } else if (button == GLFW_MOUSE_BUTTON_RIGHT || (button == GLFW_MOUSE_BUTTON_LEFT && alt)) {
        drag_ = Drag::Dolly;
    } else {
        dragButton_ = -1;
    }
}

void Viewer::continueSceneDrag() {
    switch (drag_) {
    case Drag::SectionPending:
        if (glm::length(mouse_ - dragStart_) <= kClickSlop) return;
        drag_ = Drag::WindowLevel;
        tfEditor_.beginWindowLevel();
        [[fallthrough]];
    case Drag::WindowLevel: {
        const ViewRect r = viewRect(dragView_);
        tfEditor_.dragWindowLevel(mouse_ - dragStart_, glm::dvec2(r.width, r.height));
        break;
    }
    case Drag::Pending:
        if (glm::length(mouse_ - dragStart_) <= kClickSlop) return;
        drag_ = Drag::Rotate;
        navigation_->rotate(dragStart_, mouse_);
        break;
    case Drag::Rotate:
        navigation_->rotate(lastMouse_, mouse_);
        break;
    case Drag::Pan:
        navigation_->pan(lastMouse_, mouse_);
        break;
    case Drag::Dolly:
        navigation_->dolly(std::exp((mouse_.y - lastMouse_.y) * 0.01));
        break;
    case Drag::Manipulator:
        draggedManipulator_->drag(navigation_->pixelRay(mouse_));
        break;
    case Drag::ActiveObject:
        activeDrag_.update(mouse_ - dragStart_);
        break;
    case Drag::Tilt:
        walk_->tilt(-(mouse_.y - lastMouse_.y) * 0.005); // mouse up: look up
        break;
    case Drag::Walk: // stepNavigation() walks every frame while the button is down
    case Drag::None:
        break;
    }
    lastMouse_ = mouse_;
}

void Viewer::endSceneDrag() {
    if (drag_ == Drag::SectionPending) { // a click in a section view: the cursor goes there
        const ViewRect r = viewRect(dragView_);
        const glm::dvec2 local = dragStart_ - glm::dvec2(r.x, r.y);
        if (const auto voxel = sections_.voxelAtPixel(dragView_ - 1, local, r.width, r.height))
            setCursor(*voxel);
    } else if (drag_ == Drag::WindowLevel) {
        tfEditor_.endWindowLevel();
    } else if (drag_ == Drag::Pending) { // a click: select what is under the mouse, cursor there
        const Ray ray = navigation_->pixelRay(mouse_);
        const auto hit = pickScene(*root_, ray);
        select(hit ? hit->node : nullptr);
        setCursorFromPick(ray);
    } else if (drag_ == Drag::Manipulator) {
        draggedManipulator_->endDrag();
        draggedManipulator_ = nullptr;
        history_.commit();
    } else if (drag_ == Drag::ActiveObject) {
        activeDrag_.end();
    }
    drag_ = Drag::None;
    dragButton_ = -1;
}

void Viewer::select(Node* node) {
    node = originalOf(node);
    selected_ = ref_ptr<Node>(node);
    fieldPanel_.setNode(node);
    Node* material = nullptr;
    if (node && (node->isA<Material>() || node->isA<BoxClip>()))
        material = node;
    else if (node && node->isA<Volume>())
        material = nearestInScope(*root_, *node, BoxClip::classType());
    else if (node && node->isA<Shape>())
        material = nearestInScope(*root_, *node, Material::classType());
    materialEditor_.setNode(material);
    if (node && node->isA<Volume>()) {
        planeEditor_.setVolume(static_cast<Volume*>(node));
        if (Node* tf = nearestInScope(*root_, *node, TransferFunction::classType()))
            tfEditor_.selectTag(static_cast<TransferFunction*>(tf)->tag());
    }
    if (node && node->isA<TransferFunction>())
        tfEditor_.selectTag(static_cast<TransferFunction*>(node)->tag());
}

// ---- views, navigation modes and the cursor -------------------------------------------------

void Viewer::setLayout(ViewLayout layout) {
    if (layout == ViewLayout::Four && !sections_.valid())
        status("the scene has no volume: the section views have nothing to show");
    options_.layout = layout;
}

void Viewer::setNavigationMode(NavigationMode mode) {
    options_.navigation = mode;
    navigation_->stopSeek(); // fly and walk move the camera themselves
    fly_.reset();
    walk_.reset();
    if (drag_ == Drag::Walk || drag_ == Drag::Tilt) endSceneDrag();
    const ViewRect r = viewRect(kView3D);
    const Box3 box = sceneBox();
    // A tenth of the scene's diagonal per second: ten seconds to cross it.
    const double speed = box.isEmpty() ? 1.0 : 0.1 * glm::length(box.size());
    if (mode == NavigationMode::Fly) {
        fly_ = std::make_unique<FlyNavigation>(navigation_->cameraPtr(), r.width, r.height);
        fly_->setBaseSpeed(speed);
    } else if (mode == NavigationMode::Walk) {
        walk_ = std::make_unique<WalkNavigation>(navigation_->cameraPtr(), r.width, r.height);
        walk_->setWalkSpeed(speed);
    }
    lastNavigationStep_ = std::chrono::steady_clock::now();
}

void Viewer::stepNavigation() {
    const auto now = std::chrono::steady_clock::now();
    // Scripted sessions step by a fixed 1/30 s, so that they move the same on every machine.
    const bool scripted = !script_.empty();
    const double seconds =
        scripted ? 1.0 / 30.0
                 : std::min(std::chrono::duration<double>(now - lastNavigationStep_).count(), 0.1);
    lastNavigationStep_ = now;
    navigation_->stepSeek(seconds);
    // The projection toggle makes a new camera: fly and walk follow it.
    if ((fly_ && &fly_->camera() != &navigation_->camera()) ||
        (walk_ && &walk_->camera() != &navigation_->camera()))
        setNavigationMode(options_.navigation);
    const ViewRect r = viewRect(kView3D);
    const glm::dvec2 mouse = mouse_ - glm::dvec2(r.x, r.y);
    if (fly_ && fly_->speed() != 0.0) fly_->step(mouse, seconds);
    if (walk_ && drag_ == Drag::Walk) walk_->step(mouse, seconds);
}

void Viewer::attachSections() {
    cursorSet_ = false;
    region_.reset();
    if (!sections_.attach(*root_) && options_.layout == ViewLayout::Four)
        status("the scene has no volume: the section views have nothing to show");
}

void Viewer::followSceneEdits() {
    // A Transform edit moves the section views; other data (a field edit, undo) starts over.
    const VolumeData* before = sections_.valid() ? &sections_.data() : nullptr;
    const bool valid = sections_.update(*root_);
    if (!valid || &sections_.data() != before) {
        cursorSet_ = false;
        region_.reset();
        patientAxesFromData(); // other data: its own geometry
    }
}

void Viewer::setCursor(const glm::ivec3& voxel) {
    if (!sections_.valid()) return;
    sections_.setCursor(voxel);
    cursorSet_ = true;
    updateRegion();
}

void Viewer::setCursorFromPick(const Ray& ray) {
    if (!sections_.valid()) return;
    // A slice reports the voxel it shows; elsewhere, the voxel at the hit point (a volume's
    // box where the ray enters it, or a shape inside the volume).
    PickAction pick;
    pick.setRay(ray);
    pick.apply(*root_);
    if (pick.picked() && pick.picked()->voxel) {
        setCursor(pick.picked()->voxel->index);
        return;
    }
    if (const auto hit = pickScene(*root_, ray))
        if (const auto voxel = sections_.voxelAtWorld(hit->point)) setCursor(*voxel);
}

void Viewer::updateRegion() {
    region_.reset();
    if (!sections_.valid() || !cursorSet_) return;
    const TransferFunction* tf = sections_.transferFunction();
    glm::dvec2 range(0.0, 255.0);
    if (tf && !tf->dataRange.isDefault()) {
        range = glm::dvec2(tf->dataRange());
    } else {
        const auto natural = sections_.grid().naturalRange();
        range = {natural.first, natural.second};
    }
    region_ =
        RegionHistogram::of(sections_.grid(), sections_.cursor(), regionPanel_.regionSize, range);
}

// ---- manipulators ---------------------------------------------------------------------------

void Viewer::toggleManipulator() {
    Node* node = selected_.get();
    if (!node) {
        status("select a ClipPlane, BoxClip or Transform to manipulate it");
        return;
    }
    for (auto it = manipulators_.begin(); it != manipulators_.end(); ++it)
        if (it->manipulator->original() == node) {
            it->manipulator->detach();
            manipulators_.erase(it);
            return;
        }
    ref_ptr<Node> manipNode;
    Manipulator* manip = nullptr;
    if (node->isA<ClipPlane>()) {
        auto m = ClipPlaneManip::create();
        manip = m.get();
        manipNode = m;
    } else if (node->isA<BoxClip>()) {
        auto m = BoxClipManip::create();
        manip = m.get();
        manipNode = m;
    } else if (node->isA<Transform>()) {
        auto m = TransformManip::create();
        manip = m.get();
        manipNode = m;
    } else {
        status(std::string("no manipulator for a ") + node->type().name());
        return;
    }
    if (!manip->attach(*root_, *node)) return;
    manipulators_.push_back({manipNode, manip, node->version()});
    syncManipulators();
}

void Viewer::syncManipulators() {
    const Box3 box = sceneBox();
    const double size = box.isEmpty() ? 1.0 : 0.6 * glm::length(box.size());
    for (Attached& a : manipulators_) {
        a.manipulator->setHandleSize(size);
        if (!box.isEmpty()) a.manipulator->setAnchor(box.center());
        Node* original = a.manipulator->original();
        if (original && original->version() != a.originalVersion) {
            // An editor or undo changed the plain node: the manipulator shows it.
            if (!a.manipulator->isDragging()) copyFieldValues(*original, *a.node);
            a.originalVersion = original->version();
        }
    }
}

void Viewer::detachAll() {
    for (Attached& a : manipulators_)
        a.manipulator->detach();
}

void Viewer::reattach(const std::vector<ref_ptr<Node>>& originals) {
    for (std::size_t i = 0; i < manipulators_.size() && i < originals.size(); ++i)
        if (originals[i]) manipulators_[i].manipulator->attach(*root_, *originals[i]);
}

// ---- saving, screenshots, reloading ---------------------------------------------------------

void Viewer::screenshot(const std::string& path, bool sceneOnly) {
    const glm::ivec2 size = window_->size();
    Image image;
    if (sceneOnly) {
        RenderOptions o;
        o.width = size.x;
        o.height = size.y;
        o.background = options_.background;
        o.camera = navigation_->cameraPtr();
        // With the view's antialiasing: multisampled, or rendered at twice the size and each
        // 2x2 block averaged.
        const bool supersample = options_.antialias == Antialias::Supersample;
        if (options_.antialias == Antialias::Multisample) o.samples = 4;
        if (supersample) {
            o.width *= 2;
            o.height *= 2;
        }
        image = renderStereo(*renderer_, *root_, o, options_.stereo);
        if (supersample) {
            Image small(size.x, size.y);
            for (int y = 0; y < size.y; ++y)
                for (int x = 0; x < size.x; ++x)
                    small.at(x, y) =
                        0.25f * (image.at(2 * x, 2 * y) + image.at(2 * x + 1, 2 * y) +
                                 image.at(2 * x, 2 * y + 1) + image.at(2 * x + 1, 2 * y + 1));
            image = std::move(small);
        }
    } else {
        // The back buffer as drawn this frame (the front buffer reads black under GLX).
        std::vector<unsigned char> rgba(std::size_t(size.x) * std::size_t(size.y) * 4);
        glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
        glReadBuffer(GL_BACK);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
        image = Image(size.x, size.y);
        for (int y = 0; y < size.y; ++y)
            for (int x = 0; x < size.x; ++x) {
                const unsigned char* p =
                    &rgba[(std::size_t(size.y - 1 - y) * std::size_t(size.x) + std::size_t(x)) * 4];
                image.at(x, y) = glm::vec4(p[0], p[1], p[2], 255) / 255.0f;
            }
    }
    try {
        writePng(path, image);
        std::error_code ec;
        const auto where = std::filesystem::absolute(path, ec);
        // The scene time of the frame shown, for a scene that engines or animated nodes change.
        char when[64] = "";
        if (sceneChanges_) std::snprintf(when, sizeof when, " (scene time %.4f s)", sceneSeconds_);
        status("screenshot saved to " + (ec ? path : where.string()) + when);
    } catch (const Error& e) {
        status(std::string("screenshot failed: ") + e.what());
        exitStatus_ = 1;
    }
}

void Viewer::checkReload() {
    const auto now = std::chrono::steady_clock::now();
    if (now - lastReloadCheck_ < std::chrono::milliseconds(500)) return;
    lastReloadCheck_ = now;
    std::error_code ec;
    const auto time = std::filesystem::last_write_time(options_.scenePath, ec);
    if (ec || time == sceneTime_) return;
    sceneTime_ = time;
    try {
        ref_ptr<Node> fresh = readSceneForFile(options_.scenePath, options_.open);
        detachAll();
        root_ = fresh;
        takeSceneText();
        loadScene();
        status("reloaded " + options_.scenePath);
    } catch (const Error& e) {
        status(std::string("reload failed, keeping the old scene: ") + e.what());
    }
}

// ---- the frame ------------------------------------------------------------------------------

glm::dvec2 Viewer::resolvePoint(const ScriptPoint& p) const {
    switch (p.kind) {
    case ScriptPoint::Kind::Pixels:
        return {p.value.x, p.value.y};
    case ScriptPoint::Kind::Canvas: {
        const auto it = canvases_.find(p.canvas);
        if (it == canvases_.end())
            throw Error("the " + p.canvas + " canvas is not on screen (show its panel first)");
        const auto [lo, hi] = it->second;
        return {lo.x + p.value.x * (hi.x - lo.x), hi.y - p.value.y * (hi.y - lo.y)};
    }
    case ScriptPoint::Kind::World: {
        const Camera& c = navigation_->camera();
        const glm::dvec4 clip =
            c.projectionMatrix(navigation_->aspect()) * c.viewMatrix() * glm::dvec4(p.value, 1.0);
        const ViewRect r = viewRect(kView3D);
        return {r.x + (clip.x / clip.w + 1.0) * 0.5 * r.width,
                r.y + (1.0 - clip.y / clip.w) * 0.5 * r.height};
    }
    case ScriptPoint::Kind::Dialog: {
        const auto it = browserPanel_.places.find(p.canvas);
        if (!openDialogShown_ || it == browserPanel_.places.end())
            throw Error("'" + p.canvas + "' is not in the open dialog (open it first: key o ctrl)");
        const auto [lo, hi] = it->second;
        return {0.5 * double(lo.x + hi.x), 0.5 * double(lo.y + hi.y)};
    }
    case ScriptPoint::Kind::View: {
        if (p.canvas != "3d" && options_.layout != ViewLayout::Four)
            throw Error("the " + p.canvas + " view shows only in the four-view layout");
        const ViewRect r =
            viewRect(p.canvas == "3d" ? kView3D : 1 + SectionViews::sectionNamed(p.canvas));
        return {r.x + p.value.x * r.width, r.y + (1.0 - p.value.y) * r.height};
    }
    }
    return {0.0, 0.0};
}

void Viewer::runScriptStep() {
    if (scriptNext_ >= script_.size()) return;
    if (scriptWait_ > 0) {
        --scriptWait_;
        return;
    }
    const ScriptStep& s = script_[scriptNext_++];
    try {
        using K = ScriptStep::Kind;
        glm::dvec2 point = mouse_;
        if (s.hasPoint) point = resolvePoint(s.point);
        switch (s.kind) {
        case K::Wait:
            if (s.text == "seek") {
                if (navigation_->isSeeking()) --scriptNext_; // again next frame
                break;
            }
            scriptWait_ = std::max(0, s.frames - 1);
            break;
        case K::Move:
            onMouseMove(point);
            break;
        case K::Press:
        case K::Release:
            if (s.hasPoint) onMouseMove(point);
            {
                PendingEvent e{PendingEvent::Kind::Button, point};
                e.button = s.button;
                e.pressed = s.kind == K::Press;
                e.mods = s.mods;
                events_.push_back(e);
            }
            break;
        case K::Scroll:
            if (s.hasPoint) onMouseMove(point);
            onScroll(s.scroll);
            break;
        case K::Key:
            onKey(keyCodeOf(s.text), s.mods);
            scriptKeys_.emplace_back(keyCodeOf(s.text), s.mods); // and to the UI's fields
            break;
        case K::Open:
            requestOpenOrAskLayout(s.text);
            break;
        case K::Drop:
            onDrop(s.files);
            break;
        case K::Recent:
            openRecent(s.frames - 1);
            break;
        case K::Type:
            scriptTyped_ += s.text;
            break;
        case K::DialogRaw: {
            static const char* types[4] = {"uchar", "ushort", "short", "float"};
            rawForm_.use = true;
            for (int a = 0; a < 3; ++a) {
                rawForm_.dimensions[a] = s.voxel[a];
                rawForm_.spacing[a] = float(s.spacing[a]);
            }
            for (int t = 0; t < 4; ++t)
                if (s.text == types[t]) rawForm_.type = t;
            break;
        }
        case K::Confirm:
            if (!pendingOpen_) throw Error("no question is waiting for an answer");
            answerUnsavedQuestion(s.text == "cancel" ? 0 : s.text == "save" ? 1 : 2);
            break;
        case K::Select: {
            Node* node = findByName(*root_, s.text);
            if (!node) throw Error("no node named '" + s.text + "' in the scene");
            select(node);
            break;
        }
        case K::Panel:
            if (s.text != "tf" && s.text != "planeOpacity" && s.text != "material" &&
                s.text != "fields" && s.text != "region")
                throw Error("unknown panel '" + s.text + "'");
            revealPanel_ = s.text;
            options_.panels = true;
            break;
        case K::Layout:
            setLayout(parseViewLayout(s.text));
            break;
        case K::Navigation:
            setNavigationMode(parseNavigationMode(s.text));
            break;
        case K::Stereo:
            options_.stereo.mode = parseStereoMode(s.text);
            if (s.separation > 0.0) options_.stereo.separationFraction = s.separation;
            break;
        case K::Cursor:
            if (!sections_.valid()) throw Error("the scene has no volume for the cursor");
            setCursor(s.voxel);
            break;
        case K::Region:
            regionPanel_.regionSize = s.voxel.x;
            updateRegion();
            break;
        case K::View:
            setAnatomicalView(*parseAnatomicalView(s.text));
            break;
        case K::Sections:
            sections_.setFlipped(s.text == "neurological");
            break;
        case K::Axes:
            setPatientAxes(PatientAxes{glm::dvec3(s.voxel)});
            break;
        case K::Hounsfield:
            tfEditor_.setHounsfieldZero(s.scroll);
            break;
        case K::Preset: {
            const TransferFunctionPreset* preset = nullptr;
            for (const TransferFunctionPreset& p : transferFunctionPresets())
                if (p.name == s.text) preset = &p;
            if (!preset) throw Error("no transfer-function preset named '" + s.text + "'");
            if (!tfEditor_.selected()) throw Error("the scene has no TransferFunction");
            tfEditor_.applyPreset(*preset, PresetApply(s.frames));
            break;
        }
        case K::SeriesStep:
        case K::SeriesPlay:
        case K::SeriesPause:
            if (!seriesPanel_.active()) throw Error("the scene has no VolumeSeries");
            if (s.kind == K::SeriesStep) seriesPanel_.setStep(s.frames);
            if (s.kind == K::SeriesPlay) seriesPanel_.play(glfwGetTime());
            if (s.kind == K::SeriesPause) seriesPanel_.pause();
            break;
        case K::Screenshot:
        case K::Save:
        case K::Quit:
            break; // after this frame is drawn (see frame())
        }
    } catch (const Error& e) {
        status(options_.scriptPath + ":" + std::to_string(s.line) + ": " + e.what());
        exitStatus_ = 1;
        quit_ = true;
    }
}

WindowLayout Viewer::layout() const {
    const bool four = options_.layout == ViewLayout::Four && sections_.valid();
    return layoutWindow(window_->size(), options_.panels,
                        four ? ViewLayout::Four : ViewLayout::Single);
}

Viewer::ViewRect Viewer::viewRect(int view) const {
    const WindowLayout l = layout();
    return view >= 0 && view < l.viewCount ? l.views[std::size_t(view)] : l.views[0];
}

int Viewer::viewAt(const glm::dvec2& pixel) const {
    const WindowLayout l = layout();
    for (int v = 0; v < l.viewCount; ++v)
        if (l.views[std::size_t(v)].contains(pixel)) return v;
    return -1;
}

void Viewer::drawImageIntoRect(const Image& image, const ViewRect& rect) {
    if (!stereoImage_) {
        stereoImage_ = Texture(GL_TEXTURE_2D);
        stereoSource_ = Framebuffer::create();
    }
    stereoImage_.image2D(GL_RGBA32F, image.width, image.height, GL_RGBA, GL_FLOAT,
                         image.pixels.data());
    stereoSource_.attach(GL_COLOR_ATTACHMENT0, stereoImage_);
    stereoSource_.requireComplete("stereo image");
    stereoSource_.bind(GL_READ_FRAMEBUFFER);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    const int windowHeight = window_->size().y;
    // The Image's row 0 is the top; GL's is the bottom: the copy flips it.
    glBlitFramebuffer(0, image.height, image.width, 0, rect.x, windowHeight - rect.y - rect.height,
                      rect.x + rect.width, windowHeight - rect.y, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void Viewer::renderIntoRect(Node& root, RenderOptions o, const ViewRect& rect, double scale,
                            bool stereo) {
    o.width = rect.width;
    o.height = rect.height;
    if (stereo && options_.stereo.mode != StereoMode::Off) {
        drawImageIntoRect(renderStereo(*renderer_, root, o, options_.stereo), rect);
        return;
    }
    const glm::ivec2 windowSize = window_->size();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (scale == 1.0 && rect.x == 0 && rect.y == 0 && rect.width == windowSize.x &&
        rect.height == windowSize.y) {
        renderer_->renderToBoundFramebuffer(root, o);
        return;
    }
    // Off the window first: into a double-size target for 2x2 supersampling (the renderer
    // draws into a single-sample float target, so the window's own multisampling would not
    // help), a smaller one for a coarse frame (scaled up with linear filtering), or just into
    // the view's own rectangle.
    const glm::ivec2 size = glm::max(
        glm::ivec2(glm::round(scale * glm::dvec2(rect.width, rect.height))), glm::ivec2(1));
    if (size != viewTargetSize_) {
        viewColor_ = Renderbuffer(GL_RGBA8, size.x, size.y);
        viewTarget_ = Framebuffer::create();
        viewTarget_.attach(GL_COLOR_ATTACHMENT0, viewColor_);
        viewTarget_.requireComplete("view target");
        viewTargetSize_ = size;
    }
    viewTarget_.bind(GL_FRAMEBUFFER);
    o.width = size.x;
    o.height = size.y;
    renderer_->renderToBoundFramebuffer(root, o);
    viewTarget_.bind(GL_READ_FRAMEBUFFER);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    const int y0 = windowSize.y - rect.y - rect.height;
    glBlitFramebuffer(0, 0, size.x, size.y, rect.x, y0, rect.x + rect.width, y0 + rect.height,
                      GL_COLOR_BUFFER_BIT, GL_LINEAR);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, windowSize.x, windowSize.y);
}

void Viewer::renderViews() {
    RenderOptions o;
    o.background = options_.background;
    o.interactive = isInteracting();
    o.interactivePlaneScale = quality_.planeScale();
    o.camera = navigation_->cameraPtr();
    // The 3D view's resolution: a quarter of it (and the interactive planes) for the first
    // image of a scene, the interactive rule's while the user drags, else full (or twice,
    // supersampled).
    double resolution = options_.antialias == Antialias::Supersample ? 2.0 : 1.0;
    if (refineStage_ == 0) {
        resolution = kFirstImageResolution;
        o.interactive = true;
        o.interactivePlaneScale = 1.0;
    } else if (o.interactive) {
        resolution = quality_.resolutionScale();
    }
    const bool four = options_.layout == ViewLayout::Four && sections_.valid();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    { // under the panel column (and the seams between views, if any): nothing stale shows
        const glm::ivec2 size = window_->size();
        glViewport(0, 0, size.x, size.y);
        glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    // One cache frame for all views: the section graphs USE the scene's VolumeData and
    // TransferFunction nodes, so their textures and tables are made once for every view.
    renderer_->beginViewGroup();
    try {
        RenderOptions view3D = o;
        if (options_.antialias == Antialias::Multisample) view3D.samples = 4;
        renderIntoRect(*root_, view3D, viewRect(kView3D), resolution, true);
        if (four)
            for (int s = 0; s < 3; ++s) {
                const ViewRect r = viewRect(1 + s);
                RenderOptions section = o;
                section.camera = sections_.camera(s, double(r.width) / double(r.height));
                renderIntoRect(sections_.graph(s), section, r, 1.0, false);
            }
    } catch (...) {
        renderer_->endViewGroup();
        throw;
    }
    renderer_->endViewGroup();
}

void Viewer::frame() {
    const auto start = std::chrono::steady_clock::now();
    // Nothing to draw and no script to play: wait for input (or the reload check) rather than
    // spin.
    if (idle_ && scriptNext_ >= script_.size() && scriptWait_ == 0)
        glfwWaitEventsTimeout(0.1);
    else
        GlfwWindow::pollEvents();
    const bool scripted = scriptNext_ < script_.size() || scriptWait_ > 0;
    const ScriptStep* step = scripted && scriptWait_ == 0 ? &script_[scriptNext_] : nullptr;
    runScriptStep();
    openRequested();
    checkReload();

    // The mouse state of this frame, from the events in order.
    justPressed_[0] = justPressed_[1] = justPressed_[2] = false;
    for (const PendingEvent& e : events_) {
        if (e.kind == PendingEvent::Kind::Move) mouse_ = e.position;
        if (e.kind == PendingEvent::Kind::Button && e.button >= 0 && e.button < 3) {
            buttons_[e.button] = e.pressed;
            if (e.pressed) justPressed_[e.button] = true;
            mods_ = e.mods;
        }
    }

    const ViewRect view3D = viewRect(kView3D);
    navigation_->setViewport(view3D.width, view3D.height);
    if (fly_) fly_->setViewport(view3D.width, view3D.height);
    if (walk_) walk_->setViewport(view3D.width, view3D.height);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(float(mouse_.x), float(mouse_.y)); // ours: GLFW's or the script's
    for (int b = 0; b < 3; ++b)
        io.MouseDown[b] = buttons_[b] || justPressed_[b];
    if (!script_.empty()) {
        // The script's keys and text reach the UI's fields as GLFW's would: a key is down for
        // one frame. The UI's clock steps 1/30 s a frame, as fly and walk do, so a scripted
        // double-click is one on any machine.
        io.DeltaTime = 1.0f / 30.0f;
        for (const int key : scriptKeysDown_)
            io.KeysDown[key] = false;
        if (!scriptKeysDown_.empty()) io.KeyCtrl = io.KeyShift = io.KeyAlt = false;
        scriptKeysDown_.clear();
        for (const auto& [key, mods] : scriptKeys_)
            if (key >= 0 && key < int(IM_ARRAYSIZE(io.KeysDown))) {
                io.KeysDown[key] = true;
                io.KeyCtrl = (mods & GLFW_MOD_CONTROL) != 0;
                io.KeyShift = (mods & GLFW_MOD_SHIFT) != 0;
                io.KeyAlt = (mods & GLFW_MOD_ALT) != 0;
                scriptKeysDown_.push_back(key);
            }
        scriptKeys_.clear();
        for (const char c : scriptTyped_)
            io.AddInputCharacter(static_cast<unsigned char>(c));
        scriptTyped_.clear();
    }
    ImGui::NewFrame();
    handleSceneEvents();
    events_.clear();
    if (!dropped_.empty()) { // the first dropped file opens, as the dialog would open it
        const std::vector<std::string> dropped = std::move(dropped_);
        dropped_.clear();
        if (dropped.size() > 1)
            status("opening the first of " + std::to_string(dropped.size()) + " dropped files");
        requestOpenOrAskLayout(dropped.front());
    }
    seriesPanel_.update(glfwGetTime());
    followSceneEdits();
    // Engines, field connections and animated nodes (Rotor, Blinker, ...) run on the viewer's
    // clock; a field they change redraws the views (the frame's signature sees its version).
    sceneSeconds_ =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - startTime_).count();
    if (engines_.evaluate(*root_, sceneSeconds_) > 0) sceneChanges_ = true;
    tfPanel_.deferHistogram = refineStage_ == 0; // the first image before the histogram
    if (options_.panels) drawPanels();
    drawOpenDialog();
    drawUnsavedQuestion();
    progressText_ = refineStage_ == 0 ? "first image at a quarter of the resolution: refining..."
                                      : std::string();
    drawViewOverlays();
    stepNavigation();
    syncManipulators();
    navigation_->adjustClipping(sceneBox());
    ImGui::Render();

    // A still frame that would show exactly what the last one showed is not drawn again: the
    // views are copied back from the last one (ViewerRedraw.cpp), so the viewer answers input
    // at once instead of redrawing a slow full-quality image every frame.
    const ViewSignature signature = viewSignature();
    idle_ = refineStage_ >= 2 && !isInteracting() && lastShown_ && *lastShown_ == signature &&
            restoreViews();
    ++framesTotal_;
    if (!idle_) {
        ++framesDrawn_;
        const auto renderStart = std::chrono::steady_clock::now();
        lastShown_.reset();
        try {
            renderViews();
            // Only a full still image is kept (a coarse or interactive one is redrawn).
            // A paged volume still loading bricks draws again as they arrive (volsg-view README).
            if (refineStage_ >= 1 && !isInteracting() && !cli::volumesRefining(*root_)) {
                keepViews();
                lastShown_ = signature;
            }
        } catch (const Error& e) {
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glClearColor(0.3f, 0.0f, 0.0f, 1.0f);
            glClear(GL_COLOR_BUFFER_BIT);
            if (statusText_ != e.what()) status(e.what());
        }
        glFinish(); // llvmpipe draws on demand: the render time is measured when it is done
        lastRenderMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                                  renderStart)
                            .count();
    }
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

    if (step && step->kind == ScriptStep::Kind::Screenshot) screenshot(step->text, step->sceneOnly);
    if (step && step->kind == ScriptStep::Kind::Save) saveScene(step->text);
    if (step && step->kind == ScriptStep::Kind::Quit) quit_ = true;
    window_->swapBuffers();
    if (refineStage_ < 2) { // how long the first image and the full one took to show
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - startTime_)
                .count();
        // And the processor time the process used (all threads): on a machine shared with
        // other work, the wall time overstates what an idle one takes.
        const double cpuMs = 1000.0 * double(std::clock()) / CLOCKS_PER_SEC;
        char text[128];
        std::snprintf(text, sizeof text, "%s image after %.0f ms (processor time %.0f ms)",
                      refineStage_ == 0 ? "first (coarse)" : "full", ms, cpuMs);
        status(text);
        ++refineStage_;
    }

    lastFrameMs_ =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    quality_.frameDone(isInteracting(), lastFrameMs_);
}

int Viewer::run() {
    while (!quit_ && !window_->shouldClose())
        frame();
    status(std::to_string(framesTotal_) + " frames, " + std::to_string(framesDrawn_) +
           " drawn (the others showed the last still image again)");
    return exitStatus_;
}

} // namespace volsg
