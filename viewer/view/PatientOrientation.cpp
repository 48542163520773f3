#include "PatientOrientation.h"

#include <algorithm>
#include <cmath>

namespace volsg {

glm::dmat3 PatientAxes::fromLpsDirections(const glm::dmat3& lps) {
    // LPS to RAS negates x and y.
    return glm::dmat3(glm::dvec3(-1.0, 0.0, 0.0), glm::dvec3(0.0, -1.0, 0.0),
                      glm::dvec3(0.0, 0.0, 1.0)) *
           lps;
}

glm::dmat3 PatientAxes::localToRas() const {
    glm::dmat3 m = fromFile;
    for (int a = 0; a < 3; ++a)
        m[a] *= signs[a] < 0.0 ? -1.0 : 1.0;
    return m;
}

glm::dvec3 PatientAxes::toLocal(const glm::dvec3& ras) const {
    const glm::dmat3 m = localToRas();
    // A degenerate matrix (a broken file) falls back to the convention rather than to NaN.
    if (!(std::abs(glm::determinant(m)) > 1e-12)) return ras * signs;
    return glm::inverse(m) * ras;
}

char patientLetter(const glm::dvec3& d) {
    const glm::dvec3 a = glm::abs(d);
    const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
    static const char plus[3] = {'R', 'A', 'S'}, minus[3] = {'L', 'P', 'I'};
    return d[axis] >= 0.0 ? plus[axis] : minus[axis];
}

char PatientAxes::letter(int axis, bool positive) const {
    glm::dvec3 local(0.0);
    local[std::clamp(axis, 0, 2)] = positive ? 1.0 : -1.0;
    return patientLetter(toRas(local));
}

glm::ivec3 PatientAxes::localAxisOfRas() const {
    // The pairs (RAS axis, local axis) by how closely they align, best first: each takes the
    // best pair whose two axes are both still free.
    const glm::dmat3 m = localToRas(); // m[local][ras]
    glm::ivec3 out(-1);
    bool localTaken[3] = {false, false, false};
    for (int round = 0; round < 3; ++round) {
        double best = -1.0;
        int bestRas = 0, bestLocal = 0;
        for (int r = 0; r < 3; ++r)
            for (int l = 0; l < 3; ++l)
                if (out[r] < 0 && !localTaken[l] && std::abs(m[l][r]) > best) {
                    best = std::abs(m[l][r]);
                    bestRas = r;
                    bestLocal = l;
                }
        out[bestRas] = bestLocal;
        localTaken[bestLocal] = true;
    }
    return out;
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
