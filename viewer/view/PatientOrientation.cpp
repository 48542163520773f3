#include "PatientOrientation.h"

#include <algorithm>

namespace volsg {

char PatientAxes::letter(int axis, bool positive) const {
    static const char plus[3] = {'R', 'A', 'S'}, minus[3] = {'L', 'P', 'I'};
    axis = std::clamp(axis, 0, 2);
    const bool towardsPlus = positive == (signs[axis] >= 0.0);
    return towardsPlus ? plus[axis] : minus[axis];
}

const char* anatomicalViewName(AnatomicalView view) {
    static const char* names[kAnatomicalViewCount] = {"anterior", "posterior", "left",
                                                      "right",    "superior",  "inferior"};
    return names[std::clamp(int(view), 0, kAnatomicalViewCount - 1)];
}

std::optional<AnatomicalView> parseAnatomicalView(const std::string& name) {
    for (int v = 0; v < kAnatomicalViewCount; ++v)
        if (name == anatomicalViewName(AnatomicalView(v))) return AnatomicalView(v);
    return std::nullopt;
}

ViewDirection anatomicalViewDirection(AnatomicalView view) {
    switch (view) {
    case AnatomicalView::Anterior:
        return {{0, -1, 0}, {0, 0, 1}};
    case AnatomicalView::Posterior:
        return {{0, 1, 0}, {0, 0, 1}};
    case AnatomicalView::Left: // from the patient's left side (-x), looking towards +x
        return {{1, 0, 0}, {0, 0, 1}};
    case AnatomicalView::Right:
        return {{-1, 0, 0}, {0, 0, 1}};
    case AnatomicalView::Superior:
        return {{0, 0, -1}, {0, 1, 0}};
    case AnatomicalView::Inferior:
        return {{0, 0, 1}, {0, 1, 0}};
    }
    return {};
}

ViewDirection sectionViewDirection(int section, bool flipped) {
    // Sagittal from the left (+x), coronal from the front (-y), axial from the feet (+z).
    static const ViewDirection radiological[3] = {
        {{1, 0, 0}, {0, 0, 1}}, {{0, -1, 0}, {0, 0, 1}}, {{0, 0, 1}, {0, 1, 0}}};
    ViewDirection d = radiological[std::clamp(section, 0, 2)];
    if (flipped) d.forward = -d.forward;
    return d;
}

glm::dquat cameraOrientation(const glm::dvec3& forward, const glm::dvec3& up) {
    const glm::dvec3 f = glm::normalize(forward);
    const glm::dvec3 right = glm::normalize(glm::cross(f, up));
    return glm::quat_cast(glm::dmat3(right, glm::cross(right, f), -f));
}

} // namespace volsg
