// Opening files while the viewer runs: the one openFile the command line also goes through,
// the open dialog (a FileBrowser with a form for raw voxels' layout), drops on the window, the
// recent files, the question before unsaved edits are dropped, and the patient axes from the
// opened volume's geometry.
#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "Viewer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include <volsg/context/GlfwWindow.h>
#include <volsg/core/Error.h>
#include <volsg/core/Limits.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/nodes/VolumeSeries.h> // complete for SeriesPanel's ref_ptr

namespace volsg {

namespace fs = std::filesystem;

namespace {

std::string sizeOf(const std::string& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return {};
    const auto bytes = fs::file_size(path, ec);
    if (ec) return {};
    char text[48];
    std::snprintf(text, sizeof text, " (%.1f MB)", double(bytes) / 1048576.0);
    return text;
}

} // namespace

void Viewer::openFile(const std::string& path, const OpenFileOptions& open) {
    showMessageFrame("loading " + fs::path(path).filename().string() + sizeOf(path) + "...");
    ref_ptr<Node> fresh = readSceneForFile(path, open); // throws: the old scene stays
    detachAll();
    root_ = fresh;
    seekMode_ = false; // input under way was for the old scene
    drag_ = Drag::None;
    dragButton_ = -1;
    // The scene's clock and the first-image times count from here (at start-up: from the
    // viewer's start, window included).
    if (framesTotal_ > 0) startTime_ = std::chrono::steady_clock::now();
    options_.scenePath = path;
    options_.open = open;
    // A scene file's text is kept for saving in place; a data file's scene is saved beside it.
    sceneText_.reset();
    if (scenePathForSaving(path, open) == path) {
        takeSceneText();
        showMessageFrame(loadingMessage()); // the volume files the scene names load next
    }
    std::error_code ec;
    sceneTime_ = fs::last_write_time(path, ec);
    patientAxes_ = PatientAxes{}; // the user's reversals were for the old data
    loadScene();
    setupCamera();
    setNavigationMode(options_.navigation);
    lastShown_.reset();
    errorLine_.clear();
    glfwSetWindowTitle(window_->handle(), ("volsg-view " + path).c_str());
    // The dialog opens next where this file is.
    const fs::path where = fs::path(path).parent_path();
    if (browser_.setFolder(where.empty() ? fs::current_path() : where))
        browserPanel_.typedFollowsFolder = true;
    if (const std::string why = recent_.add(path); !why.empty()) status(why);
    status("opened " + path);
}

void Viewer::requestOpen(const std::string& path, const OpenFileOptions& open) {
    if (sceneEdited()) {
        pendingOpen_ = {path, open};
        unsavedQuestionRequested_ = true;
        return;
    }
    openNext_ = {path, open}; // between frames: opening draws its own "loading" frame
}

void Viewer::openRequested() {
    if (!openNext_) return;
    const auto [path, open] = *openNext_;
    openNext_.reset();
    try {
        openFile(path, open);
    } catch (const Error& e) {
        // Error's text names the file (and the place in it); the old scene is still shown.
        errorLine_ = "cannot open " + fs::path(path).filename().string() + ": " + e.what();
        status(errorLine_);
    }
}

void Viewer::requestOpenOrAskLayout(const std::string& path) {
    if (!needsRawLayout(path)) {
        requestOpen(path, {});
        return;
    }
    // Raw voxels say nothing about themselves: the dialog asks, as --dims --type --spacing do.
    rawForm_.use = true;
    showOpenDialog(path);
    dialogError_ = fs::path(path).filename().string() +
                   " is raw voxels: give their dimensions, type and spacing, then Open";
}

void Viewer::onDrop(const std::vector<std::string>& paths) {
    if (!paths.empty()) dropped_ = paths;
}

void Viewer::openRecent(int index) {
    const auto& entries = recent_.entries();
    if (index < 0 || index >= int(entries.size())) {
        errorLine_ = "no recent file " + std::to_string(index + 1) + " (there are " +
                     std::to_string(entries.size()) + ")";
        status(errorLine_);
        return;
    }
    const std::string path = entries[std::size_t(index)];
    std::error_code ec;
    if (!fs::exists(path, ec)) {
        errorLine_ = "cannot open: " + path + ": it no longer exists";
        status(errorLine_);
        return;
    }
    // A raw file was opened with a layout the list does not keep: the dialog asks again.
    requestOpenOrAskLayout(path);
}

void Viewer::patientAxesFromData() {
    PatientAxes axes = patientAxes_;
    axes.fromFile = glm::dmat3(1.0);
    if (sections_.valid() && sections_.grid().geometry().known)
        axes.fromFile = PatientAxes::fromLpsDirections(sections_.grid().geometry().directions);
    setPatientAxes(axes);
}

// ---- the open dialog ------------------------------------------------------------------------

void Viewer::showOpenDialog(const std::string& selectPath) {
    openDialogRequested_ = true;
    dialogError_.clear();
    if (selectPath.empty()) return;
    const fs::path p(selectPath);
    browser_.setFolder(p.parent_path().empty() ? fs::current_path() : p.parent_path());
    browserPanel_.typedFollowsFolder = true;
    const auto& entries = browser_.entries();
    for (std::size_t i = 0; i < entries.size(); ++i)
        if (entries[i].name == p.filename().string()) browser_.select(int(i));
}

void Viewer::openFromDialog(const std::string& path) {
    OpenFileOptions open;
    if (rawForm_.use) {
        RawVolumeLayout raw;
        for (int a = 0; a < 3; ++a) {
            raw.dimensions[a] = rawForm_.dimensions[a];
            raw.spacing[a] = double(rawForm_.spacing[a]);
        }
        raw.type = VoxelType(std::clamp(rawForm_.type, 0, 3));
        raw.bigEndian = rawForm_.bigEndian;
        raw.headerSkip = std::uint64_t(std::max(rawForm_.headerSkip, 0));
        if (glm::any(glm::lessThan(raw.dimensions, glm::ivec3(1))) ||
            glm::any(glm::greaterThan(raw.dimensions, glm::ivec3(limits::maxVolumeDimension))) ||
            !(raw.spacing.x > 0.0 && raw.spacing.y > 0.0 && raw.spacing.z > 0.0) ||
            !std::isfinite(raw.spacing.x + raw.spacing.y + raw.spacing.z)) {
            dialogError_ = fs::path(path).filename().string() +
                           ": give the raw voxels' dimensions (each 1 to " +
                           std::to_string(limits::maxVolumeDimension) + ") and spacing (> 0)";
            return;
        }
        open.raw = raw;
    } else if (needsRawLayout(path)) {
        rawForm_.use = true;
        dialogError_ = fs::path(path).filename().string() +
                       " is raw voxels: give their dimensions, type and spacing, then Open";
        return;
    }
    openDialogShown_ = false;
    ImGui::CloseCurrentPopup();
    requestOpen(path, open);
}

void Viewer::drawOpenDialog() {
    const char* title = "Open a file";
    if (openDialogRequested_) {
        ImGui::OpenPopup(title);
        openDialogRequested_ = false;
        openDialogShown_ = true;
        browser_.refresh();
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const ImVec2 size(std::min(display.x - 40.0f, 720.0f), std::min(display.y - 40.0f, 560.0f));
    ImGui::SetNextWindowSize(size, ImGuiCond_Always);
    ImGui::SetNextWindowPos(ImVec2(0.5f * display.x, 0.5f * display.y), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(title, nullptr,
                                ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoMove |
                                    ImGuiWindowFlags_NoSavedSettings)) {
        openDialogShown_ = false;
        return;
    }
    const float formHeight =
        (rawForm_.use ? 4.0f * ImGui::GetFrameHeightWithSpacing() : 0.0f) +
        (dialogError_.empty() ? 0.0f : 2.0f * ImGui::GetTextLineHeightWithSpacing());
    const float listHeight = std::max(80.0f, ImGui::GetContentRegionAvail().y - formHeight -
                                                 3.5f * ImGui::GetFrameHeightWithSpacing());
    const std::string chosen = drawFileBrowserPanel(browser_, browserPanel_, listHeight);
    auto& places = browserPanel_.places;
    const auto remember = [&places](const char* name) {
        places[name] = {ImGui::GetItemRectMin(), ImGui::GetItemRectMax()};
    };
    ImGui::SameLine(0.0f, 24.0f);
    ImGui::Checkbox("raw voxels", &rawForm_.use);
    remember("raw");
    if (rawForm_.use) {
        ImGui::InputInt3("dimensions X Y Z", rawForm_.dimensions);
        remember("dims");
        ImGui::Combo("type", &rawForm_.type, "uchar\0ushort\0short\0float\0");
        ImGui::InputFloat3("spacing X Y Z", rawForm_.spacing, "%g");
        ImGui::Checkbox("big-endian", &rawForm_.bigEndian);
        ImGui::SameLine();
        ImGui::SetNextItemWidth(120.0f);
        ImGui::InputInt("header bytes to skip", &rawForm_.headerSkip);
    }
    if (!dialogError_.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.35f, 1.0f));
        ImGui::TextWrapped("%s", dialogError_.c_str());
        ImGui::PopStyleColor();
    }
    if (!chosen.empty()) {
        openFromDialog(chosen);
    } else {
        const int selected = browser_.selected();
        const bool folderSelected =
            selected >= 0 && browser_.entries()[std::size_t(selected)].folder;
        ImGui::BeginDisabled(selected < 0);
        if (ImGui::Button(folderSelected ? "Open folder as DICOM series" : "Open"))
            openFromDialog(browser_.selectedPath());
        remember("open");
        ImGui::EndDisabled();
        ImGui::SameLine();
        if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
            openDialogShown_ = false;
            ImGui::CloseCurrentPopup();
        }
        remember("cancel");
    }
    ImGui::EndPopup();
}

void Viewer::drawUnsavedQuestion() {
    const char* title = "Unsaved edits";
    if (unsavedQuestionRequested_) {
        ImGui::OpenPopup(title);
        unsavedQuestionRequested_ = false;
    }
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0.5f * display.x, 0.5f * display.y), ImGuiCond_Always,
                            ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(title, nullptr,
                                ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove |
                                    ImGuiWindowFlags_NoSavedSettings))
        return;
    if (!pendingOpen_) {
        ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
        return;
    }
    ImGui::Text("%s has unsaved edits.", fs::path(options_.scenePath).filename().string().c_str());
    ImGui::Text("Open %s instead?", fs::path(pendingOpen_->first).filename().string().c_str());
    if (ImGui::Button("Save, then open")) answerUnsavedQuestion(1);
    ImGui::SameLine();
    if (ImGui::Button("Open without saving")) answerUnsavedQuestion(2);
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) answerUnsavedQuestion(0);
    ImGui::EndPopup();
}

void Viewer::answerUnsavedQuestion(int answer) {
    if (!pendingOpen_) return;
    const auto [path, open] = *pendingOpen_;
    pendingOpen_.reset();
    // The question's popup closes itself on its next frame (drawUnsavedQuestion).
    if (answer == 0) {
        status("not opened " + path + ": the edited scene stays");
        return;
    }
    if (answer == 1) {
        saveScene(scenePathForSaving(options_.scenePath, options_.open));
        if (sceneEdited()) return; // the save failed (the status says why): stay
    }
    savedChangeCount_ = history_.changeCount(); // the edits are given up
    requestOpen(path, open);
}

// ---- the menu bar of the panel column -------------------------------------------------------

void Viewer::drawMenuBar() {
    if (!ImGui::BeginMenuBar()) return;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Open...", "Ctrl+O")) showOpenDialog();
        if (ImGui::BeginMenu("Open recent", !recent_.entries().empty())) {
            const auto& entries = recent_.entries();
            for (int i = 0; i < int(entries.size()); ++i) {
                std::error_code ec;
                // A file that is gone is shown, disabled, so the list still says what it was.
                const bool exists = fs::exists(entries[std::size_t(i)], ec);
                const std::string label = std::to_string(i + 1) + "  " + entries[std::size_t(i)];
                if (ImGui::MenuItem(label.c_str(), nullptr, false, exists)) openRecent(i);
            }
            ImGui::EndMenu();
        }
        if (ImGui::MenuItem("Save", "Ctrl+S"))
            saveScene(scenePathForSaving(options_.scenePath, options_.open));
        if (ImGui::MenuItem("Quit", "Q")) quit_ = true;
        ImGui::EndMenu();
    }
    ImGui::EndMenuBar();
}

} // namespace volsg
