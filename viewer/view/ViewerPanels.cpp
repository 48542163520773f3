// The viewer's panel column: one fixed window at the right edge of the window (WindowLayout)
// holding the Scene, Transfer function, Plane opacity, Material, Fields, Cursor and Series
// sections one under the other (collapsible, the column scrolls), so no panel ever covers a
// view.
#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "Viewer.h"
#include "VolumeReport.h"

#include <algorithm>

#include <imgui.h>

#include <volsg/actions/SearchAction.h>
#include <volsg/editors/panels/MaterialPanel.h>
#include <volsg/editors/panels/PlaneOpacityPanel.h>
#include <volsg/manipulators/Manipulator.h>
#include <volsg/nodes/BoxClip.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/Transform.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeSeries.h> // complete for SeriesPanel's ref_ptr
#include <volsg/volumescene/SceneForFile.h>

namespace volsg {

namespace {

Node* originalNodeOf(Node* node) {
    if (auto* m = dynamic_cast<Manipulator*>(node))
        if (m->original()) return m->original();
    return node;
}

} // namespace

void Viewer::drawSceneTree(Node& node, int depth) {
    Node* original = originalNodeOf(&node);
    std::string label = std::string(node.type().name());
    if (!original->getName().empty()) label += " " + original->getName();
    label += "##" + std::to_string(reinterpret_cast<std::uintptr_t>(&node)) + "_" +
             std::to_string(depth);
    auto* children = node.children();
    ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_SpanAvailWidth;
    if (!children || children->empty())
        flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
    if (depth < 2) flags |= ImGuiTreeNodeFlags_DefaultOpen;
    if (selected_.get() == original) flags |= ImGuiTreeNodeFlags_Selected;
    const bool open = ImGui::TreeNodeEx(label.c_str(), flags);
    if (ImGui::IsItemClicked()) select(original);
    if (open && children && !children->empty()) {
        if (depth < 32)
            for (const auto& child : *children)
                if (child) drawSceneTree(*child, depth + 1);
        ImGui::TreePop();
    }
}

bool Viewer::panelSection(const char* title, bool& open, const char* scriptName) {
    const bool reveal = scriptName && revealPanel_ == scriptName;
    if (reveal) open = true;
    ImGui::SetNextItemOpen(open, ImGuiCond_Always);
    open = ImGui::CollapsingHeader(title);
    if (reveal) {
        ImGui::SetScrollHereY(0.0f); // its top at the column's top from the next frame
        revealPanel_.clear();
    }
    return open;
}

void Viewer::drawPanels() {
    const PixelRect column = layout().panels;
    canvases_.clear();
    if (column.empty()) return;
    ImGui::SetNextWindowPos(ImVec2(float(column.x), float(column.y)), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(float(column.width), float(column.height)), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(1.0f); // opaque: the column shows the panels alone
    ImGui::Begin("##panels", nullptr,
                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoBringToFrontOnFocus | ImGuiWindowFlags_MenuBar);
    drawMenuBar();
    if (panelSection("Scene", showScene_, nullptr)) drawScenePanel();
    if (panelSection("Transfer function", showTf_, "tf")) {
        drawTransferFunctionPanel(tfEditor_, tfPanel_);
        canvases_["tf"] = {glm::vec2(tfPanel_.canvas.rectMin.x, tfPanel_.canvas.rectMin.y),
                           glm::vec2(tfPanel_.canvas.rectMax.x, tfPanel_.canvas.rectMax.y)};
    }
    if (seriesPanel_.active()) seriesPanel_.draw(glfwGetTime());
    if (panelSection("Plane opacity", showPlane_, "planeOpacity")) {
        drawPlaneOpacityPanel(planeEditor_, planePanel_);
        canvases_["planeOpacity"] = {glm::vec2(planePanel_.rectMin.x, planePanel_.rectMin.y),
                                     glm::vec2(planePanel_.rectMax.x, planePanel_.rectMax.y)};
    }
    if (panelSection("Material", showMaterial_, "material")) drawMaterialPanel(materialEditor_);
    if (panelSection("Fields", showFields_, "fields"))
        drawFieldPanel(fieldPanel_, fieldPanelState_);
    if (panelSection("Cursor", showRegion_, "region"))
        if (drawRegionHistogramPanel(region_, regionPanel_)) updateRegion();
    ImGui::End();
}

/// The volumes' quality: one slider sets every volume node's errorTarget (the RMSE a still
/// frame may have, an undoable edit), and a line per volume says what its last frame drew
/// with and the error it predicts (as volsg-render --verbose prints it).
void Viewer::drawVolumeQuality() {
    if (!root_) return;
    std::vector<SFFloat*> targets;
    for (Node* n : findAll(*root_, Volume::classType()))
        targets.push_back(&static_cast<Volume*>(n)->errorTarget);
    for (Node* n : findAll(*root_, ShearWarpVolume::classType()))
        targets.push_back(&static_cast<ShearWarpVolume*>(n)->errorTarget);
    if (targets.empty()) return;
    float target = (*targets.front())();
    const float width = std::max(80.0f, ImGui::GetContentRegionAvail().x - 150.0f);
    ImGui::SetNextItemWidth(width);
    if (ImGui::SliderFloat("error target /255", &target, 0.1f, 8.0f, "%.2f",
                           ImGuiSliderFlags_Logarithmic)) {
        if (!history_.isOpen())
            history_.begin("error target", std::vector<Field*>(targets.begin(), targets.end()));
        for (SFFloat* field : targets)
            *field = target;
    }
    if (ImGui::IsItemDeactivatedAfterEdit()) history_.commit();
    // The slider's frame, without its label (a script's errorTarget:U,V).
    const ImVec2 lo = ImGui::GetItemRectMin(), hi = ImGui::GetItemRectMax();
    canvases_["errorTarget"] = {glm::vec2(lo.x, lo.y), glm::vec2(lo.x + width, hi.y)};
    // While the user drags, a new view direction is not predicted in the frame's time.
    for (const std::string& line : cli::volumeQualityLines(*root_, !isInteracting()))
        ImGui::TextWrapped("%s", line.c_str());
}

void Viewer::drawScenePanel() {
    ImGui::Text("%.1f fps  frame %.0f ms  render %.0f ms",
                lastFrameMs_ > 0 ? 1000.0 / lastFrameMs_ : 0.0, lastFrameMs_, lastRenderMs_);
    ImGui::Text("%s  planes x%.3g  %s%s", isInteracting() ? "interactive" : "still",
                quality_.scale(), navigation_->isOrthographic() ? "ortho" : "perspective",
                options_.antialias == Antialias::Multisample   ? "  AA msaa 4x"
                : options_.antialias == Antialias::Supersample ? "  AA 2x2"
                                                               : "");
    drawVolumeQuality();
    if (ImGui::Button("view all")) navigation_->viewAll(sceneBox());
    ImGui::SameLine();
    if (ImGui::Button("home")) navigation_->goHome();
    ImGui::SameLine();
    if (ImGui::Button(navigation_->isOrthographic() ? "perspective" : "ortho"))
        navigation_->toggleProjection();
    ImGui::SameLine();
    int aa = int(options_.antialias);
    ImGui::SetNextItemWidth(90.0f);
    if (ImGui::Combo("AA", &aa,
                     "off\0msaa 4x\0"
                     "2x2\0"))
        options_.antialias = Antialias(aa);
    if (ImGui::Button(seekMode_ ? "seek: click a point" : "seek")) seekMode_ = !seekMode_;
    ImGui::SameLine();
    ImGui::BeginDisabled(!history_.canUndo());
    if (ImGui::Button("undo")) history_.undo();
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!history_.canRedo());
    if (ImGui::Button("redo")) history_.redo();
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("save")) saveScene(scenePathForSaving(options_.scenePath, options_.open));
    // Save As: a new file name (relative names from the current folder); later saves go there.
    ImGui::SetNextItemWidth(std::max(80.0f, ImGui::GetContentRegionAvail().x - 70.0f));
    ImGui::InputTextWithHint("##saveas", "save as: file.iv", saveAsPath_, sizeof saveAsPath_);
    ImGui::SameLine();
    ImGui::BeginDisabled(saveAsPath_[0] == '\0');
    if (ImGui::Button("save as")) saveScene(saveAsPath_);
    ImGui::EndDisabled();
    const bool manipulable =
        selected_ &&
        (selected_->isA<ClipPlane>() || selected_->isA<BoxClip>() || selected_->isA<Transform>());
    ImGui::BeginDisabled(!manipulable);
    bool attached = false;
    for (const Attached& a : manipulators_)
        attached |= a.manipulator->original() == selected_.get();
    if (ImGui::Button(attached ? "remove manipulator (m)" : "manipulate (m)")) toggleManipulator();
    ImGui::EndDisabled();
    drawViewControls();
    drawOrientationControls();
    if (!statusText_.empty()) ImGui::TextWrapped("%s", statusText_.c_str());
    if (ImGui::TreeNodeEx("scene graph", ImGuiTreeNodeFlags_DefaultOpen)) {
        drawSceneTree(*root_, 0);
        ImGui::TreePop();
    }
}

void Viewer::drawOrientationControls() {
    // The 3D view from each side of the patient (A P L R S I), the section views' convention,
    // and how the volume's axes run when its file does not say (PatientOrientation.h).
    ImGui::TextUnformatted("view from");
    static const char* labels[kAnatomicalViewCount] = {"A", "P", "L", "R", "S", "I"};
    for (int v = 0; v < kAnatomicalViewCount; ++v) {
        ImGui::SameLine();
        if (ImGui::SmallButton(labels[v])) setAnatomicalView(AnatomicalView(v));
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s view", anatomicalViewName(AnatomicalView(v)));
    }
    bool flipped = sections_.flipped();
    if (ImGui::Checkbox("sections flipped (neurological)", &flipped)) sections_.setFlipped(flipped);
    ImGui::TextUnformatted("volume axes reversed");
    PatientAxes axes = patientAxes_;
    bool changed = false;
    for (int a = 0; a < 3; ++a) {
        ImGui::SameLine();
        bool reversed = axes.signs[a] < 0.0;
        const char* name[3] = {"x##axis", "y##axis", "z##axis"};
        if (ImGui::Checkbox(name[a], &reversed)) {
            axes.signs[a] = reversed ? -1.0 : 1.0;
            changed = true;
        }
    }
    if (changed) setPatientAxes(axes);
    // Where each volume axis points in the patient (from the file's geometry, if it has one).
    ImGui::Text("volume axes +x %c  +y %c  +z %c%s", patientAxes_.letter(0, true),
                patientAxes_.letter(1, true), patientAxes_.letter(2, true),
                patientAxes_.fromFile == glm::dmat3(1.0) ? "" : "  (from the file)");
}

void Viewer::drawViewControls() {
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.5f); // room for the labels
    int layout = int(options_.layout);
    if (ImGui::Combo("layout (l)", &layout, "single view\0four views\0"))
        setLayout(ViewLayout(layout));
    int navigation = int(options_.navigation);
    if (ImGui::Combo("navigation (e f w)", &navigation, "examiner\0fly\0walk\0"))
        setNavigationMode(NavigationMode(navigation));
    int stereo = int(options_.stereo.mode);
    if (ImGui::Combo("stereo (t)", &stereo, "off\0red-cyan anaglyph\0side by side\0"))
        options_.stereo.mode = StereoMode(stereo);
    if (options_.stereo.mode != StereoMode::Off) {
        float fraction = float(options_.stereo.separationFraction);
        if (ImGui::SliderFloat("eye separation", &fraction, 0.005f, 0.2f, "%.3f x focal"))
            options_.stereo.separationFraction = double(fraction);
    }
    ImGui::PopItemWidth();
}

} // namespace volsg
