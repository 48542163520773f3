// The registry of node types the reader knows by name. A new node type adds one line here.
#include <volsg/nodes/BuiltinNodes.h>

#include <mutex>

#include <volsg/nodes/Annotation.h>
#include <volsg/nodes/AntiSquish.h>
#include <volsg/nodes/AppearanceKit.h>
#include <volsg/nodes/Array.h>
#include <volsg/nodes/AsciiText.h>
#include <volsg/nodes/BaseColor.h>
#include <volsg/nodes/BaseKit.h>
#include <volsg/nodes/Bindings.h>
#include <volsg/nodes/BoxClip.h>
#include <volsg/nodes/Camera.h>
#include <volsg/nodes/CameraKit.h>
#include <volsg/nodes/ClipPlane.h>
#include <volsg/nodes/Complexity.h>
#include <volsg/nodes/Cone.h>
#include <volsg/nodes/Coordinate3.h>
#include <volsg/nodes/Coordinate4.h>
#include <volsg/nodes/Cube.h>
#include <volsg/nodes/Cylinder.h>
#include <volsg/nodes/Dragger.h>
#include <volsg/nodes/DrawStyle.h>
#include <volsg/nodes/Environment.h>
#include <volsg/nodes/FaceSet.h>
#include <volsg/nodes/File.h>
#include <volsg/nodes/Font.h>
#include <volsg/nodes/GltfModel.h>
#include <volsg/nodes/Group.h>
#include <volsg/nodes/IndexedFaceSet.h>
#include <volsg/nodes/IndexedLineSet.h>
#include <volsg/nodes/IndexedTriangleStripSet.h>
#include <volsg/nodes/Info.h>
#include <volsg/nodes/LOD.h>
#include <volsg/nodes/Label.h>
#include <volsg/nodes/LevelOfDetail.h>
#include <volsg/nodes/Light.h>
#include <volsg/nodes/LightKit.h>
#include <volsg/nodes/LightModel.h>
#include <volsg/nodes/LineSet.h>
#include <volsg/nodes/Material.h>
#include <volsg/nodes/MatrixTransform.h>
#include <volsg/nodes/MultipleCopy.h>
#include <volsg/nodes/NodeKitListPart.h>
#include <volsg/nodes/Normal.h>
#include <volsg/nodes/NurbsCurve.h>
#include <volsg/nodes/NurbsSurface.h>
#include <volsg/nodes/ObliqueSlice.h>
#include <volsg/nodes/OrthoSlice.h>
#include <volsg/nodes/PickStyle.h>
#include <volsg/nodes/PointSet.h>
#include <volsg/nodes/Profile.h>
#include <volsg/nodes/ProfileCoordinate2.h>
#include <volsg/nodes/ProfileCoordinate3.h>
#include <volsg/nodes/QuadMesh.h>
#include <volsg/nodes/ResetTransform.h>
#include <volsg/nodes/Rotation.h>
#include <volsg/nodes/RotationXYZ.h>
#include <volsg/nodes/Scale.h>
#include <volsg/nodes/SceneKit.h>
#include <volsg/nodes/Selection.h>
#include <volsg/nodes/Separator.h>
#include <volsg/nodes/SeparatorKit.h>
#include <volsg/nodes/ShapeHints.h>
#include <volsg/nodes/ShapeKit.h>
#include <volsg/nodes/ShearWarpVolume.h>
#include <volsg/nodes/Sphere.h>
#include <volsg/nodes/Switch.h>
#include <volsg/nodes/Text2.h>
#include <volsg/nodes/Text3.h>
#include <volsg/nodes/Texture2.h>
#include <volsg/nodes/Texture2Transform.h>
#include <volsg/nodes/TextureCoordinate2.h>
#include <volsg/nodes/TextureCoordinateDefault.h>
#include <volsg/nodes/TextureCoordinateEnvironment.h>
#include <volsg/nodes/TextureCoordinatePlane.h>
#include <volsg/nodes/TransferFunction.h>
#include <volsg/nodes/Transform.h>
#include <volsg/nodes/TransformSeparator.h>
#include <volsg/nodes/Translation.h>
#include <volsg/nodes/TriangleStripSet.h>
#include <volsg/nodes/Units.h>
#include <volsg/nodes/VertexProperty.h>
#include <volsg/nodes/Volume.h>
#include <volsg/nodes/VolumeData.h>
#include <volsg/nodes/VolumeObject.h>
#include <volsg/nodes/VolumeSeries.h>
#include <volsg/nodes/WrapperKit.h>

namespace volsg {

namespace {

void addBuiltinTypes(NodeRegistry& r) {
    r.add(Group::classType());
    r.add(Separator::classType());
    r.add(Switch::classType());
    r.add(Transform::classType());
    r.add(MatrixTransform::classType());
    r.add(Material::classType());
    r.add(PerspectiveCamera::classType());
    r.add(OrthographicCamera::classType());
    r.add(DirectionalLight::classType());
    r.add(PointLight::classType());
    r.add(Cube::classType());
    r.add(Sphere::classType());
    r.add(Cone::classType());
    r.add(Cylinder::classType());
    r.add(Coordinate3::classType());
    r.add(Normal::classType());
    r.add(IndexedFaceSet::classType());
    r.add(IndexedLineSet::classType());
    r.add(ClipPlane::classType());
    r.add(VolumeData::classType());
    r.add(VolumeSeries::classType());
    r.add(TransferFunction::classType());
    r.add(BoxClip::classType());
    r.add(Volume::classType());
    r.add(ShearWarpVolume::classType());
    r.add(VolumeObject::classType());
    r.add(GltfModel::classType());
    r.add(LightModel::classType());
    r.add(ResetTransform::classType());
    r.add(OrthoSlice::classType());
    r.add(ObliqueSlice::classType());
    // Inventor 2.1: appearance, vertex data and vertex shapes.
    r.add(BaseColor::classType());
    r.add(MaterialBinding::classType());
    r.add(NormalBinding::classType());
    r.add(TextureCoordinateBinding::classType());
    r.add(Coordinate4::classType());
    r.add(VertexProperty::classType());
    r.add(ShapeHints::classType());
    r.add(DrawStyle::classType());
    r.add(Complexity::classType());
    r.add(Environment::classType());
    r.add(SpotLight::classType());
    r.add(Texture2::classType());
    r.add(Texture2Transform::classType());
    r.add(TextureCoordinate2::classType());
    r.add(TextureCoordinatePlane::classType());
    r.add(TextureCoordinateEnvironment::classType());
    r.add(TextureCoordinateDefault::classType());
    r.add(FaceSet::classType());
    r.add(TriangleStripSet::classType());
    r.add(IndexedTriangleStripSet::classType());
    r.add(QuadMesh::classType());
    r.add(LineSet::classType());
    r.add(PointSet::classType());
    r.add(Translation::classType());
    r.add(RotationNode::classType());
    r.add(RotationXYZ::classType());
    r.add(Scale::classType());
    r.add(TransformSeparator::classType());
    r.add(Units::classType());
    r.add(LOD::classType());
    r.add(LevelOfDetail::classType());
    r.add(Array::classType());
    r.add(MultipleCopy::classType());
    r.add(Selection::classType());
    r.add(File::classType());
    r.add(Annotation::classType());
    r.add(Info::classType());
    r.add(Label::classType());
    r.add(PickStyle::classType());
    r.add(NodeKitListPart::classType());
    r.add(BaseKit::classType());
    r.add(AppearanceKit::classType());
    r.add(SeparatorKit::classType());
    r.add(ShapeKit::classType());
    r.add(WrapperKit::classType());
    r.add(LightKit::classType());
    r.add(CameraKit::classType());
    r.add(SceneKit::classType());
    // Inventor 2.1: text and NURBS.
    r.add(Font::classType());
    r.add(Text2::classType());
    r.add(Text3::classType());
    r.add(AsciiText::classType());
    r.add(ProfileCoordinate2::classType());
    r.add(ProfileCoordinate3::classType());
    r.add(LinearProfile::classType());
    r.add(NurbsProfile::classType());
    r.add(NurbsCurve::classType());
    r.add(IndexedNurbsCurve::classType());
    r.add(NurbsSurface::classType());
    r.add(IndexedNurbsSurface::classType());
    // Inventor 2.1: draggers, drawn at rest, and the AntiSquish their geometry uses.
    r.add(AntiSquish::classType());
    for (const NodeType* dragger : Dragger::draggerTypes())
        r.add(*dragger);
}

} // namespace

NodeRegistry& nodeTypes() {
    static std::once_flag once;
    std::call_once(once, [] { addBuiltinTypes(NodeRegistry::instance()); });
    return NodeRegistry::instance();
}

} // namespace volsg
