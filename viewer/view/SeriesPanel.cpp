#include "SeriesPanel.h"

#include <algorithm>

#include <imgui.h>

#include <volsg/actions/SearchAction.h>
#include <volsg/core/Error.h>
#include <volsg/nodes/VolumeSeries.h>

namespace volsg {

SeriesPanel::SeriesPanel() = default;
SeriesPanel::~SeriesPanel() = default;

void SeriesPanel::attach(Node* root) {
    series_ = nullptr;
    player_.pause();
    if (!root) return;
    const auto found = findAll(*root, VolumeSeries::classType());
    if (!found.empty()) series_ = ref_ptr<VolumeSeries>(static_cast<VolumeSeries*>(found.front()));
}

void SeriesPanel::play(double now) {
    if (series_) player_.play(now);
}

void SeriesPanel::pause() {
    player_.pause();
}

void SeriesPanel::togglePlay(double now) {
    player_.playing() ? pause() : play(now);
}

void SeriesPanel::setStep(int step) {
    if (!series_) return;
    player_.pause();
    try {
        series_->step = std::clamp(step, 0, series_->stepCount() - 1);
    } catch (const Error&) { // a malformed series: the panel shows the message
    }
}

void SeriesPanel::stepBy(int delta) {
    if (!series_) return;
    try {
        const int count = series_->stepCount();
        int next = series_->shownStep() + delta;
        if (series_->loop()) next = ((next % count) + count) % count;
        player_.setDirection(delta);
        setStep(next);
    } catch (const Error&) { // as above
    }
}

bool SeriesPanel::update(double now) {
    if (!series_ || !player_.playing()) return false;
    try {
        const int current = series_->shownStep();
        const int next = player_.advance(now, current, series_->stepCount(), series_->loop());
        if (next == current) return false;
        series_->step = next;
        return true;
    } catch (const Error&) { // as above
        player_.pause();
        return false;
    }
}

void SeriesPanel::draw(double now) {
    if (!series_) return;
    int count = 1;
    SeriesCacheStats s;
    try {
        count = series_->stepCount();
        s = series_->cache().stats();
    } catch (const Error& e) {
        ImGui::TextWrapped("%s", e.what());
        return;
    }
    if (!ImGui::CollapsingHeader("Series", ImGuiTreeNodeFlags_DefaultOpen)) return;
    int step = series_->shownStep();
    if (ImGui::SliderInt("step", &step, 0, count - 1)) setStep(step);
    if (ImGui::Button("<")) stepBy(-1);
    ImGui::SameLine();
    if (ImGui::Button(player_.playing() ? "pause" : "play")) togglePlay(now);
    ImGui::SameLine();
    if (ImGui::Button(">")) stepBy(+1);
    ImGui::SameLine();
    bool backward = player_.direction() < 0;
    if (ImGui::Checkbox("backward", &backward)) player_.setDirection(backward ? -1 : 1);
    float speed = float(player_.stepsPerSecond());
    if (ImGui::SliderFloat("steps/s", &speed, 0.5f, 60.0f, "%.1f"))
        player_.setStepsPerSecond(speed);
    ImGui::Text("lists %.1f / %.0f MB in memory, %.1f MB on disk",
                double(s.memoryBytes) / 1048576.0, double(series_->cacheMegabytes()),
                double(s.diskBytes) / 1048576.0);
    ImGui::Text("%llu extracted, %llu read back, %llu waits", (unsigned long long)s.extractions,
                (unsigned long long)s.diskReads, (unsigned long long)s.waits);
}

} // namespace volsg
