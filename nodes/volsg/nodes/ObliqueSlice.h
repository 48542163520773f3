#pragma once
// ObliqueSlice: the current VolumeData through its TransferFunction(s) on an arbitrary plane,
// drawn as the textured polygon where the plane cuts the volume box (Open Inventor VolumeViz
// SoObliqueSlice).
#include <optional>

#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>
#include <volsg/nodes/OrthoSlice.h>
#include <volsg/sections/SlicePlane.h>

namespace volsg {

class ObliqueSlice : public Inherit<Node, ObliqueSlice> {
public:
    static constexpr const char* typeName = "ObliqueSlice";
    using Interpolation = OrthoSlice::Interpolation;
    using AlphaUse = OrthoSlice::AlphaUse;

    /// normal . p = distance, in the volume's local (object) coordinates.
    SFPlane plane{this, "plane", Plane{glm::vec3(0.0f, 0.0f, 1.0f), 0.0f}};
    /// LINEAR is trilinear.
    SFEnum interpolation{this, "interpolation", OrthoSlice::interpolationNames, OrthoSlice::LINEAR};
    SFEnum alphaUse{this, "alphaUse", OrthoSlice::alphaUseNames, OrthoSlice::ALPHA_BINARY};

    /// The plane normalised, or nothing for a zero normal (then nothing is drawn).
    std::optional<SlicePlane> localPlane() const;
    SliceStyle style() const; ///< interpolation and alphaUse as lib/volsg/sections takes them

protected:
    ~ObliqueSlice() override = default;
};

} // namespace volsg
