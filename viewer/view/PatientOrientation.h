#pragma once
// Anatomical directions for the viewer: the volume's axes in patient coordinates (RAS: +x the
// patient's right, +y anterior, +z superior; viewer/view/README.md), the six standard views
// of the 3D view (anterior ... inferior) and the three section views' directions in
// radiological or neurological convention.

#include <optional>
#include <string>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace volsg {

/// How the volume's local axes run in patient coordinates: local axis i runs along RAS axis i,
/// reversed where signs[i] is -1. All +1 (the default) is the viewer's convention for data
/// without geometry: x from the patient's left to right, y posterior to anterior, z inferior
/// to superior. A file stored head first along z (VTK's headsq) needs z reversed.
struct PatientAxes {
    glm::dvec3 signs{1.0};
    /// A RAS direction in the volume's local coordinates (and back: the map is its own
    /// inverse).
    glm::dvec3 toLocal(const glm::dvec3& ras) const { return ras * signs; }
    /// The anatomical letter of the direction +axis (or -axis) of the volume: R/L, A/P, S/I.
    char letter(int axis, bool positive) const;
};

/// A camera direction in patient coordinates: where it looks and which way is up.
struct ViewDirection {
    glm::dvec3 forward{0.0, 0.0, -1.0}, up{0.0, 1.0, 0.0};
};

enum class AnatomicalView { Anterior, Posterior, Left, Right, Superior, Inferior };
constexpr int kAnatomicalViewCount = 6;
const char* anatomicalViewName(AnatomicalView view); ///< "anterior", ...
std::optional<AnatomicalView> parseAnatomicalView(const std::string& name);

/// The 3D view from that side of the patient, head up (superior and inferior: anterior up):
/// anterior looks at the face (along -y), left looks at the patient's left side (along +x).
ViewDirection anatomicalViewDirection(AnatomicalView view);

/// A section view (0 sagittal, 1 coronal, 2 axial) in radiological convention: axial from the
/// feet and coronal from the front, so the patient's left is on the screen's right; sagittal
/// from the patient's left (anterior on the screen's left); head (axial: anterior) up.
/// Neurological (`flipped`): seen from the other side, left and right swap, up stays.
ViewDirection sectionViewDirection(int section, bool flipped);

/// The orientation of a camera looking along `forward` with `up` (world directions; up is
/// made perpendicular to forward): its -z along forward, its +y along up.
glm::dquat cameraOrientation(const glm::dvec3& forward, const glm::dvec3& up);

} // namespace volsg
