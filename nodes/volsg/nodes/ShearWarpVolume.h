#pragma once
// ShearWarpVolume: the RTVR voxel-list renderer as a node. A group of TransferFunction and
// BoxClip state nodes and VolumeObject children (Inventor style: each VolumeObject takes the
// state before it), drawing the VolumeData in scope by shear-warp on the CPU in the Volume pass.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <volsg/fields/Fields.h>
#include <volsg/nodes/Group.h>
#include <volsg/shearwarp/ShearWarpRenderer.h>
#include <volsg/slicing/SlicingQuality.h>

namespace volsg {

class VolumeObject;
class VoxelListOptimizer;

class ShearWarpVolume : public Inherit<Group, ShearWarpVolume> {
public:
    static constexpr const char* typeName = "ShearWarpVolume";
    enum InterObject { DVR, MIP };
    static const EnumValues interObjectNames;

    SFEnum interObjectCompositing{this, "interObjectCompositing", interObjectNames, DVR};
    SFBool optimize{this, "optimize", true}; ///< run the idle-time optimizer
    SFInt32 threads{this, "threads", 0};     ///< 0: every core
    /// While the viewer reports interaction: composite every n-th slice (opacity-corrected), n
    /// = interactiveSliceStep divided by the viewer's interactive plane scale (at most 16).
    /// SURFACE objects keep every slice. 1: full quality while interacting too.
    SFInt32 interactiveSliceStep{this, "interactiveSliceStep", 2};
    /// RMSE per channel, in 1/255, against the rendering model: still frames draw every slice
    /// (the error there is shear-warp's floor, reported); while interacting the slice step is
    /// the largest whose predicted error meets interactiveErrorTarget, unless
    /// interactiveSliceStep is set. Predicted for DVR of transfer-function objects only.
    SFFloat errorTarget{this, "errorTarget", 0.5f};
    SFFloat interactiveErrorTarget{this, "interactiveErrorTarget", 2.0f};
    /// Pure MIP scenes (every object MIP, MIP between them, nothing clipped, no opaque
    /// geometry) draw value-sorted voxels onto their nearest pixel, with no maximum search.
    /// FALSE: the general path, which resamples each slice bilinearly (slower, a little closer
    /// to the reference).
    SFBool valueSortedMip{this, "valueSortedMip", true};
    /// A compact voxel-list file (.vsgv, lib/volsg/voxelfile/README.md), "path" or "path#k"
    /// for its volume k: the objects' voxels come from it instead of the VolumeData in scope.
    SFString voxelFile{this, "voxelFile", ""};

    /// Renders `objects` (gathered from the state: gatherShearWarpObjects,
    /// nodes/volsg/volumescene/ShearWarpObjects.h) with this node's engine, reusing the last
    /// frame's buffers, and keeps the frame for picking; `sources` are the objects' VolumeObject
    /// nodes and `model` the model matrix at this node. Hands the lists to the idle-time
    /// optimizer when `optimize` is on.
    const ShearWarpFrame& renderFrame(std::vector<ShearWarpObject>& objects,
                                      const ShearWarpView& view, std::vector<VolumeObject*> sources,
                                      const glm::dmat4& model);

    /// The frame the last render drew (for picking and tests), or null.
    const ShearWarpFrame* lastFrame() const { return lastFrame_.get(); }
    /// What the last frame shows at pixel (x, y) (row 0 at the top): the VolumeObject and the
    /// point in world coordinates. Empty where nothing was hit.
    struct Pick {
        VolumeObject* object = nullptr;
        glm::dvec3 worldPosition{0.0};
    };
    std::optional<Pick> pickAt(int x, int y) const;

    /// Bytes of the voxel lists (extracted voxels and every RenderList built) of the objects
    /// the last frame drew.
    std::size_t voxelListBytes() const;

    /// Blocks until the optimizer has finished with the current lists.
    void waitForOptimizer();

    /// The slice step a frame uses: 1 for still frames; while interactive,
    /// interactiveSliceStep / interactivePlaneScale rounded, in [1, 16].
    int sliceStepFor(bool interactive, double interactivePlaneScale) const;

    /// The last frame's error: predicted by the error model (lib/volsg/slicing/SlabErrorModel.h)
    /// for the slice step used, and at step 1 (shear-warp's floor: one sample per slice,
    /// classification before resampling), against the frame's target (0..1 units).
    struct Quality {
        bool predicted = false;
        int sliceStep = 1;
        double predictedRmse = 0.0, floorRmse = 0.0, target = 0.0;
        /// A paged volume (lib/volsg/paging/README.md, "Shear-warp"): the pyramid level drawn,
        /// read whole, the level the view asks for (its voxels at most a pixel, within the
        /// memory budget), and whether a finer level is still loading. -1: not paged.
        int pagedLevel = -1, wantedLevel = -1;
        bool refining = false;
        std::string levelError; ///< why the wanted level could not be read (it stays coarser)
    };
    /// The last frame's quality. Where the frame's view direction had no rays of the error
    /// model cast yet, the prediction is made here, when first read, not in the frame: casting
    /// them costs more than a frame (8-35 ms a new direction on the head CT and on
    /// Marschner-Lobb 256^3, against frames of 1-23 ms).
    const Quality& lastQuality() const;
    /// The same without predicting: `predicted` is false while a prediction waits for a read
    /// (for a display drawn every frame, which would cast every new direction).
    const Quality& lastQualityKnown() const { return quality_; }
    /// Whether the last frame's prediction waits for lastQuality().
    bool predictionPending() const { return pendingPrediction_.has_value(); }
    /// A prediction left to the first lastQuality(): along `directions` of this node's error
    /// model (the one errorModel() gave the frame), the image RMSE `scale` times the rays'.
    struct PendingPrediction {
        ModelDirections directions;
        double scale = 1.0;
    };
    void setLastQuality(const Quality& q, std::optional<PendingPrediction> pending = {}) {
        quality_ = q;
        pendingPrediction_ = pending;
    }
    /// The error model of `volume` (built when `key` changes; kept for the next frames).
    SlabErrorModel& errorModel(const RayCastVolume& volume, std::uint64_t key);
    /// The object drawn when the node has no VolumeObject child: WHOLE with every field at its
    /// default, so a bare ShearWarpVolume shows the whole volume through the transfer function
    /// in scope, as a Volume would. Made on first use, owned by this node (never a child).
    VolumeObject& wholeVolumeObject();

    /// The folder of the scene file: a relative voxelFile resolves against it.
    const std::string& directory() const { return directory_; }

    void doAction(Action& action) override;
    void readDone(const ReadContext& context) override;

    ShearWarpVolume();

protected:
    ~ShearWarpVolume() override;

private:
    ShearWarpRenderer renderer_;
    std::unique_ptr<VoxelListOptimizer> optimizer_;
    std::unique_ptr<ShearWarpFrame> lastFrame_;
    std::vector<VolumeObject*> lastSources_;
    std::vector<ref_ptr<VoxelObject>> lastObjects_;
    glm::dmat4 lastModel_{1.0};
    std::string directory_; ///< of the scene file: a relative voxelFile resolves against it
    mutable Quality quality_;
    mutable std::optional<PendingPrediction> pendingPrediction_; ///< filled by lastQuality()
    std::unique_ptr<SlabErrorModel> errorModel_;
    std::uint64_t errorModelKey_ = 0;
    ref_ptr<VolumeObject> wholeVolume_; ///< wholeVolumeObject()
};

} // namespace volsg
