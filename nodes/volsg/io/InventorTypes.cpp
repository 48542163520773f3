// The node types of standard Inventor (as Coin 4 defines them, without its VRML97 nodes)
// with their fields and field types, for nodes the reader keeps as unknown nodes: a binary
// file names each field but not its type, and a text file gives no description for them
// (docs/SCENE-FORMAT.md section 1.4). Generated once from Coin's type system (SoType,
// SoFieldData: each type's name, parent, whether it is a group or node kit, and its fields in
// declaration order); the values and defaults are not needed.
#include <volsg/io/InventorTypes.h>

#include <mutex>
#include <sstream>
#include <unordered_map>

namespace volsg {

namespace {

// Per type: name, parent, group | kit | leaf, then field=Type in declaration order; a line
// that starts with spaces continues the type above.
constexpr const char* table = R"(
AlphaTest Node leaf function=SFEnum value=SFFloat
Annotation Separator group renderCaching=SFEnum boundingBoxCaching=SFEnum renderCulling=SFEnum
  pickCulling=SFEnum
AntiSquish Transformation leaf recalcAlways=SFBool sizing=SFEnum
AppearanceKit BaseKit kit callbackList=SFNode lightModel=SFNode environment=SFNode
  drawStyle=SFNode material=SFNode complexity=SFNode texture2=SFNode font=SFNode
Array Group group origin=SFEnum numElements1=SFShort numElements2=SFShort numElements3=SFShort
  separation1=SFVec3f separation2=SFVec3f separation3=SFVec3f
AsciiText Shape leaf string=MFString spacing=SFFloat justification=SFEnum width=MFFloat
BaseColor Node leaf rgb=MFColor
BaseKit Node kit callbackList=SFNode
Blinker Switch group whichChild=SFInt32 speed=SFFloat on=SFBool
BumpMap Node leaf filename=SFString image=SFImage wrapS=SFEnum wrapT=SFEnum
BumpMapCoordinate Node leaf point=MFVec2f
BumpMapTransform Node leaf translation=SFVec2f rotation=SFFloat scaleFactor=SFVec2f center=SFVec2f
CacheHint Node leaf memValue=SFFloat gfxValue=SFFloat
Callback Node leaf
CameraKit BaseKit kit callbackList=SFNode transformGroup=SFNode transform=SFNode camera=SFNode
CenterballDragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool XAxis=SFNode XAxisSwitch=SFNode XCenterChanger=SFNode
  XRotator=SFNode YAxis=SFNode YAxisSwitch=SFNode YCenterChanger=SFNode YRotator=SFNode
  ZAxis=SFNode ZAxisSwitch=SFNode ZCenterChanger=SFNode ZRotator=SFNode antiSquish=SFNode
  lightModel=SFNode rot2X90=SFNode rotX90=SFNode rotY90=SFNode rotator=SFNode surroundScale=SFNode
  translateToCenter=SFNode rotation=SFRotation center=SFVec3f
CenterballManip TransformManip leaf translation=SFVec3f rotation=SFRotation scaleFactor=SFVec3f
  scaleOrientation=SFRotation center=SFVec3f
ClipPlane Node leaf plane=SFPlane on=SFBool
ClipPlaneManip ClipPlane leaf plane=SFPlane on=SFBool draggerPosition=SFVec3f
ColorIndex Node leaf index=MFInt32
Complexity Node leaf type=SFEnum value=SFFloat textureQuality=SFFloat
Cone Shape leaf bottomRadius=SFFloat height=SFFloat parts=SFBitMask
Coordinate3 Node leaf point=MFVec3f
Coordinate4 Node leaf point=MFVec4f
Cube Shape leaf width=SFFloat height=SFFloat depth=SFFloat
Cylinder Shape leaf radius=SFFloat height=SFFloat parts=SFBitMask
DepthBuffer Node leaf test=SFBool write=SFBool function=SFEnum range=SFVec2f
DirectionalLight Light leaf on=SFBool intensity=SFFloat color=SFColor direction=SFVec3f
DirectionalLightDragger Dragger kit callbackList=SFNode renderCaching=SFEnum
  boundingBoxCaching=SFEnum renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode
  geomSeparator=SFNode motionMatrix=SFNode isActive=SFBool material=SFNode rotator=SFNode
  translator=SFNode translatorRotInv=SFNode translatorSep=SFNode rotation=SFRotation
  translation=SFVec3f
DirectionalLightManip DirectionalLight leaf on=SFBool intensity=SFFloat color=SFColor
  direction=SFVec3f
DragPointDragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool noRotSep=SFNode planeFeedbackSep=SFNode
  planeFeedbackSwitch=SFNode planeFeedbackTranslation=SFNode rotX=SFNode rotXSep=SFNode
  rotY=SFNode rotYSep=SFNode rotZ=SFNode rotZSep=SFNode xFeedback=SFNode xFeedbackSep=SFNode
  xFeedbackSwitch=SFNode xFeedbackTranslation=SFNode xTranslator=SFNode xTranslatorSwitch=SFNode
  xyFeedback=SFNode xyTranslator=SFNode xyTranslatorSwitch=SFNode xzFeedback=SFNode
  xzTranslator=SFNode xzTranslatorSwitch=SFNode yFeedback=SFNode yFeedbackSep=SFNode
  yFeedbackSwitch=SFNode yFeedbackTranslation=SFNode yTranslator=SFNode yTranslatorSwitch=SFNode
  yzFeedback=SFNode yzTranslator=SFNode yzTranslatorSwitch=SFNode zFeedback=SFNode
  zFeedbackSep=SFNode zFeedbackSwitch=SFNode zFeedbackTranslation=SFNode zTranslator=SFNode
  zTranslatorSwitch=SFNode translation=SFVec3f
Dragger InteractionKit kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool
DrawStyle Node leaf style=SFEnum pointSize=SFFloat lineWidth=SFFloat linePattern=SFUShort
  linePatternScaleFactor=SFInt32
Environment Node leaf ambientIntensity=SFFloat ambientColor=SFColor attenuation=SFVec3f
  fogType=SFEnum fogColor=SFColor fogVisibility=SFFloat
EventCallback Node leaf
ExtSelection Selection group renderCaching=SFEnum boundingBoxCaching=SFEnum renderCulling=SFEnum
  pickCulling=SFEnum policy=SFEnum lassoType=SFEnum lassoPolicy=SFEnum lassoMode=SFEnum
FaceSet NonIndexedShape leaf vertexProperty=SFNode startIndex=SFInt32 numVertices=MFInt32
File Node leaf name=SFString
Font Node leaf name=SFName size=SFFloat
FontStyle Font leaf name=SFName size=SFFloat family=SFEnum style=SFBitMask
FragmentShader ShaderObject leaf isActive=SFBool sourceType=SFEnum sourceProgram=SFString
  parameter=MFNode
FrustumCamera Camera leaf viewportMapping=SFEnum position=SFVec3f orientation=SFRotation
  nearDistance=SFFloat farDistance=SFFloat aspectRatio=SFFloat focalDistance=SFFloat top=SFFloat
  bottom=SFFloat left=SFFloat right=SFFloat
GeoCoordinate Node leaf point=MFVec3d geoSystem=MFString
GeoLocation Transformation leaf geoCoords=SFVec3d geoSystem=MFString
GeoOrigin Node leaf geoCoords=SFVec3d geoSystem=MFString
GeoSeparator Separator group renderCaching=SFEnum boundingBoxCaching=SFEnum renderCulling=SFEnum
  pickCulling=SFEnum geoCoords=SFVec3d geoSystem=MFString
GeometryShader ShaderObject leaf isActive=SFBool sourceType=SFEnum sourceProgram=SFString
  parameter=MFNode inputType=SFEnum outputType=SFEnum maxEmit=SFInt32
Group Node group
HandleBoxDragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool surroundScale=SFNode drawStyle=SFNode
  translator1Switch=SFNode translator1=SFNode translator1Active=SFNode translator2Switch=SFNode
  translator2=SFNode translator2Active=SFNode translator3Switch=SFNode translator3=SFNode
  translator3Active=SFNode translator4Switch=SFNode translator4=SFNode translator4Active=SFNode
  translator5Switch=SFNode translator5=SFNode translator5Active=SFNode translator6Switch=SFNode
  translator6=SFNode translator6Active=SFNode extruder1Switch=SFNode extruder1=SFNode
  extruder1Active=SFNode extruder2Switch=SFNode extruder2=SFNode extruder2Active=SFNode
  extruder3Switch=SFNode extruder3=SFNode extruder3Active=SFNode extruder4Switch=SFNode
  extruder4=SFNode extruder4Active=SFNode extruder5Switch=SFNode extruder5=SFNode
  extruder5Active=SFNode extruder6Switch=SFNode extruder6=SFNode extruder6Active=SFNode
  uniform1Switch=SFNode uniform1=SFNode uniform1Active=SFNode uniform2Switch=SFNode
  uniform2=SFNode uniform2Active=SFNode uniform3Switch=SFNode uniform3=SFNode
  uniform3Active=SFNode uniform4Switch=SFNode uniform4=SFNode uniform4Active=SFNode
  uniform5Switch=SFNode uniform5=SFNode uniform5Active=SFNode uniform6Switch=SFNode
  uniform6=SFNode uniform6Active=SFNode uniform7Switch=SFNode uniform7=SFNode
  uniform7Active=SFNode uniform8Switch=SFNode uniform8=SFNode uniform8Active=SFNode
  arrowTranslation=SFNode arrow1Switch=SFNode arrow1=SFNode arrow2Switch=SFNode arrow2=SFNode
  arrow3Switch=SFNode arrow3=SFNode arrow4Switch=SFNode arrow4=SFNode arrow5Switch=SFNode
  arrow5=SFNode arrow6Switch=SFNode arrow6=SFNode translation=SFVec3f scaleFactor=SFVec3f
HandleBoxManip TransformManip leaf translation=SFVec3f rotation=SFRotation scaleFactor=SFVec3f
  scaleOrientation=SFRotation center=SFVec3f
Image Shape leaf width=SFInt32 height=SFInt32 vertAlignment=SFEnum horAlignment=SFEnum
  image=SFImage filename=SFString
IndexedFaceSet IndexedShape leaf vertexProperty=SFNode coordIndex=MFInt32 materialIndex=MFInt32
  normalIndex=MFInt32 textureCoordIndex=MFInt32
IndexedLineSet IndexedShape leaf vertexProperty=SFNode coordIndex=MFInt32 materialIndex=MFInt32
  normalIndex=MFInt32 textureCoordIndex=MFInt32
IndexedMarkerSet IndexedPointSet leaf vertexProperty=SFNode coordIndex=MFInt32
  materialIndex=MFInt32 normalIndex=MFInt32 textureCoordIndex=MFInt32 markerIndex=MFInt32
IndexedNurbsCurve Shape leaf numControlPoints=SFInt32 coordIndex=MFInt32 knotVector=MFFloat
IndexedNurbsSurface Shape leaf numUControlPoints=SFInt32 numVControlPoints=SFInt32
  coordIndex=MFInt32 uKnotVector=MFFloat vKnotVector=MFFloat numSControlPoints=SFInt32
  numTControlPoints=SFInt32 textureCoordIndex=MFInt32 sKnotVector=MFFloat tKnotVector=MFFloat
IndexedPointSet IndexedShape leaf vertexProperty=SFNode coordIndex=MFInt32 materialIndex=MFInt32
  normalIndex=MFInt32 textureCoordIndex=MFInt32
IndexedTriangleStripSet IndexedShape leaf vertexProperty=SFNode coordIndex=MFInt32
  materialIndex=MFInt32 normalIndex=MFInt32 textureCoordIndex=MFInt32
Info Node leaf string=SFString
InteractionKit BaseKit kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
JackDragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool surroundScale=SFNode antiSquish=SFNode scaler=SFNode
  rotator=SFNode translator=SFNode rotation=SFRotation translation=SFVec3f scaleFactor=SFVec3f
JackManip TransformManip leaf translation=SFVec3f rotation=SFRotation scaleFactor=SFVec3f
  scaleOrientation=SFRotation center=SFVec3f
LOD Group group center=SFVec3f range=MFFloat
Label Node leaf label=SFName
LevelOfDetail Group group screenArea=MFFloat
LightKit BaseKit kit callbackList=SFNode transformGroup=SFNode transform=SFNode light=SFNode
  iconSeparator=SFNode icon=SFNode
LightModel Node leaf model=SFEnum
LineSet NonIndexedShape leaf vertexProperty=SFNode startIndex=SFInt32 numVertices=MFInt32
LinearProfile Profile leaf index=MFInt32 linkage=SFEnum
Listener Node leaf position=SFVec3f orientation=SFRotation dopplerVelocity=SFVec3f
  dopplerFactor=SFFloat gain=SFFloat
LocateHighlight Separator group renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum color=SFColor style=SFEnum mode=SFEnum
MarkerSet PointSet leaf vertexProperty=SFNode startIndex=SFInt32 numPoints=SFInt32
  markerIndex=MFInt32
Material Node leaf ambientColor=MFColor diffuseColor=MFColor specularColor=MFColor
  emissiveColor=MFColor shininess=MFFloat transparency=MFFloat
MaterialBinding Node leaf value=SFEnum
MatrixTransform Transformation leaf matrix=SFMatrix
MultipleCopy Group group matrix=MFMatrix
NodeKitListPart Node leaf containerTypeName=SFName childTypeNames=MFName containerNode=SFNode
Normal Node leaf vector=MFVec3f
NormalBinding Node leaf value=SFEnum
NurbsCurve Shape leaf numControlPoints=SFInt32 knotVector=MFFloat
NurbsProfile Profile leaf index=MFInt32 linkage=SFEnum knotVector=MFFloat
NurbsSurface Shape leaf numUControlPoints=SFInt32 numVControlPoints=SFInt32
  numSControlPoints=SFInt32 numTControlPoints=SFInt32 uKnotVector=MFFloat vKnotVector=MFFloat
  sKnotVector=MFFloat tKnotVector=MFFloat
OrthographicCamera Camera leaf viewportMapping=SFEnum position=SFVec3f orientation=SFRotation
  nearDistance=SFFloat farDistance=SFFloat aspectRatio=SFFloat focalDistance=SFFloat
  height=SFFloat
PackedColor Node leaf orderedRGBA=MFUInt32
PathSwitch Group group path=SFPath
Pendulum Rotation leaf rotation=SFRotation rotation0=SFRotation rotation1=SFRotation speed=SFFloat
  on=SFBool
PerspectiveCamera Camera leaf viewportMapping=SFEnum position=SFVec3f orientation=SFRotation
  nearDistance=SFFloat farDistance=SFFloat aspectRatio=SFFloat focalDistance=SFFloat
  heightAngle=SFFloat
PickStyle Node leaf style=SFEnum
PointLight Light leaf on=SFBool intensity=SFFloat color=SFColor location=SFVec3f
PointLightDragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool material=SFNode translator=SFNode translation=SFVec3f
PointLightManip PointLight leaf on=SFBool intensity=SFFloat color=SFColor location=SFVec3f
PointSet NonIndexedShape leaf vertexProperty=SFNode startIndex=SFInt32 numPoints=SFInt32
PolygonOffset Node leaf factor=SFFloat units=SFFloat styles=SFBitMask on=SFBool
ProfileCoordinate2 Node leaf point=MFVec2f
ProfileCoordinate3 Node leaf point=MFVec3f
QuadMesh NonIndexedShape leaf vertexProperty=SFNode startIndex=SFInt32 verticesPerColumn=SFInt32
  verticesPerRow=SFInt32
ResetTransform Transformation leaf whatToReset=SFBitMask
ReversePerspectiveCamera PerspectiveCamera leaf viewportMapping=SFEnum position=SFVec3f
  orientation=SFRotation nearDistance=SFFloat farDistance=SFFloat aspectRatio=SFFloat
  focalDistance=SFFloat heightAngle=SFFloat
RotateCylindricalDragger Dragger kit callbackList=SFNode renderCaching=SFEnum
  boundingBoxCaching=SFEnum renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode
  geomSeparator=SFNode motionMatrix=SFNode isActive=SFBool rotatorSwitch=SFNode rotator=SFNode
  rotatorActive=SFNode feedbackSwitch=SFNode feedback=SFNode feedbackActive=SFNode
  rotation=SFRotation
RotateDiscDragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool rotatorSwitch=SFNode rotator=SFNode rotatorActive=SFNode
  feedbackSwitch=SFNode feedback=SFNode feedbackActive=SFNode rotation=SFRotation
RotateSphericalDragger Dragger kit callbackList=SFNode renderCaching=SFEnum
  boundingBoxCaching=SFEnum renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode
  geomSeparator=SFNode motionMatrix=SFNode isActive=SFBool rotatorSwitch=SFNode rotator=SFNode
  rotatorActive=SFNode feedbackSwitch=SFNode feedback=SFNode feedbackActive=SFNode
  rotation=SFRotation
Rotation Transformation leaf rotation=SFRotation
RotationXYZ Transformation leaf angle=SFFloat axis=SFEnum
Rotor Rotation leaf rotation=SFRotation speed=SFFloat on=SFBool
Scale Transformation leaf scaleFactor=SFVec3f
Scale1Dragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool scalerSwitch=SFNode scaler=SFNode scalerActive=SFNode
  feedbackSwitch=SFNode feedback=SFNode feedbackActive=SFNode scaleFactor=SFVec3f
Scale2Dragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool scalerSwitch=SFNode scaler=SFNode scalerActive=SFNode
  feedbackSwitch=SFNode feedback=SFNode feedbackActive=SFNode scaleFactor=SFVec3f
Scale2UniformDragger Dragger kit callbackList=SFNode renderCaching=SFEnum
  boundingBoxCaching=SFEnum renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode
  geomSeparator=SFNode motionMatrix=SFNode isActive=SFBool scalerSwitch=SFNode scaler=SFNode
  scalerActive=SFNode feedbackSwitch=SFNode feedback=SFNode feedbackActive=SFNode
  scaleFactor=SFVec3f
ScaleUniformDragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool scalerSwitch=SFNode scaler=SFNode scalerActive=SFNode
  feedbackSwitch=SFNode feedback=SFNode feedbackActive=SFNode scaleFactor=SFVec3f
SceneKit BaseKit kit callbackList=SFNode topSeparator=SFNode cameraList=SFNode lightList=SFNode
  childList=SFNode
SceneTexture2 Node leaf size=SFVec2s scene=SFNode sceneTransparencyType=SFNode
  backgroundColor=SFVec4f transparencyFunction=SFEnum wrapS=SFEnum wrapT=SFEnum model=SFEnum
  blendColor=SFColor type=SFEnum
Selection Separator group renderCaching=SFEnum boundingBoxCaching=SFEnum renderCulling=SFEnum
  pickCulling=SFEnum policy=SFEnum
Separator Group group renderCaching=SFEnum boundingBoxCaching=SFEnum renderCulling=SFEnum
  pickCulling=SFEnum
SeparatorKit BaseKit kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode pickStyle=SFNode appearance=SFNode
  units=SFNode transform=SFNode texture2Transform=SFNode childList=SFNode
ShaderParameter1f UniformShaderParameter leaf name=SFString identifier=SFInt32 value=SFFloat
ShaderParameter1i UniformShaderParameter leaf name=SFString identifier=SFInt32 value=SFInt32
ShaderParameter2f UniformShaderParameter leaf name=SFString identifier=SFInt32 value=SFVec2f
ShaderParameter2i UniformShaderParameter leaf name=SFString identifier=SFInt32 value=SFVec2i32
ShaderParameter3f UniformShaderParameter leaf name=SFString identifier=SFInt32 value=SFVec3f
ShaderParameter3i UniformShaderParameter leaf name=SFString identifier=SFInt32 value=SFVec3i32
ShaderParameter4f UniformShaderParameter leaf name=SFString identifier=SFInt32 value=SFVec4f
ShaderParameter4i UniformShaderParameter leaf name=SFString identifier=SFInt32 value=SFVec4i32
ShaderParameterArray1f UniformShaderParameter leaf name=SFString identifier=SFInt32 value=MFFloat
ShaderParameterArray1i UniformShaderParameter leaf name=SFString identifier=SFInt32 value=MFInt32
ShaderParameterArray2f UniformShaderParameter leaf name=SFString identifier=SFInt32 value=MFVec2f
ShaderParameterArray2i UniformShaderParameter leaf name=SFString identifier=SFInt32
  value=MFVec2i32
ShaderParameterArray3f UniformShaderParameter leaf name=SFString identifier=SFInt32 value=MFVec3f
ShaderParameterArray3i UniformShaderParameter leaf name=SFString identifier=SFInt32
  value=MFVec3i32
ShaderParameterArray4f UniformShaderParameter leaf name=SFString identifier=SFInt32 value=MFVec4f
ShaderParameterArray4i UniformShaderParameter leaf name=SFString identifier=SFInt32
  value=MFVec4i32
ShaderParameterMatrix UniformShaderParameter leaf name=SFString identifier=SFInt32 value=SFMatrix
ShaderParameterMatrixArray UniformShaderParameter leaf name=SFString identifier=SFInt32
  value=MFMatrix
ShaderProgram Node leaf shaderObject=MFNode
ShaderStateMatrixParameter UniformShaderParameter leaf name=SFString identifier=SFInt32
  matrixType=SFEnum matrixTransform=SFEnum
ShadowCulling Node leaf mode=SFEnum
ShadowDirectionalLight DirectionalLight leaf on=SFBool intensity=SFFloat color=SFColor
  direction=SFVec3f shadowMapScene=SFNode maxShadowDistance=SFFloat bboxCenter=SFVec3f
  bboxSize=SFVec3f
ShadowGroup Separator group renderCaching=SFEnum boundingBoxCaching=SFEnum renderCulling=SFEnum
  pickCulling=SFEnum isActive=SFBool intensity=SFFloat precision=SFFloat quality=SFFloat
  shadowCachingEnabled=SFBool visibilityNearRadius=SFFloat visibilityRadius=SFFloat
  epsilon=SFFloat threshold=SFFloat smoothBorder=SFFloat visibilityFlag=SFEnum
ShadowSpotLight SpotLight leaf on=SFBool intensity=SFFloat color=SFColor location=SFVec3f
  direction=SFVec3f dropOffRate=SFFloat cutOffAngle=SFFloat shadowMapScene=SFNode
  nearDistance=SFFloat farDistance=SFFloat
ShadowStyle Node leaf style=SFEnum
ShapeHints Node leaf vertexOrdering=SFEnum shapeType=SFEnum faceType=SFEnum creaseAngle=SFFloat
ShapeKit SeparatorKit kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode pickStyle=SFNode appearance=SFNode
  units=SFNode transform=SFNode texture2Transform=SFNode childList=SFNode materialBinding=SFNode
  normalBinding=SFNode textureCoordinateBinding=SFNode shapeHints=SFNode coordinate3=SFNode
  coordinate4=SFNode normal=SFNode textureCoordinate2=SFNode textureCoordinateFunction=SFNode
  profileCoordinate2=SFNode profileCoordinate3=SFNode profileList=SFNode localTransform=SFNode
  shapeSeparator=SFNode shape=SFNode
Shuttle Translation leaf translation=SFVec3f translation0=SFVec3f translation1=SFVec3f
  speed=SFFloat on=SFBool
SoSTLFileKit SoForeignFileKit kit callbackList=SFNode topSeparator=SFNode info=SFString
  binary=SFBool colorization=SFEnum facets=SFNode coordinates=SFNode material=SFNode
  materialbinding=SFNode normals=SFNode normalbinding=SFNode texture=SFNode shapehints=SFNode
SoSceneTextureCubeMap Node leaf size=SFVec2s scene=SFNode backgroundColor=SFColor
  transparencyFunction=SFEnum wrapS=SFEnum wrapT=SFEnum wrapR=SFEnum model=SFEnum
  blendColor=SFColor
Sphere Shape leaf radius=SFFloat
SpotLight Light leaf on=SFBool intensity=SFFloat color=SFColor location=SFVec3f direction=SFVec3f
  dropOffRate=SFFloat cutOffAngle=SFFloat
SpotLightDragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool material=SFNode translatorSep=SFNode translatorRotInv=SFNode
  translator=SFNode rotator=SFNode beamSep=SFNode beamPlacement=SFNode beamScale=SFNode
  beamSwitch=SFNode beam=SFNode beamActive=SFNode rotation=SFRotation translation=SFVec3f
  angle=SFFloat
SpotLightManip SpotLight leaf on=SFBool intensity=SFFloat color=SFColor location=SFVec3f
  direction=SFVec3f dropOffRate=SFFloat cutOffAngle=SFFloat
SurroundScale Transformation leaf numNodesUpToContainer=SFInt32 numNodesUpToReset=SFInt32
Switch Group group whichChild=SFInt32
TabBoxDragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool surroundScale=SFNode tabPlane1Sep=SFNode tabPlane1Xf=SFNode
  tabPlane1=SFNode tabPlane2Sep=SFNode tabPlane2Xf=SFNode tabPlane2=SFNode tabPlane3Sep=SFNode
  tabPlane3Xf=SFNode tabPlane3=SFNode tabPlane4Sep=SFNode tabPlane4Xf=SFNode tabPlane4=SFNode
  tabPlane5Sep=SFNode tabPlane5Xf=SFNode tabPlane5=SFNode tabPlane6Sep=SFNode tabPlane6Xf=SFNode
  tabPlane6=SFNode boxGeom=SFNode translation=SFVec3f scaleFactor=SFVec3f
TabBoxManip TransformManip leaf translation=SFVec3f rotation=SFRotation scaleFactor=SFVec3f
  scaleOrientation=SFRotation center=SFVec3f
TabPlaneDragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool planeSwitch=SFNode translator=SFNode scaleTabs=SFNode
  scaleTabMaterial=SFNode scaleTabHints=SFNode scaleTabMaterialBinding=SFNode
  scaleTabNormalBinding=SFNode scaleTabNormal=SFNode edgeScaleCoords=SFNode edgeScaleTab0=SFNode
  edgeScaleTab1=SFNode edgeScaleTab2=SFNode edgeScaleTab3=SFNode cornerScaleCoords=SFNode
  cornerScaleTab0=SFNode cornerScaleTab1=SFNode cornerScaleTab2=SFNode cornerScaleTab3=SFNode
  translation=SFVec3f scaleFactor=SFVec3f
Text2 Shape leaf string=MFString spacing=SFFloat justification=SFEnum
Text3 Shape leaf string=MFString spacing=SFFloat justification=SFEnum parts=SFBitMask
Texture2 SoTexture leaf filename=SFString image=SFImage wrapS=SFEnum wrapT=SFEnum model=SFEnum
  blendColor=SFColor enableCompressedTexture=SFBool
Texture2Transform Node leaf translation=SFVec2f rotation=SFFloat scaleFactor=SFVec2f
  center=SFVec2f
Texture3 SoTexture leaf filenames=MFString images=SFImage3 wrapR=SFEnum wrapS=SFEnum wrapT=SFEnum
  model=SFEnum blendColor=SFColor enableCompressedTexture=SFBool
Texture3Transform Node leaf translation=SFVec3f rotation=SFRotation scaleFactor=SFVec3f
  scaleOrientation=SFRotation center=SFVec3f
TextureCombine Node leaf rgbSource=MFEnum alphaSource=MFEnum rgbOperand=MFEnum alphaOperand=MFEnum
  rgbOperation=SFEnum alphaOperation=SFEnum rgbScale=SFFloat alphaScale=SFFloat
  constantColor=SFVec4f
TextureCoordinate2 Node leaf point=MFVec2f
TextureCoordinate3 Node leaf point=MFVec3f
TextureCoordinateBinding Node leaf value=SFEnum
TextureCoordinateCube Node leaf
TextureCoordinateCylinder Node leaf
TextureCoordinateDefault TextureCoordinateFunction leaf
TextureCoordinateEnvironment TextureCoordinateFunction leaf
TextureCoordinateNormalMap TextureCoordinateFunction leaf
TextureCoordinateObject TextureCoordinateFunction leaf factorS=SFVec4f factorT=SFVec4f
  factorR=SFVec4f factorQ=SFVec4f
TextureCoordinatePlane TextureCoordinateFunction leaf directionS=SFVec3f directionT=SFVec3f
  directionR=SFVec3f
TextureCoordinateReflectionMap TextureCoordinateFunction leaf
TextureCoordinateSphere Node leaf
TextureCubeMap SoTexture leaf filenames=MFString imagePosX=SFImage imageNegX=SFImage
  imagePosY=SFImage imageNegY=SFImage imagePosZ=SFImage imageNegZ=SFImage wrapS=SFEnum
  wrapT=SFEnum model=SFEnum blendColor=SFColor
TextureMatrixTransform Node leaf matrix=SFMatrix
TextureScalePolicy Node leaf policy=SFEnum quality=SFFloat
TextureUnit Node leaf unit=SFInt32 mappingMethod=SFEnum
TrackballDragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool surroundScale=SFNode antiSquish=SFNode rotatorSwitch=SFNode
  rotator=SFNode rotatorActive=SFNode XRotatorSwitch=SFNode XRotator=SFNode XRotatorActive=SFNode
  YRotatorSwitch=SFNode YRotator=SFNode YRotatorActive=SFNode ZRotatorSwitch=SFNode
  ZRotator=SFNode ZRotatorActive=SFNode userAxisRotation=SFNode userAxisSwitch=SFNode
  userAxis=SFNode userAxisActive=SFNode userRotatorSwitch=SFNode userRotator=SFNode
  userRotatorActive=SFNode rotation=SFRotation scaleFactor=SFVec3f
TrackballManip TransformManip leaf translation=SFVec3f rotation=SFRotation scaleFactor=SFVec3f
  scaleOrientation=SFRotation center=SFVec3f
Transform Transformation leaf translation=SFVec3f rotation=SFRotation scaleFactor=SFVec3f
  scaleOrientation=SFRotation center=SFVec3f
TransformBoxDragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool surroundScale=SFNode antiSquish=SFNode scaler=SFNode
  rotator1Sep=SFNode rotator1Rot=SFNode rotator1=SFNode rotator2Sep=SFNode rotator2Rot=SFNode
  rotator2=SFNode rotator3Sep=SFNode rotator3Rot=SFNode rotator3=SFNode translator1Sep=SFNode
  translator1Rot=SFNode translator1=SFNode translator2Sep=SFNode translator2Rot=SFNode
  translator2=SFNode translator3Sep=SFNode translator3Rot=SFNode translator3=SFNode
  translator4Sep=SFNode translator4Rot=SFNode translator4=SFNode translator5Sep=SFNode
  translator5Rot=SFNode translator5=SFNode translator6Sep=SFNode translator6Rot=SFNode
  translator6=SFNode rotation=SFRotation translation=SFVec3f scaleFactor=SFVec3f
TransformBoxManip TransformManip leaf translation=SFVec3f rotation=SFRotation scaleFactor=SFVec3f
  scaleOrientation=SFRotation center=SFVec3f
TransformManip Transform leaf translation=SFVec3f rotation=SFRotation scaleFactor=SFVec3f
  scaleOrientation=SFRotation center=SFVec3f
TransformSeparator Group group
TransformerDragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool surroundScale=SFNode overallStyle=SFNode
  translatorSep=SFNode translator1Switch=SFNode translator1LocateGroup=SFNode translator1=SFNode
  translator1Active=SFNode translator2Switch=SFNode translator2LocateGroup=SFNode
  translator2=SFNode translator2Active=SFNode translator3Switch=SFNode
  translator3LocateGroup=SFNode translator3=SFNode translator3Active=SFNode
  translator4Switch=SFNode translator4LocateGroup=SFNode translator4=SFNode
  translator4Active=SFNode translator5Switch=SFNode translator5LocateGroup=SFNode
  translator5=SFNode translator5Active=SFNode translator6Switch=SFNode
  translator6LocateGroup=SFNode translator6=SFNode translator6Active=SFNode rotatorSep=SFNode
  rotator1Switch=SFNode rotator1LocateGroup=SFNode rotator1=SFNode rotator1Active=SFNode
  rotator2Switch=SFNode rotator2LocateGroup=SFNode rotator2=SFNode rotator2Active=SFNode
  rotator3Switch=SFNode rotator3LocateGroup=SFNode rotator3=SFNode rotator3Active=SFNode
  rotator4Switch=SFNode rotator4LocateGroup=SFNode rotator4=SFNode rotator4Active=SFNode
  rotator5Switch=SFNode rotator5LocateGroup=SFNode rotator5=SFNode rotator5Active=SFNode
  rotator6Switch=SFNode rotator6LocateGroup=SFNode rotator6=SFNode rotator6Active=SFNode
  scaleSep=SFNode scale1Switch=SFNode scale1LocateGroup=SFNode scale1=SFNode scale1Active=SFNode
  scale2Switch=SFNode scale2LocateGroup=SFNode scale2=SFNode scale2Active=SFNode
  scale3Switch=SFNode scale3LocateGroup=SFNode scale3=SFNode scale3Active=SFNode
  scale4Switch=SFNode scale4LocateGroup=SFNode scale4=SFNode scale4Active=SFNode
  scale5Switch=SFNode scale5LocateGroup=SFNode scale5=SFNode scale5Active=SFNode
  scale6Switch=SFNode scale6LocateGroup=SFNode scale6=SFNode scale6Active=SFNode
  scale7Switch=SFNode scale7LocateGroup=SFNode scale7=SFNode scale7Active=SFNode
  scale8Switch=SFNode scale8LocateGroup=SFNode scale8=SFNode scale8Active=SFNode
  axisFeedbackSep=SFNode axisFeedbackLocation=SFNode xAxisFeedbackSwitch=SFNode
  xAxisFeedbackActive=SFNode xAxisFeedbackSelect=SFNode xCrosshairFeedback=SFNode
  yAxisFeedbackSwitch=SFNode yAxisFeedbackActive=SFNode yAxisFeedbackSelect=SFNode
  yCrosshairFeedback=SFNode zAxisFeedbackSwitch=SFNode zAxisFeedbackActive=SFNode
  zAxisFeedbackSelect=SFNode zCrosshairFeedback=SFNode translateBoxFeedbackSep=SFNode
  translateBoxFeedbackSwitch=SFNode translateBoxFeedbackRotation=SFNode
  translateBoxFeedback=SFNode scaleBoxFeedbackSwitch=SFNode scaleBoxFeedback=SFNode
  posXWallFeedbackSwitch=SFNode posXWallFeedback=SFNode posXRoundWallFeedback=SFNode
  posYWallFeedbackSwitch=SFNode posYWallFeedback=SFNode posYRoundWallFeedback=SFNode
  posZWallFeedbackSwitch=SFNode posZWallFeedback=SFNode posZRoundWallFeedback=SFNode
  negXWallFeedbackSwitch=SFNode negXWallFeedback=SFNode negXRoundWallFeedback=SFNode
  negYWallFeedbackSwitch=SFNode negYWallFeedback=SFNode negYRoundWallFeedback=SFNode
  negZWallFeedbackSwitch=SFNode negZWallFeedback=SFNode negZRoundWallFeedback=SFNode
  radialFeedbackSwitch=SFNode radialFeedback=SFNode circleFeedbackSep=SFNode
  circleFeedbackTransformSwitch=SFNode circleFeedbackAntiSquish=SFNode
  circleFeedbackTransform=SFNode xCircleFeedbackSwitch=SFNode xCircleFeedback=SFNode
  yCircleFeedbackSwitch=SFNode yCircleFeedback=SFNode zCircleFeedbackSwitch=SFNode
  zCircleFeedback=SFNode rotation=SFRotation translation=SFVec3f scaleFactor=SFVec3f
  minDiscRotDot=SFFloat
TransformerManip TransformManip leaf translation=SFVec3f rotation=SFRotation scaleFactor=SFVec3f
  scaleOrientation=SFRotation center=SFVec3f
Translate1Dragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool translatorSwitch=SFNode translator=SFNode
  translatorActive=SFNode feedbackSwitch=SFNode feedback=SFNode feedbackActive=SFNode
  translation=SFVec3f minTranslation=SFFloat maxTranslation=SFFloat
Translate2Dragger Dragger kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode geomSeparator=SFNode
  motionMatrix=SFNode isActive=SFBool translatorSwitch=SFNode translator=SFNode
  translatorActive=SFNode feedbackSwitch=SFNode feedback=SFNode feedbackActive=SFNode
  axisFeedbackSwitch=SFNode xAxisFeedback=SFNode yAxisFeedback=SFNode translation=SFVec3f
  minTranslation=SFVec2f maxTranslation=SFVec2f
Translation Transformation leaf translation=SFVec3f
TransparencyType Node leaf value=SFEnum
TriangleStripSet NonIndexedShape leaf vertexProperty=SFNode startIndex=SFInt32 numVertices=MFInt32
Units Transformation leaf units=SFEnum
VertexAttribute Node leaf name=SFName typeName=SFName
VertexAttributeBinding Node leaf value=SFEnum
VertexProperty Node leaf vertex=MFVec3f normal=MFVec3f texCoord=MFVec2f orderedRGBA=MFUInt32
  texCoord3=MFVec3f textureUnit=MFInt32 normalBinding=SFEnum materialBinding=SFEnum
VertexShader ShaderObject leaf isActive=SFBool sourceType=SFEnum sourceProgram=SFString
  parameter=MFNode
WWWAnchor LocateHighlight group renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum color=SFColor style=SFEnum mode=SFEnum name=SFString
  description=SFString map=SFEnum
WWWInline Node leaf name=SFString bboxCenter=SFVec3f bboxSize=SFVec3f alternateRep=SFNode
WrapperKit SeparatorKit kit callbackList=SFNode renderCaching=SFEnum boundingBoxCaching=SFEnum
  renderCulling=SFEnum pickCulling=SFEnum topSeparator=SFNode pickStyle=SFNode appearance=SFNode
  units=SFNode transform=SFNode texture2Transform=SFNode childList=SFNode localTransform=SFNode
  contents=SFNode
)";

} // namespace

const InventorType* findInventorType(std::string_view name) {
    static const std::unordered_map<std::string, InventorType> types = [] {
        std::unordered_map<std::string, InventorType> out;
        // Joins continuation lines first.
        std::vector<std::string> entries;
        std::istringstream lines(table);
        std::string line;
        while (std::getline(lines, line)) {
            if (!line.empty() && line[0] == ' ' && !entries.empty())
                entries.back() += line;
            else
                entries.push_back(line);
        }
        for (const std::string& entry : entries) {
            std::istringstream words(entry);
            InventorType t;
            std::string kind, field;
            if (!(words >> t.name >> t.parent >> kind)) continue;
            t.isGroup = kind == "group";
            t.isKit = kind == "kit";
            while (words >> field) {
                const auto eq = field.find('=');
                t.fields.emplace_back(field.substr(0, eq), field.substr(eq + 1));
            }
            std::string name = t.name;
            out.emplace(std::move(name), std::move(t));
        }
        return out;
    }();
    const auto it = types.find(std::string(name));
    return it == types.end() ? nullptr : &it->second;
}

} // namespace volsg
