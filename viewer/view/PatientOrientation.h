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

/// How the volume's local axes run in patient coordinates (RAS). `fromFile` is what the data
/// file says (its columns: the RAS directions of the local x, y and z axes; the identity for a
/// file without geometry, the viewer's convention: x from the patient's left to right, y
/// posterior to anterior, z inferior to superior); `signs` reverses local axes on top of it
/// (the Scene panel's boxes, script `axes`: a file stored head first along z without saying
/// so, like VTK's headsq, needs z reversed).
struct PatientAxes {
    glm::dvec3 signs{1.0};
    glm::dmat3 fromFile{1.0};

    /// From a file's geometry: the LPS directions of its index axes (VolumeGeometry).
    static glm::dmat3 fromLpsDirections(const glm::dmat3& lps);
    /// Local axes to RAS: fromFile with the reversals.
    glm::dmat3 localToRas() const;
    /// A RAS direction in the volume's local coordinates.
    glm::dvec3 toLocal(const glm::dvec3& ras) const;
    /// A local direction in RAS.
    glm::dvec3 toRas(const glm::dvec3& local) const { return localToRas() * local; }
    /// The anatomical letter of the direction +axis (or -axis) of the volume: R/L, A/P, S/I
    /// (of the largest RAS component, for an oblique axis).
    char letter(int axis, bool positive) const;
    /// The local axis nearest each RAS axis (R, A, S): a permutation, so an oblique volume's
    /// sagittal, coronal and axial sections each slice along a different local axis.
    glm::ivec3 localAxisOfRas() const;
};

/// The anatomical letter of a RAS direction: of its largest component (R L A P S I).
char patientLetter(const glm::dvec3& ras);

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
