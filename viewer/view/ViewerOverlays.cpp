// What the viewer draws over its views: the cursor's crosshairs and the anatomical letters at
// the edges of the section views, the cursor's ring, the axes marker (a small triad of the
// patient axes R, A, S) and the scale bar in the 3D view, and the navigation mode's line.
#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "Viewer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <volsg/actions/SearchAction.h>
#include <volsg/context/GlfwWindow.h>
#include <volsg/editors/ValueAxis.h>
#include <volsg/manipulators/DragMath.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/VolumeData.h>

namespace volsg {

namespace {

void drawLetter(ImDrawList* draw, ImVec2 at, char letter, ImU32 colour) {
    const char text[2] = {letter, '\0'};
    const ImVec2 size = ImGui::CalcTextSize(text);
    const ImVec2 corner(at.x - 0.5f * size.x, at.y - 0.5f * size.y);
    // A dark outline keeps the letter legible on any image.
    for (const ImVec2 d : {ImVec2(-1, 0), ImVec2(1, 0), ImVec2(0, -1), ImVec2(0, 1)})
        draw->AddText(ImVec2(corner.x + d.x, corner.y + d.y), IM_COL32(0, 0, 0, 220), text);
    draw->AddText(corner, colour, text);
}

} // namespace

double Viewer::worldUnitsPerPixel() const {
    const Camera& c = navigation_->camera();
    const ViewRect r = viewRect(kView3D);
    if (const auto* o = dynamic_cast<const OrthographicCamera*>(&c))
        return double(o->height()) / double(r.height);
    if (const auto* p = dynamic_cast<const PerspectiveCamera*>(&c))
        return 2.0 * double(c.focalDistance()) * std::tan(0.5 * double(p->heightAngle())) /
               double(r.height);
    return 0.0;
}

glm::dvec3 Viewer::patientDirectionInWorld(const glm::dvec3& ras) const {
    const glm::dmat3 linear = sections_.valid() ? glm::dmat3(sections_.model()) : glm::dmat3(1.0);
    return glm::normalize(linear * patientAxes_.toLocal(ras));
}

void Viewer::drawAxesMarker(ImDrawList* draw, const ViewRect& r) {
    // The patient axes seen by the 3D camera, from a point in the view's bottom-left corner;
    // the ones pointing away are drawn first, so nearer ones cover them.
    const glm::dquat turn = navigation_->camera().orientation().quat();
    const glm::dvec3 right = turn * glm::dvec3(1, 0, 0), up = turn * glm::dvec3(0, 1, 0),
                     back = turn * glm::dvec3(0, 0, 1);
    const ImVec2 centre(float(r.x + 44), float(r.y + r.height - 44));
    const float length = 30.0f;
    const ImU32 colours[3] = {IM_COL32(235, 70, 70, 255), IM_COL32(80, 210, 80, 255),
                              IM_COL32(90, 140, 255, 255)};
    std::array<int, 3> order{0, 1, 2};
    std::array<glm::dvec3, 3> world;
    for (int a = 0; a < 3; ++a)
        world[std::size_t(a)] = patientDirectionInWorld(glm::dvec3(a == 0, a == 1, a == 2));
    std::sort(order.begin(), order.end(), [&](int a, int b) {
        return glm::dot(world[std::size_t(a)], back) < glm::dot(world[std::size_t(b)], back);
    });
    draw->AddCircleFilled(centre, length + 12.0f, IM_COL32(0, 0, 0, 90), 24);
    for (const int a : order) {
        const glm::dvec3& d = world[std::size_t(a)];
        const ImVec2 tip(centre.x + length * float(glm::dot(d, right)),
                         centre.y - length * float(glm::dot(d, up)));
        draw->AddLine(centre, tip, colours[a], 2.5f);
        const ImVec2 label(centre.x + (length + 8.0f) * float(glm::dot(d, right)),
                           centre.y - (length + 8.0f) * float(glm::dot(d, up)));
        drawLetter(draw, label, "RAS"[a], colours[a]);
    }
}

void Viewer::drawScaleBar(ImDrawList* draw, const ViewRect& r) {
    // At the focal distance (a perspective view's scale changes with depth): a round length
    // of at most a quarter of the view's width.
    const double unitsPerPixel = worldUnitsPerPixel();
    const double length = niceFloor(0.25 * double(r.width) * unitsPerPixel);
    if (!(length > 0.0)) return;
    const float pixels = float(length / unitsPerPixel);
    const float x1 = float(r.x + r.width - 16), x0 = x1 - pixels, y = float(r.y + r.height - 26);
    const ImU32 colour = IM_COL32(235, 235, 235, 255);
    draw->AddLine({x0, y}, {x1, y}, colour, 2.0f);
    draw->AddLine({x0, y - 5.0f}, {x0, y + 5.0f}, colour, 2.0f);
    draw->AddLine({x1, y - 5.0f}, {x1, y + 5.0f}, colour, 2.0f);
    char text[48];
    // Volume files from scanners (NRRD, NIfTI, DICOM, ...) give spacing in millimetres; a
    // generated volume's spacing has no unit.
    const bool millimetres = sections_.valid() && !sections_.data().fileName().empty();
    std::snprintf(text, sizeof text, "%g%s", length, millimetres ? " mm" : "");
    const ImVec2 size = ImGui::CalcTextSize(text);
    draw->AddText({0.5f * (x0 + x1) - 0.5f * size.x, y - 6.0f - size.y}, colour, text);
}

void Viewer::drawViewOverlays() {
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const bool four = layout().viewCount == 4;
    const ImU32 cross = IM_COL32(255, 220, 0, 200), label = IM_COL32(230, 230, 230, 255);
    const ImU32 letter = IM_COL32(255, 200, 120, 255);
    if (four) {
        const glm::dvec3 cursor = sections_.worldOf(sections_.cursor());
        for (int s = 0; s < 3; ++s) {
            const ViewRect r = viewRect(1 + s);
            const glm::dvec2 p = sections_.pixelOf(s, cursor, r.width, r.height);
            const float x = float(r.x + p.x), y = float(r.y + p.y);
            draw->PushClipRect(ImVec2(float(r.x), float(r.y)),
                               ImVec2(float(r.x + r.width), float(r.y + r.height)), true);
            draw->AddLine(ImVec2(float(r.x), y), ImVec2(float(r.x + r.width), y), cross);
            draw->AddLine(ImVec2(x, float(r.y)), ImVec2(x, float(r.y + r.height)), cross);
            const std::string text = std::string(SectionViews::name(s)) + "  slice " +
                                     std::to_string(sections_.cursor()[sections_.axisOf(s)]) +
                                     (sections_.flipped() ? "  (flipped)" : "");
            draw->AddText(ImVec2(float(r.x + 6), float(r.y + r.height - 20)), label, text.c_str());
            // The patient's directions at the view's edges (radiological: L on the right).
            const ViewDirection d = sectionViewDirection(s, sections_.flipped());
            const glm::dvec3 right = glm::cross(d.forward, d.up);
            const float cx = float(r.x) + 0.5f * float(r.width),
                        cy = float(r.y) + 0.5f * float(r.height);
            drawLetter(draw, {float(r.x + r.width - 12), cy}, patientLetter(right), letter);
            drawLetter(draw, {float(r.x + 12), cy}, patientLetter(-right), letter);
            drawLetter(draw, {cx, float(r.y + 12)}, patientLetter(d.up), letter);
            drawLetter(draw, {cx, float(r.y + r.height - 34)}, patientLetter(-d.up), letter);
            draw->PopClipRect();
        }
    }
    const ViewRect r = viewRect(kView3D);
    if (cursorSet_) { // the cursor point in the 3D view
        const Camera& c = navigation_->camera();
        const glm::dvec4 clip = c.projectionMatrix(navigation_->aspect()) * c.viewMatrix() *
                                glm::dvec4(sections_.worldOf(sections_.cursor()), 1.0);
        if (clip.w > 0.0) {
            const ImVec2 p(float(r.x + (clip.x / clip.w + 1.0) * 0.5 * r.width),
                           float(r.y + (1.0 - clip.y / clip.w) * 0.5 * r.height));
            draw->AddCircle(p, 6.0f, cross, 12, 2.0f);
        }
    }
    draw->PushClipRect(ImVec2(float(r.x), float(r.y)),
                       ImVec2(float(r.x + r.width), float(r.y + r.height)), true);
    drawAxesMarker(draw, r);
    drawScaleBar(draw, r);
    std::string mode = navigationModeName(options_.navigation);
    if (fly_) mode += "  speed " + std::to_string(fly_->speed()).substr(0, 5);
    if (options_.stereo.mode != StereoMode::Off)
        mode += std::string("  stereo ") + stereoModeName(options_.stereo.mode);
    draw->AddText(ImVec2(float(r.x) + float(r.width) * 0.5f - 60.0f, float(r.y + r.height - 20)),
                  label, mode.c_str());
    if (!errorLine_.empty()) { // a file that did not open: one line over the view
        const ImVec2 at(float(r.x + 8), float(r.y + 8));
        const ImVec2 size = ImGui::CalcTextSize(errorLine_.c_str());
        draw->AddRectFilled({at.x - 4.0f, at.y - 3.0f},
                            {at.x + size.x + 4.0f, at.y + size.y + 3.0f}, IM_COL32(90, 0, 0, 200),
                            3.0f);
        draw->AddText(at, IM_COL32(255, 220, 210, 255), errorLine_.c_str());
    }
    if (!progressText_.empty()) { // loading or refining: said in the view itself
        const ImVec2 size = ImGui::CalcTextSize(progressText_.c_str());
        const ImVec2 at(float(r.x) + 0.5f * (float(r.width) - size.x), float(r.y + 12));
        draw->AddRectFilled({at.x - 8.0f, at.y - 4.0f},
                            {at.x + size.x + 8.0f, at.y + size.y + 4.0f}, IM_COL32(0, 0, 0, 160),
                            4.0f);
        draw->AddText(at, label, progressText_.c_str());
    }
    draw->PopClipRect();
}

void Viewer::setAnatomicalView(AnatomicalView view) {
    const ViewDirection d = anatomicalViewDirection(view);
    navigation_->stopSeek();
    navigation_->camera().orientation = rotationFromQuat(
        cameraOrientation(patientDirectionInWorld(d.forward), patientDirectionInWorld(d.up)));
    navigation_->viewAll(sceneBox());
}

void Viewer::setPatientAxes(const PatientAxes& axes) {
    patientAxes_ = axes;
    sections_.setPatientAxes(axes);
}

std::string Viewer::loadingMessage() const {
    std::string files;
    for (Node* n : findAll(*root_, VolumeData::classType())) {
        const auto& data = static_cast<const VolumeData&>(*n);
        if (data.fileName().empty()) continue;
        std::error_code ec;
        std::filesystem::path path(data.fileName()); // relative names: from the scene's folder
        if (path.is_relative())
            path = std::filesystem::path(options_.scenePath).parent_path() / path;
        const auto bytes = std::filesystem::file_size(path, ec);
        char size[48] = "";
        if (!ec) std::snprintf(size, sizeof size, " (%.1f MB)", double(bytes) / 1048576.0);
        files += (files.empty() ? "" : ", ") +
                 std::filesystem::path(data.fileName()).filename().string() + size;
    }
    return files.empty() ? "loading the scene..." : "loading " + files + "...";
}

void Viewer::showMessageFrame(const std::string& message) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const ImVec2 size = ImGui::CalcTextSize(message.c_str());
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    draw->AddText(ImVec2(0.5f * (display.x - size.x), 0.5f * (display.y - size.y)),
                  IM_COL32(230, 230, 230, 255), message.c_str());
    ImGui::Render();
    const glm::ivec2 window = window_->size();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, window.x, window.y);
    glClearColor(options_.background.r, options_.background.g, options_.background.b, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
    window_->swapBuffers();
}

} // namespace volsg
