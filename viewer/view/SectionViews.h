#pragma once
// The viewer's three orthogonal section views of the scene's first volume (sagittal, coronal,
// axial: looking along the volume's x, y and z axes, in radiological convention or flipped) and
// the linked 3D cursor.
//
// Each section view is an orthographic camera on a small graph that USEs the scene's own
// VolumeData and TransferFunction nodes under the volume's model matrix:
//
//   Separator { MatrixTransform { <model at the volume> }  USE data  USE tf...  OrthoSlice { } }
//
// so one Renderer draws all views from the same GL resources (textures and tables are cached
// per node). The cursor is a voxel of that volume: setting it moves the three section planes
// (their sliceNumbers) and every OrthoSlice of the scene on that volume through it.

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/core/Node.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/OrthoSlice.h> // complete: held by ref_ptr
#include <volsg/nodes/VolumeData.h>

#include "PatientOrientation.h"

namespace volsg {

class MatrixTransform;
class TransferFunction;

class SectionViews {
public:
    /// The anatomical planes; each view slices along the volume axis nearest its normal
    /// (axisOf: the same axis for a volume stored in the viewer's convention).
    enum Section { Sagittal = 0, Coronal = 1, Axial = 2 };
    static const char* name(int section); ///< "sagittal", "coronal", "axial"
    /// The section named `name`, or -1.
    static int sectionNamed(const std::string& name);

    /// Finds the first Volume, ShearWarpVolume, VolumeObject or slice of `root` in traversal
    /// order (else the first VolumeData) and builds the three section graphs on its data. The
    /// cursor starts in the middle of the volume, or on the scene's OrthoSlices along their
    /// axes (attaching changes nothing in the scene). False (and no views) when the scene has
    /// no volume or its data cannot be loaded.
    bool attach(Node& root);
    void detach();
    bool valid() const { return data_ != nullptr; }
    /// Follows edits of the scene since attach(): a moved volume (its model matrix) moves the
    /// views; another first volume or reloaded data attaches anew. Cheap: one traversal of the
    /// scene. Returns whether the views are valid.
    bool update(Node& root);

    Node& graph(int section) const { return *graphs_[std::size_t(section)]; }
    VolumeData& data() const { return *data_; }
    const VolumeGrid& grid() const { return *grid_; }
    /// The transfer function nearest the volume (the tag -1 one if any), or null.
    TransferFunction* transferFunction() const { return transferFunction_; }
    const glm::dmat4& model() const { return model_; }

    /// Radiological convention (the patient's left on the screen's right; sagittal: anterior on
    /// the left), or flipped: neurological (left on the left; sagittal: anterior on the right).
    /// Head (axial: anterior) up either way.
    void setFlipped(bool flipped) { flipped_ = flipped; }
    bool flipped() const { return flipped_; }
    /// How the volume's axes run in patient coordinates (PatientOrientation.h); by default the
    /// viewer's convention (x to the patient's right, y anterior, z superior).
    /// The sections then slice along the local axes nearest their patient normals.
    void setPatientAxes(const PatientAxes& axes);
    /// The volume axis a section slices along (its OrthoSlice::axis, the cursor component it
    /// shows).
    int axisOf(int section) const { return axisOf_[std::clamp(section, 0, 2)]; }
    const PatientAxes& patientAxes() const { return patientAxes_; }
    /// The orthographic camera of a section view with this aspect (width / height), in world
    /// coordinates: the volume's box fills the view with a small margin.
    ref_ptr<Camera> camera(int section, double aspect) const;
    /// The world point of pixel (x, y) of a width x height section view on its current plane,
    /// as the voxel whose cell holds it; std::nullopt outside the volume's box.
    std::optional<glm::ivec3> voxelAtPixel(int section, const glm::dvec2& pixel, int width,
                                           int height) const;
    /// Where a world point shows in a width x height section view (pixels, origin top-left).
    glm::dvec2 pixelOf(int section, const glm::dvec3& world, int width, int height) const;

    /// The voxel of a world point (the cell holding it), or std::nullopt outside the box.
    std::optional<glm::ivec3> voxelAtWorld(const glm::dvec3& world) const;
    glm::dvec3 worldOf(const glm::ivec3& voxel) const; ///< the voxel's centre

    const glm::ivec3& cursor() const { return cursor_; }
    /// Moves the cursor (clamped to the grid) and the section planes through it: the views'
    /// slices and the scene's OrthoSlices on this volume (their sliceNumber along their axis).
    void setCursor(const glm::ivec3& voxel);
    /// The scene's OrthoSlices on this volume (moved by setCursor), for undo records.
    const std::vector<ref_ptr<OrthoSlice>>& sceneSlices() const { return sceneSlices_; }

private:
    ref_ptr<VolumeData> data_;
    ref_ptr<const VolumeGrid> grid_;
    TransferFunction* transferFunction_ = nullptr;
    glm::dmat4 model_{1.0};
    std::array<ref_ptr<Node>, 3> graphs_;
    std::array<MatrixTransform*, 3> transforms_{};
    std::array<OrthoSlice*, 3> slices_{};
    std::vector<ref_ptr<OrthoSlice>> sceneSlices_;
    glm::ivec3 cursor_{0};
    bool flipped_ = false;
    PatientAxes patientAxes_;
    glm::ivec3 axisOf_{0, 1, 2};
};

} // namespace volsg
