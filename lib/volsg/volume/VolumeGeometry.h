#pragma once
// Where a volume file puts its grid in the world of the scanner: the direction of each index
// axis and the position of the first voxel, in patient coordinates (DICOM's LPS: +x towards
// the patient's left, +y posterior, +z superior), millimetres.

#include <glm/glm.hpp>

namespace volsg {

/// The file's geometry of a VolumeGrid. A voxel (i, j, k) lies at
/// `origin + directions * (spacing * (i, j, k))` (spacing is the grid's). Readers of formats
/// that carry it fill it (NIfTI qform/sform, DICOM Image Position/Orientation (Patient), NRRD
/// `space directions` and `space origin`, MetaImage `Offset`/`TransformMatrix`), converted to
/// LPS; a raw file has none (`known` false: identity directions, zero origin).
struct VolumeGeometry {
    bool known = false;
    glm::dmat3 directions{1.0}; ///< columns: unit vectors of the i, j and k axes (LPS)
    glm::dvec3 origin{0.0};     ///< centre of voxel (0, 0, 0) (LPS, mm)

    /// From the grid's local coordinates (centred on its origin, extent dimensions * spacing;
    /// VolumeGrid) to patient coordinates: what a scene puts in a MatrixTransform above the
    /// VolumeData to place the volume as the scanner did.
    glm::dmat4 localToPatient(const glm::ivec3& dimensions, const glm::dvec3& spacing) const {
        // local = (index + 0.5) * spacing - extent / 2, so index * spacing = local + shift.
        const glm::dvec3 shift = 0.5 * glm::dvec3(dimensions) * spacing - 0.5 * spacing;
        glm::dmat4 m(directions);
        m[3] = glm::dvec4(origin + directions * shift, 1.0);
        return m;
    }
};

} // namespace volsg
