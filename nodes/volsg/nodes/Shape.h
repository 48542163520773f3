#pragma once
// Base of geometry nodes: a shape only says how to build its Mesh; drawing, bounding boxes and
// picking are done once for all shapes from that mesh (nodes/volsg/render/ShapeRendering.cpp,
// the bounding box and pick actions).

#include <cstdint>
#include <vector>

#include <volsg/core/Node.h>
#include <volsg/geometry/Mesh.h>

namespace volsg {

class State;

class Shape : public Inherit<Node, Shape> {
public:
    static constexpr const char* typeName = "Shape";

    /// The mesh for the current state, rebuilt only when meshKey() changes.
    const Mesh& mesh(const State& state) const;
    /// The bounds of mesh(state), found once per build (a text's mesh under many instances is
    /// bounded once, not once per instance).
    const Box3& meshBounds(const State& state) const;
    /// Identifies everything the mesh depends on; the node's version by default. Shapes that
    /// read state (IndexedFaceSet reads Coordinate3 and Normal) combine their versions.
    virtual std::uint64_t meshKey(const State& state) const;
    /// Coarser tessellations of mesh(state), finest first, for shapes that tessellate a curved
    /// surface (Sphere, Cone, Cylinder); none by default. Renderers draw one where its deviation
    /// projects below a fraction of a pixel (lib/volsg/render/ShapeDetail.h); bounding boxes
    /// and picking keep mesh(state).
    virtual void buildCoarserMeshes(const State& state, std::vector<CoarserMesh>& out) const;

protected:
    ~Shape() override = default;
    virtual void buildMesh(const State& state, Mesh& out) const = 0;

private:
    mutable Mesh mesh_;
    mutable Box3 meshBounds_;
    mutable std::uint64_t meshKey_ = 0;
    mutable bool meshValid_ = false;
};

} // namespace volsg
