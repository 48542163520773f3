#pragma once
// BoxClipManip: a BoxClip with handles (the seed's box manipulator). The box is drawn as its
// twelve edges; drag a face handle to move that face along its axis, or a corner to move the
// corner in the plane facing the viewer.

#include <volsg/manipulators/Manipulator.h>
#include <volsg/nodes/BoxClip.h>

namespace volsg {

class BoxClipManip : public Inherit<BoxClip, BoxClipManip>, public Manipulator {
public:
    static constexpr const char* typeName = "BoxClipManip";
    /// Parts: 12 edges (ids 0-11), then faces -x +x -y +y -z +z (12-17), then corners (18-25,
    /// bit 0 of the corner number: +x, bit 1: +y, bit 2: +z).
    static constexpr int firstEdge = 0, firstFace = 12, firstCorner = 18;
    /// No drag makes the box thinner than this, in local units.
    static constexpr double minimumExtent = 1e-3;

    Node& node() override { return *this; }

protected:
    ~BoxClipManip() override = default;
    void buildHandles(DraggerGeometry& handles) override;
    void placeHandles() override;
    void startDrag(int part, const Ray& localRay) override;
    void continueDrag(int part, const Ray& localRay) override;

private:
    glm::dvec3 startMin_{0.0}, startMax_{0.0};
    glm::dvec3 startGrab_{0.0}, dragNormal_{0.0, 0.0, 1.0};
    double startLine_ = 0.0;
    bool grabValid_ = false;
    void setBox(glm::dvec3 lo, glm::dvec3 hi);
};

} // namespace volsg
