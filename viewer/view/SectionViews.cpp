#include "SectionViews.h"

#include "PatientOrientation.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

#include <volsg/actions/Action.h>
#include <volsg/core/Error.h>
#include <volsg/editors/RegionHistogram.h>
#include <volsg/manipulators/DragMath.h>
#include <volsg/nodes/MatrixTransform.h>
#include <volsg/nodes/ObliqueSlice.h>
#include <volsg/nodes/OrthoSlice.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/nodes/VolumeObject.h>
#include <volsg/volume/VolumeGrid.h>

namespace volsg {

namespace {

/// Where the first volume of a scene is drawn: its data, model matrix and transfer functions
/// (the state at the first node that draws a volume), and every OrthoSlice with its data.
class FirstVolumeAction : public Action {
public:
    const VolumeData* data = nullptr;
    glm::dmat4 model{1.0};
    std::vector<const TransferFunction*> transferFunctions;
    std::vector<std::pair<OrthoSlice*, const VolumeData*>> slices;
    const VolumeData* firstData = nullptr;
    glm::dmat4 firstDataModel{1.0};

protected:
    void dispatch(Node& node) override {
        node.doAction(*this);
        const VolumeData* inScope = state().nearestNode<VolumeData>();
        if (node.isA<VolumeData>() && !firstData) {
            firstData = static_cast<const VolumeData*>(&node);
            firstDataModel = state().modelMatrix();
        }
        if (node.isA<OrthoSlice>()) slices.emplace_back(static_cast<OrthoSlice*>(&node), inScope);
        const bool drawsVolume = node.isA<Volume>() || node.isA<ShearWarpVolume>() ||
                                 node.isA<VolumeObject>() || node.isA<OrthoSlice>() ||
                                 node.isA<ObliqueSlice>();
        if (drawsVolume && inScope && !data) {
            data = inScope;
            model = state().modelMatrix();
            for (const StateEntry* e : state().all<TransferFunction>())
                transferFunctions.push_back(static_cast<const TransferFunction*>(e->node));
        }
    }
};

} // namespace

const char* SectionViews::name(int section) {
    static const char* names[3] = {"sagittal", "coronal", "axial"};
    return section >= 0 && section < 3 ? names[section] : "?";
}

int SectionViews::sectionNamed(const std::string& text) {
    for (int s = 0; s < 3; ++s)
        if (text == name(s)) return s;
    return -1;
}

void SectionViews::detach() {
    data_ = nullptr;
    grid_ = nullptr;
    transferFunction_ = nullptr;
    graphs_ = {};
    transforms_ = {};
    slices_ = {};
    sceneSlices_.clear();
}

bool SectionViews::attach(Node& root) {
    detach();
    FirstVolumeAction find;
    find.apply(root);
    const VolumeData* data = find.data ? find.data : find.firstData;
    if (!data) return false;
    try {
        grid_ = data->grid();
    } catch (const Error&) {
        return false; // the 3D view shows the error; sections have nothing to show
    }
    data_ = ref_ptr<VolumeData>(const_cast<VolumeData*>(data));
    model_ = find.data ? find.model : find.firstDataModel;
    for (const TransferFunction* tf : find.transferFunctions)
        if (!transferFunction_ || tf->tag() == -1)
            transferFunction_ = const_cast<TransferFunction*>(tf);
    for (const auto& [slice, sliceData] : find.slices)
        if (sliceData == data) sceneSlices_.emplace_back(slice);

    const glm::mat4 model(model_);
    for (int s = 0; s < 3; ++s) {
        auto graph = Separator::create();
        auto transform = MatrixTransform::create();
        transform->matrix = model;
        transforms_[std::size_t(s)] = transform.get();
        graph->addChild(transform);
        graph->addChild(data_); // USE: the scene's own node, so its GL resources are shared
        for (const TransferFunction* tf : find.transferFunctions)
            graph->addChild(ref_ptr<Node>(const_cast<TransferFunction*>(tf)));
        auto slice = OrthoSlice::create();
        slice->axis = axisOf(s);
        slice->alphaUse = OrthoSlice::ALPHA_OPAQUE; // a section shows every voxel's colour
        slices_[std::size_t(s)] = slice.get();
        graph->addChild(slice);
        graphs_[std::size_t(s)] = graph;
    }
    // The cursor starts in the middle, or on the scene's own slices: attaching moves no plane of
    // the scene.
    cursor_ = grid_->dimensions() / 2;
    for (const ref_ptr<OrthoSlice>& slice : sceneSlices_) {
        const int axis = std::clamp(slice->axis(), 0, 2);
        cursor_[axis] = std::clamp(slice->sliceNumber(), 0, grid_->dimensions()[axis] - 1);
    }
    for (int s = 0; s < 3; ++s)
        slices_[std::size_t(s)]->sliceNumber = cursor_[axisOf(s)];
    return true;
}

void SectionViews::setPatientAxes(const PatientAxes& axes) {
    patientAxes_ = axes;
    axisOf_ = axes.localAxisOfRas();
    for (int s = 0; s < 3; ++s)
        if (OrthoSlice* slice = slices_[std::size_t(s)]) {
            if (slice->axis() != axisOf(s)) slice->axis = axisOf(s);
            if (slice->sliceNumber() != cursor_[axisOf(s)]) slice->sliceNumber = cursor_[axisOf(s)];
        }
}

bool SectionViews::update(Node& root) {
    FirstVolumeAction find;
    find.apply(root);
    const VolumeData* data = find.data ? find.data : find.firstData;
    ref_ptr<const VolumeGrid> grid;
    try {
        if (data) grid = data->grid();
    } catch (const Error&) {
        data = nullptr;
    }
    if (!data || data != data_.get() || grid != grid_) {
        return attach(root);
    }
    const glm::dmat4 model = find.data ? find.model : find.firstDataModel;
    if (model != model_) {
        model_ = model;
        for (MatrixTransform* t : transforms_)
            t->matrix = glm::mat4(model);
    }
    return true;
}

ref_ptr<Camera> SectionViews::camera(int section, double aspect) const {
    // The view's patient directions (radiological or flipped) in the volume's local axes, then
    // in the world through its model matrix. Screen right and up are what the convention
    // fixes; the camera looks along up x right, which is the patient's forward unless the
    // volume's axes are a mirror image of RAS (then it looks from the other side of the
    // plane, which shows the same section the right way round).
    // An oblique volume's slice is a plane of its own axes: the patient's up and right are
    // projected into it (along the slicing axis), the nearest it shows.
    const ViewDirection d = sectionViewDirection(section, flipped_);
    glm::dvec3 upLocal = patientAxes_.toLocal(d.up);
    glm::dvec3 rightLocal = patientAxes_.toLocal(glm::cross(d.forward, d.up));
    upLocal[axisOf(section)] = 0.0;
    rightLocal[axisOf(section)] = 0.0;
    if (glm::length(upLocal) < 1e-9 || glm::length(rightLocal) < 1e-9) { // degenerate axes
        upLocal = rightLocal = glm::dvec3(0.0);
        upLocal[(axisOf(section) + 2) % 3] = 1.0;
        rightLocal[(axisOf(section) + 1) % 3] = 1.0;
    }
    upLocal = glm::normalize(upLocal);
    rightLocal = glm::normalize(rightLocal);
    const glm::dmat3 linear(model_);
    const glm::dvec3 extent = grid_->extent();
    const glm::dvec3 up = glm::normalize(linear * upLocal);
    const glm::dvec3 forward = glm::normalize(glm::cross(up, linear * rightLocal));
    // The box's extent across the view: its edges projected on the view's up and right (an
    // oblique volume's slice shows turned, its corners further out).
    const glm::dvec3 right = glm::normalize(linear * rightLocal);
    double upExtent = 0.0, rightExtent = 0.0;
    for (int a = 0; a < 3; ++a) {
        if (a == axisOf(section)) continue;
        const glm::dvec3 edge = linear[a] * extent[a];
        upExtent += std::abs(glm::dot(edge, up));
        rightExtent += std::abs(glm::dot(edge, right));
    }
    const double depth = glm::length(linear * extent); // the box's diagonal
    auto camera = OrthographicCamera::create();
    camera->height = float(1.06 * std::max(upExtent, rightExtent / std::max(aspect, 1e-6)));
    const glm::dvec3 center(model_ * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    camera->position = glm::vec3(center - forward * depth);
    camera->focalDistance = float(depth);
    camera->nearDistance = float(0.01 * depth);
    camera->farDistance = float(2.0 * depth);
    camera->orientation = rotationFromQuat(cameraOrientation(forward, up));
    return camera;
}

std::optional<glm::ivec3> SectionViews::voxelAtWorld(const glm::dvec3& world) const {
    if (!valid()) return std::nullopt;
    const glm::dvec3 local(glm::inverse(model_) * glm::dvec4(world, 1.0));
    return RegionHistogram::voxelAt(*grid_, local);
}

glm::dvec3 SectionViews::worldOf(const glm::ivec3& voxel) const {
    return glm::dvec3(model_ * glm::dvec4(grid_->voxelCenter(voxel.x, voxel.y, voxel.z), 1.0));
}

std::optional<glm::ivec3> SectionViews::voxelAtPixel(int section, const glm::dvec2& pixel,
                                                     int width, int height) const {
    if (!valid() || width < 1 || height < 1) return std::nullopt;
    const ref_ptr<Camera> c = camera(section, double(width) / double(height));
    const glm::dmat4 toWorld =
        glm::inverse(c->projectionMatrix(double(width) / double(height)) * c->viewMatrix());
    const glm::dvec4 ndc(2.0 * pixel.x / width - 1.0, 1.0 - 2.0 * pixel.y / height, 0.0, 1.0);
    const glm::dvec4 world = toWorld * ndc;
    // The ray runs along the section's axis: in local coordinates only that coordinate varies,
    // and the plane fixes it at the slice's voxel centre.
    glm::dvec3 local(glm::inverse(model_) * (world / world.w));
    local[axisOf(section)] = grid_->voxelCenter(cursor_.x, cursor_.y, cursor_.z)[axisOf(section)];
    return RegionHistogram::voxelAt(*grid_, local);
}

glm::dvec2 SectionViews::pixelOf(int section, const glm::dvec3& world, int width,
                                 int height) const {
    const ref_ptr<Camera> c = camera(section, double(width) / double(height));
    const glm::dvec4 clip = c->projectionMatrix(double(width) / double(height)) * c->viewMatrix() *
                            glm::dvec4(world, 1.0);
    return {(clip.x / clip.w + 1.0) * 0.5 * width, (1.0 - clip.y / clip.w) * 0.5 * height};
}

void SectionViews::setCursor(const glm::ivec3& voxel) {
    if (!valid()) return;
    cursor_ = glm::clamp(voxel, glm::ivec3(0), grid_->dimensions() - 1);
    for (int s = 0; s < 3; ++s)
        if (slices_[std::size_t(s)]->sliceNumber() != cursor_[axisOf(s)])
            slices_[std::size_t(s)]->sliceNumber = cursor_[axisOf(s)];
    for (const ref_ptr<OrthoSlice>& slice : sceneSlices_) {
        const int axis = std::clamp(slice->axis(), 0, 2);
        if (slice->sliceNumber() != cursor_[axis]) slice->sliceNumber = cursor_[axis];
    }
}

} // namespace volsg
