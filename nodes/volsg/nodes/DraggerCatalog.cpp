// The catalogs of Inventor's draggers, from Coin 4's sources (src/draggers/So*Dragger.cpp):
// each type's parts in the order of its catalog tree (Coin orders a container's children by
// their rightSibling entries), with what each is at rest: the Switch values the constructor
// sets (and the ones updated from the rest state: a TrackballDragger's user axis, a
// DragPointDragger's axis 1), the resource names setPartAsDefault gives, the nodes a
// constructor makes (a TransformBoxDragger's Rotation parts, a DragPointDragger's rotX ...),
// and the defaults a composite dragger gives its child draggers' parts.
//
// One line per part, indented one space per level below topSeparator:
//   name Separator | Group          a container
//   name Switch N                   a Switch showing child N at rest (-1 none, -3 all)
//   name Motion                     the motion matrix (motionMatrix)
//   name CenterMatrix               a translation by the center field (translateToCenter)
//   name RotationInverse            the inverse of the motion's rotation (translatorRotInv)
//   name BeamScale                  tan(angle) across the beam (a SpotLightDragger's beamScale)
//   name EdgeScaleCoords            a TabPlaneDragger's tab corners, sized on screen at each
//   name CornerScaleCoords          render (Dragger::adjustScaleTabs)
//   name -                          no node unless the file sets it
//   name @resourceName              the node DEF'd so in the type's resource file
//   name = Inventor text            a node the constructor makes
//   name XDragger [part=@res ...]   a child dragger; `part=` a default for one of its parts
//                                   (a dotted path reaches a grandchild), `@res` a name in
//                                   this type's resource file, `{}` an empty Separator
// A type starts with `[TypeName resourceFile.iv]`, and the word readValuesIgnored when Coin's
// dragger of that type ignores the value fields a file gives (DraggerCatalog::
// readValuesIgnored).
#include <volsg/core/Error.h>
#include <volsg/nodes/DraggerCatalog.h>

#include <sstream>

namespace volsg {

namespace {

constexpr const char* catalogText = R"(
[Translate1Dragger translate1Dragger.iv]
topSeparator Separator
 motionMatrix Motion
 geomSeparator Separator
  translatorSwitch Switch 0
   translator @translate1Translator
   translatorActive @translate1TranslatorActive
  feedbackSwitch Switch 0
   feedback @translate1Feedback
   feedbackActive @translate1FeedbackActive

[Translate2Dragger translate2Dragger.iv]
topSeparator Separator
 motionMatrix Motion
 geomSeparator Separator
  translatorSwitch Switch 0
   translator @translate2Translator
   translatorActive @translate2TranslatorActive
  feedbackSwitch Switch 0
   feedback @translate2Feedback
   feedbackActive @translate2FeedbackActive
  axisFeedbackSwitch Switch -1
   xAxisFeedback @translate2XAxisFeedback
   yAxisFeedback @translate2YAxisFeedback

[Scale1Dragger scale1Dragger.iv]
topSeparator Separator
 motionMatrix Motion
 geomSeparator Separator
  scalerSwitch Switch 0
   scaler @scale1Scaler
   scalerActive @scale1ScalerActive
  feedbackSwitch Switch 0
   feedback @scale1Feedback
   feedbackActive @scale1FeedbackActive

[Scale2Dragger scale2Dragger.iv]
topSeparator Separator
 motionMatrix Motion
 geomSeparator Separator
  scalerSwitch Switch 0
   scaler @scale2Scaler
   scalerActive @scale2ScalerActive
  feedbackSwitch Switch 0
   feedback @scale2Feedback
   feedbackActive @scale2FeedbackActive

[Scale2UniformDragger scale2UniformDragger.iv]
topSeparator Separator
 motionMatrix Motion
 geomSeparator Separator
  scalerSwitch Switch 0
   scaler @scale2UniformScaler
   scalerActive @scale2UniformScalerActive
  feedbackSwitch Switch 0
   feedback @scale2UniformFeedback
   feedbackActive @scale2UniformFeedbackActive

[ScaleUniformDragger scaleUniformDragger.iv]
topSeparator Separator
 motionMatrix Motion
 geomSeparator Separator
  scalerSwitch Switch 0
   scaler @scaleUniformScaler
   scalerActive @scaleUniformScalerActive
  feedbackSwitch Switch 0
   feedback @scaleUniformFeedback
   feedbackActive @scaleUniformFeedbackActive

[RotateDiscDragger rotateDiscDragger.iv]
topSeparator Separator
 motionMatrix Motion
 geomSeparator Separator
  rotatorSwitch Switch 0
   rotator @rotateDiscRotator
   rotatorActive @rotateDiscRotatorActive
  feedbackSwitch Switch 0
   feedback @rotateDiscFeedback
   feedbackActive @rotateDiscFeedbackActive

[RotateCylindricalDragger rotateCylindricalDragger.iv]
topSeparator Separator
 motionMatrix Motion
 geomSeparator Separator
  rotatorSwitch Switch 0
   rotator @rotateCylindricalRotator
   rotatorActive @rotateCylindricalRotatorActive
  feedbackSwitch Switch 0
   feedback @rotateCylindricalFeedback
   feedbackActive @rotateCylindricalFeedbackActive

[RotateSphericalDragger rotateSphericalDragger.iv]
topSeparator Separator
 motionMatrix Motion
 geomSeparator Separator
  rotatorSwitch Switch 0
   rotator @rotateSphericalRotator
   rotatorActive @rotateSphericalRotatorActive
  feedbackSwitch Switch 0
   feedback @rotateSphericalFeedback
   feedbackActive @rotateSphericalFeedbackActive

[TrackballDragger trackballDragger.iv]
topSeparator Separator
 motionMatrix Motion
 surroundScale -
 antiSquish = AntiSquish { sizing LONGEST_DIAGONAL }
 geomSeparator Separator
  rotatorSwitch Switch 0
   rotator @trackballRotator
   rotatorActive @trackballRotatorActive
  XRotatorSwitch Switch 0
   XRotator @trackballXRotator
   XRotatorActive @trackballXRotatorActive
  YRotatorSwitch Switch 0
   YRotator @trackballYRotator
   YRotatorActive @trackballYRotatorActive
  ZRotatorSwitch Switch 0
   ZRotator @trackballZRotator
   ZRotatorActive @trackballZRotatorActive
  userAxisRotation = Rotation { }
  userAxisSwitch Switch -1
   userAxis @trackballUserAxis
   userAxisActive @trackballUserAxisActive
  userRotatorSwitch Switch -1
   userRotator @trackballUserRotator
   userRotatorActive @trackballUserRotatorActive

[TransformBoxDragger transformBoxDragger.iv readValuesIgnored]
topSeparator Separator
 motionMatrix Motion
 surroundScale -
 antiSquish = AntiSquish { sizing BIGGEST_DIMENSION recalcAlways FALSE }
 scaler ScaleUniformDragger scaler=@transformBoxScalerScaler scalerActive=@transformBoxScalerScalerActive feedback=@transformBoxScalerFeedback feedbackActive=@transformBoxScalerFeedbackActive
 rotator1Sep Separator
  rotator1Rot = Rotation { rotation 0 0 1 1.5707964 }
  rotator1 RotateCylindricalDragger rotator=@transformBoxRotatorRotator rotatorActive=@transformBoxRotatorRotatorActive feedback=@transformBoxRotatorFeedback feedbackActive=@transformBoxRotatorFeedbackActive
 rotator2Sep Separator
  rotator2Rot = Rotation { rotation 1 0 0 1.5707964 }
  rotator2 RotateCylindricalDragger rotator=@transformBoxRotatorRotator rotatorActive=@transformBoxRotatorRotatorActive feedback=@transformBoxRotatorFeedback feedbackActive=@transformBoxRotatorFeedbackActive
 rotator3Sep Separator
  rotator3Rot = Rotation { }
  rotator3 RotateCylindricalDragger rotator=@transformBoxRotatorRotator rotatorActive=@transformBoxRotatorRotatorActive feedback=@transformBoxRotatorFeedback feedbackActive=@transformBoxRotatorFeedbackActive
 translator1Sep Separator
  translator1Rot = Rotation { rotation 0 1 0 1.5707964 }
  translator1 Translate2Dragger translator=@transformBoxTranslatorTranslator translatorActive=@transformBoxTranslatorTranslatorActive xAxisFeedback=@transformBoxTranslatorXAxisFeedback yAxisFeedback=@transformBoxTranslatorYAxisFeedback
 translator2Sep Separator
  translator2Rot = Rotation { rotation 0 1 0 -1.5707964 }
  translator2 Translate2Dragger translator=@transformBoxTranslatorTranslator translatorActive=@transformBoxTranslatorTranslatorActive xAxisFeedback=@transformBoxTranslatorXAxisFeedback yAxisFeedback=@transformBoxTranslatorYAxisFeedback
 translator3Sep Separator
  translator3Rot = Rotation { rotation 1 0 0 1.5707964 }
  translator3 Translate2Dragger translator=@transformBoxTranslatorTranslator translatorActive=@transformBoxTranslatorTranslatorActive xAxisFeedback=@transformBoxTranslatorXAxisFeedback yAxisFeedback=@transformBoxTranslatorYAxisFeedback
 translator4Sep Separator
  translator4Rot = Rotation { rotation 1 0 0 -1.5707964 }
  translator4 Translate2Dragger translator=@transformBoxTranslatorTranslator translatorActive=@transformBoxTranslatorTranslatorActive xAxisFeedback=@transformBoxTranslatorXAxisFeedback yAxisFeedback=@transformBoxTranslatorYAxisFeedback
 translator5Sep Separator
  translator5Rot = Rotation { rotation 1 0 0 3.1415927 }
  translator5 Translate2Dragger translator=@transformBoxTranslatorTranslator translatorActive=@transformBoxTranslatorTranslatorActive xAxisFeedback=@transformBoxTranslatorXAxisFeedback yAxisFeedback=@transformBoxTranslatorYAxisFeedback
 translator6Sep Separator
  translator6Rot = Rotation { }
  translator6 Translate2Dragger translator=@transformBoxTranslatorTranslator translatorActive=@transformBoxTranslatorTranslatorActive xAxisFeedback=@transformBoxTranslatorXAxisFeedback yAxisFeedback=@transformBoxTranslatorYAxisFeedback
 geomSeparator Separator

[DragPointDragger dragPointDragger.iv]
topSeparator Separator
 motionMatrix Motion
 noRotSep Separator
  xTranslatorSwitch Switch -1
   xTranslator Translate1Dragger translator=@dragPointXTranslatorTranslator translatorActive=@dragPointXTranslatorTranslatorActive
  xyTranslatorSwitch Switch -1
   xyTranslator Translate2Dragger translator=@dragPointXYTranslatorTranslator translatorActive=@dragPointXYTranslatorTranslatorActive
 rotXSep Separator
  rotX = Rotation { rotation 1 0 0 1.5707964 }
  xzTranslatorSwitch Switch 0
   xzTranslator Translate2Dragger translator=@dragPointXZTranslatorTranslator translatorActive=@dragPointXZTranslatorTranslatorActive
 rotYSep Separator
  rotY = Rotation { rotation 0 1 0 1.5707964 }
  zTranslatorSwitch Switch -1
   zTranslator Translate1Dragger translator=@dragPointZTranslatorTranslator translatorActive=@dragPointZTranslatorTranslatorActive
  yzTranslatorSwitch Switch -1
   yzTranslator Translate2Dragger translator=@dragPointYZTranslatorTranslator translatorActive=@dragPointYZTranslatorTranslatorActive
 rotZSep Separator
  rotZ = Rotation { rotation 0 0 1 1.5707964 }
  yTranslatorSwitch Switch 0
   yTranslator Translate1Dragger translator=@dragPointYTranslatorTranslator translatorActive=@dragPointYTranslatorTranslatorActive
 xFeedbackSwitch Switch -1
  xFeedbackSep Separator
   xFeedbackTranslation = Translation { }
   xFeedback @dragPointXFeedback
 yFeedbackSwitch Switch -1
  yFeedbackSep Separator
   yFeedbackTranslation = Translation { }
   yFeedback @dragPointYFeedback
 zFeedbackSwitch Switch -1
  zFeedbackSep Separator
   zFeedbackTranslation = Translation { }
   zFeedback @dragPointZFeedback
 planeFeedbackSep Separator
  planeFeedbackTranslation = Translation { }
  planeFeedbackSwitch Switch -1
   yzFeedback @dragPointYZFeedback
   xzFeedback @dragPointXZFeedback
   xyFeedback @dragPointXYFeedback
 geomSeparator Separator

[JackDragger jackDragger.iv readValuesIgnored]
topSeparator Separator
 motionMatrix Motion
 surroundScale -
 antiSquish = AntiSquish { sizing BIGGEST_DIMENSION recalcAlways FALSE }
 scaler ScaleUniformDragger scaler=@jackScalerScaler scalerActive=@jackScalerScalerActive feedback=@jackScalerFeedback feedbackActive=@jackScalerFeedbackActive
 rotator RotateSphericalDragger rotator=@jackRotatorRotator rotatorActive=@jackRotatorRotatorActive feedback=@jackRotatorFeedback feedbackActive=@jackRotatorFeedbackActive
 translator DragPointDragger xTranslator.translator=@jackTranslatorLineTranslator yTranslator.translator=@jackTranslatorLineTranslator zTranslator.translator=@jackTranslatorLineTranslator xTranslator.translatorActive=@jackTranslatorLineTranslatorActive yTranslator.translatorActive=@jackTranslatorLineTranslatorActive zTranslator.translatorActive=@jackTranslatorLineTranslatorActive xzTranslator.translator=@jackTranslatorPlaneTranslator xyTranslator.translator=@jackTranslatorPlaneTranslator yzTranslator.translator=@jackTranslatorPlaneTranslator xzTranslator.translatorActive=@jackTranslatorPlaneTranslatorActive xyTranslator.translatorActive=@jackTranslatorPlaneTranslatorActive yzTranslator.translatorActive=@jackTranslatorPlaneTranslatorActive xFeedback=@jackTranslatorXFeedback yFeedback=@jackTranslatorYFeedback zFeedback=@jackTranslatorZFeedback xzFeedback=@jackTranslatorXZFeedback xyFeedback=@jackTranslatorXYFeedback yzFeedback=@jackTranslatorYZFeedback
 geomSeparator Separator

[CenterballDragger centerballDragger.iv]
topSeparator Separator
 motionMatrix Motion
 translateToCenter CenterMatrix
 surroundScale -
 antiSquish = AntiSquish { sizing LONGEST_DIAGONAL recalcAlways FALSE }
 lightModel -
 geomSeparator Separator
  XAxisSwitch Switch -1
   XAxis @centerballXAxis
  YAxisSwitch Switch -1
   YAxis @centerballYAxis
  ZAxisSwitch Switch -1
   ZAxis @centerballZAxis
 rotator RotateSphericalDragger rotator=@centerballRotator rotatorActive=@centerballRotatorActive feedback={} feedbackActive={}
 YRotator RotateCylindricalDragger rotator=@centerballStripe rotatorActive=@centerballStripeActive feedback={} feedbackActive={}
 ZCenterChanger Translate2Dragger translator=@centerballCenterChanger translatorActive=@centerballCenterChangerActive xAxisFeedback=@centerballCenterXAxisFeedback yAxisFeedback=@centerballCenterYAxisFeedback
 rotX90 = Rotation { rotation 1 0 0 1.5707964 }
 ZRotator RotateCylindricalDragger rotator=@centerballStripe rotatorActive=@centerballStripeActive feedback={} feedbackActive={}
 YCenterChanger Translate2Dragger translator=@centerballCenterChanger translatorActive=@centerballCenterChangerActive xAxisFeedback=@centerballCenterXAxisFeedback yAxisFeedback=@centerballCenterYAxisFeedback
 rotY90 = Rotation { rotation 0 1 0 1.5707964 }
 XCenterChanger Translate2Dragger translator=@centerballCenterChanger translatorActive=@centerballCenterChangerActive xAxisFeedback=@centerballCenterXAxisFeedback yAxisFeedback=@centerballCenterYAxisFeedback
 rot2X90 = Rotation { rotation 1 0 0 1.5707964 }
 XRotator RotateCylindricalDragger rotator=@centerballStripe rotatorActive=@centerballStripeActive feedback={} feedbackActive={}

[TabPlaneDragger tabPlaneDragger.iv]
topSeparator Separator
 motionMatrix Motion
 geomSeparator Separator
  planeSwitch Switch -3
   translator @tabPlaneTranslator
   scaleTabs Separator
    scaleTabMaterial @tabPlaneScaleTabMaterial
    scaleTabHints @tabPlaneScaleTabHints
    scaleTabMaterialBinding = MaterialBinding { value OVERALL }
    scaleTabNormalBinding = NormalBinding { value OVERALL }
    scaleTabNormal = Normal { vector 0 0 1 }
    edgeScaleCoords EdgeScaleCoords
    edgeScaleTab0 = IndexedFaceSet { coordIndex [ 0, 1, 2, 3, -1 ] normalIndex 0 materialIndex 0 }
    edgeScaleTab1 = IndexedFaceSet { coordIndex [ 4, 5, 6, 7, -1 ] normalIndex 0 materialIndex 0 }
    edgeScaleTab2 = IndexedFaceSet { coordIndex [ 8, 9, 10, 11, -1 ] normalIndex 0 materialIndex 0 }
    edgeScaleTab3 = IndexedFaceSet { coordIndex [ 12, 13, 14, 15, -1 ] normalIndex 0 materialIndex 0 }
    cornerScaleCoords CornerScaleCoords
    cornerScaleTab0 = IndexedFaceSet { coordIndex [ 0, 1, 2, 3, -1 ] normalIndex 0 materialIndex 0 }
    cornerScaleTab1 = IndexedFaceSet { coordIndex [ 4, 5, 6, 7, -1 ] normalIndex 0 materialIndex 0 }
    cornerScaleTab2 = IndexedFaceSet { coordIndex [ 8, 9, 10, 11, -1 ] normalIndex 0 materialIndex 0 }
    cornerScaleTab3 = IndexedFaceSet { coordIndex [ 12, 13, 14, 15, -1 ] normalIndex 0 materialIndex 0 }

[TabBoxDragger tabBoxDragger.iv readValuesIgnored]
topSeparator Separator
 motionMatrix Motion
 surroundScale -
 tabPlane1Sep Separator
  tabPlane1Xf = Transform { translation 0 0 1 }
  tabPlane1 TabPlaneDragger translator=@tabBoxTranslator scaleTabMaterial=@tabBoxScaleTabMaterial scaleTabHints=@tabBoxScaleTabHints
 tabPlane2Sep Separator
  tabPlane2Xf = Transform { translation 0 0 -1 rotation 1 0 0 3.1415927 }
  tabPlane2 TabPlaneDragger translator=@tabBoxTranslator scaleTabMaterial=@tabBoxScaleTabMaterial scaleTabHints=@tabBoxScaleTabHints
 tabPlane3Sep Separator
  tabPlane3Xf = Transform { translation 1 0 0 rotation 0 1 0 1.5707964 }
  tabPlane3 TabPlaneDragger translator=@tabBoxTranslator scaleTabMaterial=@tabBoxScaleTabMaterial scaleTabHints=@tabBoxScaleTabHints
 tabPlane4Sep Separator
  tabPlane4Xf = Transform { translation -1 0 0 rotation 0 1 0 -1.5707964 }
  tabPlane4 TabPlaneDragger translator=@tabBoxTranslator scaleTabMaterial=@tabBoxScaleTabMaterial scaleTabHints=@tabBoxScaleTabHints
 tabPlane5Sep Separator
  tabPlane5Xf = Transform { translation 0 1 0 rotation 1 0 0 -1.5707964 }
  tabPlane5 TabPlaneDragger translator=@tabBoxTranslator scaleTabMaterial=@tabBoxScaleTabMaterial scaleTabHints=@tabBoxScaleTabHints
 tabPlane6Sep Separator
  tabPlane6Xf = Transform { translation 0 -1 0 rotation 1 0 0 1.5707964 }
  tabPlane6 TabPlaneDragger translator=@tabBoxTranslator scaleTabMaterial=@tabBoxScaleTabMaterial scaleTabHints=@tabBoxScaleTabHints
 geomSeparator Separator
  boxGeom @tabBoxBoxGeom

[HandleBoxDragger handleBoxDragger.iv]
topSeparator Separator
 motionMatrix Motion
 surroundScale -
 geomSeparator Separator
  drawStyle -
  translator1Switch Switch 0
   translator1 @handleBoxTranslator1
   translator1Active @handleBoxTranslator1Active
  translator2Switch Switch 0
   translator2 @handleBoxTranslator2
   translator2Active @handleBoxTranslator2Active
  translator3Switch Switch 0
   translator3 @handleBoxTranslator3
   translator3Active @handleBoxTranslator3Active
  translator4Switch Switch 0
   translator4 @handleBoxTranslator4
   translator4Active @handleBoxTranslator4Active
  translator5Switch Switch 0
   translator5 @handleBoxTranslator5
   translator5Active @handleBoxTranslator5Active
  translator6Switch Switch 0
   translator6 @handleBoxTranslator6
   translator6Active @handleBoxTranslator6Active
  extruder1Switch Switch 0
   extruder1 @handleBoxExtruder1
   extruder1Active @handleBoxExtruder1Active
  extruder2Switch Switch 0
   extruder2 @handleBoxExtruder2
   extruder2Active @handleBoxExtruder2Active
  extruder3Switch Switch 0
   extruder3 @handleBoxExtruder3
   extruder3Active @handleBoxExtruder3Active
  extruder4Switch Switch 0
   extruder4 @handleBoxExtruder4
   extruder4Active @handleBoxExtruder4Active
  extruder5Switch Switch 0
   extruder5 @handleBoxExtruder5
   extruder5Active @handleBoxExtruder5Active
  extruder6Switch Switch 0
   extruder6 @handleBoxExtruder6
   extruder6Active @handleBoxExtruder6Active
  uniform1Switch Switch 0
   uniform1 @handleBoxUniform1
   uniform1Active @handleBoxUniform1Active
  uniform2Switch Switch 0
   uniform2 @handleBoxUniform2
   uniform2Active @handleBoxUniform2Active
  uniform3Switch Switch 0
   uniform3 @handleBoxUniform3
   uniform3Active @handleBoxUniform3Active
  uniform4Switch Switch 0
   uniform4 @handleBoxUniform4
   uniform4Active @handleBoxUniform4Active
  uniform5Switch Switch 0
   uniform5 @handleBoxUniform5
   uniform5Active @handleBoxUniform5Active
  uniform6Switch Switch 0
   uniform6 @handleBoxUniform6
   uniform6Active @handleBoxUniform6Active
  uniform7Switch Switch 0
   uniform7 @handleBoxUniform7
   uniform7Active @handleBoxUniform7Active
  uniform8Switch Switch 0
   uniform8 @handleBoxUniform8
   uniform8Active @handleBoxUniform8Active
  arrowTranslation -
  arrow1Switch Switch -1
   arrow1 @handleBoxArrow1
  arrow2Switch Switch -1
   arrow2 @handleBoxArrow2
  arrow3Switch Switch -1
   arrow3 @handleBoxArrow3
  arrow4Switch Switch -1
   arrow4 @handleBoxArrow4
  arrow5Switch Switch -1
   arrow5 @handleBoxArrow5
  arrow6Switch Switch -1
   arrow6 @handleBoxArrow6

[DirectionalLightDragger directionalLightDragger.iv readValuesIgnored]
topSeparator Separator
 motionMatrix Motion
 material @directionalLightOverallMaterial
 translatorSep Separator
  translatorRotInv RotationInverse
  translator DragPointDragger xTranslator.translator=@directionalLightTranslatorLineTranslator xTranslator.translatorActive=@directionalLightTranslatorLineTranslatorActive yTranslator.translator=@directionalLightTranslatorLineTranslator yTranslator.translatorActive=@directionalLightTranslatorLineTranslatorActive zTranslator.translator=@directionalLightTranslatorLineTranslator zTranslator.translatorActive=@directionalLightTranslatorLineTranslatorActive xyTranslator.translator=@directionalLightTranslatorPlaneTranslator xyTranslator.translatorActive=@directionalLightTranslatorPlaneTranslatorActive xzTranslator.translator=@directionalLightTranslatorPlaneTranslator xzTranslator.translatorActive=@directionalLightTranslatorPlaneTranslatorActive yzTranslator.translator=@directionalLightTranslatorPlaneTranslator yzTranslator.translatorActive=@directionalLightTranslatorPlaneTranslatorActive
 rotator RotateSphericalDragger rotator=@directionalLightRotatorRotator rotatorActive=@directionalLightRotatorRotatorActive feedback=@directionalLightRotatorFeedback feedbackActive=@directionalLightRotatorFeedbackActive
 geomSeparator Separator

[PointLightDragger pointLightDragger.iv readValuesIgnored]
topSeparator Separator
 motionMatrix Motion
 material @pointLightOverallMaterial
 translator DragPointDragger xTranslator.translator=@pointLightTranslatorLineTranslator xTranslator.translatorActive=@pointLightTranslatorLineTranslatorActive yTranslator.translator=@pointLightTranslatorLineTranslator yTranslator.translatorActive=@pointLightTranslatorLineTranslatorActive zTranslator.translator=@pointLightTranslatorLineTranslator zTranslator.translatorActive=@pointLightTranslatorLineTranslatorActive xyTranslator.translator=@pointLightTranslatorPlaneTranslator xyTranslator.translatorActive=@pointLightTranslatorPlaneTranslatorActive xzTranslator.translator=@pointLightTranslatorPlaneTranslator xzTranslator.translatorActive=@pointLightTranslatorPlaneTranslatorActive yzTranslator.translator=@pointLightTranslatorPlaneTranslator yzTranslator.translatorActive=@pointLightTranslatorPlaneTranslatorActive
 geomSeparator Separator

[SpotLightDragger spotLightDragger.iv readValuesIgnored]
topSeparator Separator
 motionMatrix Motion
 material @spotLightOverallMaterial
 translatorSep Separator
  translatorRotInv RotationInverse
  translator DragPointDragger xTranslator.translator=@spotLightTranslatorLineTranslator xTranslator.translatorActive=@spotLightTranslatorLineTranslatorActive yTranslator.translator=@spotLightTranslatorLineTranslator yTranslator.translatorActive=@spotLightTranslatorLineTranslatorActive zTranslator.translator=@spotLightTranslatorLineTranslator zTranslator.translatorActive=@spotLightTranslatorLineTranslatorActive xyTranslator.translator=@spotLightTranslatorPlaneTranslator xyTranslator.translatorActive=@spotLightTranslatorPlaneTranslatorActive xzTranslator.translator=@spotLightTranslatorPlaneTranslator xzTranslator.translatorActive=@spotLightTranslatorPlaneTranslatorActive yzTranslator.translator=@spotLightTranslatorPlaneTranslator yzTranslator.translatorActive=@spotLightTranslatorPlaneTranslatorActive
 rotator RotateSphericalDragger rotator=@spotLightRotatorRotator rotatorActive=@spotLightRotatorRotatorActive feedback=@spotLightRotatorFeedback feedbackActive=@spotLightRotatorFeedbackActive
 beamSep Separator
  beamPlacement @spotLightBeamPlacement
  beamScale BeamScale
  beamSwitch Switch 0
   beam @spotLightBeam
   beamActive @spotLightBeamActive
 geomSeparator Separator

[TransformerDragger transformerDragger.iv]
topSeparator Separator
 motionMatrix Motion
 surroundScale -
 overallStyle @transformerOverallStyle
 geomSeparator Separator
  axisFeedbackSep Separator
   axisFeedbackLocation -
   xAxisFeedbackSwitch Switch -1
    xAxisFeedbackActive @transformerXAxisFeedbackActive
    xAxisFeedbackSelect @transformerXAxisFeedbackSelect
    xCrosshairFeedback @transformerXCrosshairFeedback
   yAxisFeedbackSwitch Switch -1
    yAxisFeedbackActive @transformerYAxisFeedbackActive
    yAxisFeedbackSelect @transformerYAxisFeedbackSelect
    yCrosshairFeedback @transformerYCrosshairFeedback
   zAxisFeedbackSwitch Switch -1
    zAxisFeedbackActive @transformerZAxisFeedbackActive
    zAxisFeedbackSelect @transformerZAxisFeedbackSelect
    zCrosshairFeedback @transformerZCrosshairFeedback
  translateBoxFeedbackSep Separator
   translateBoxFeedbackSwitch Switch -1
    translateBoxFeedbackRotation -
    translateBoxFeedback @transformerTranslateBoxFeedback
  scaleBoxFeedbackSwitch Switch -1
   scaleBoxFeedback @transformerScaleBoxFeedback
  posXWallFeedbackSwitch Switch -1
   posXWallFeedback @transformerPosXWallFeedback
   posXRoundWallFeedback @transformerPosXRoundWallFeedback
  posYWallFeedbackSwitch Switch -1
   posYWallFeedback @transformerPosYWallFeedback
   posYRoundWallFeedback @transformerPosYRoundWallFeedback
  posZWallFeedbackSwitch Switch -1
   posZWallFeedback @transformerPosZWallFeedback
   posZRoundWallFeedback @transformerPosZRoundWallFeedback
  negXWallFeedbackSwitch Switch -1
   negXWallFeedback @transformerNegXWallFeedback
   negXRoundWallFeedback @transformerNegXRoundWallFeedback
  negYWallFeedbackSwitch Switch -1
   negYWallFeedback @transformerNegYWallFeedback
   negYRoundWallFeedback @transformerNegYRoundWallFeedback
  negZWallFeedbackSwitch Switch -1
   negZWallFeedback @transformerNegZWallFeedback
   negZRoundWallFeedback @transformerNegZRoundWallFeedback
  radialFeedbackSwitch Switch -1
   radialFeedback @transformerRadialFeedback
 translatorSep Separator
  translator1Switch Switch 0
   translator1LocateGroup Separator
    translator1 @transformerTranslator1
   translator1Active @transformerTranslator1Active
  translator2Switch Switch 0
   translator2LocateGroup Separator
    translator2 @transformerTranslator2
   translator2Active @transformerTranslator2Active
  translator3Switch Switch 0
   translator3LocateGroup Separator
    translator3 @transformerTranslator3
   translator3Active @transformerTranslator3Active
  translator4Switch Switch 0
   translator4LocateGroup Separator
    translator4 @transformerTranslator4
   translator4Active @transformerTranslator4Active
  translator5Switch Switch 0
   translator5LocateGroup Separator
    translator5 @transformerTranslator5
   translator5Active @transformerTranslator5Active
  translator6Switch Switch 0
   translator6LocateGroup Separator
    translator6 @transformerTranslator6
   translator6Active @transformerTranslator6Active
 rotatorSep Separator
  rotator1Switch Switch 0
   rotator1LocateGroup Separator
    rotator1 @transformerRotator1
   rotator1Active @transformerRotator1Active
  rotator2Switch Switch 0
   rotator2LocateGroup Separator
    rotator2 @transformerRotator2
   rotator2Active @transformerRotator2Active
  rotator3Switch Switch 0
   rotator3LocateGroup Separator
    rotator3 @transformerRotator3
   rotator3Active @transformerRotator3Active
  rotator4Switch Switch 0
   rotator4LocateGroup Separator
    rotator4 @transformerRotator4
   rotator4Active @transformerRotator4Active
  rotator5Switch Switch 0
   rotator5LocateGroup Separator
    rotator5 @transformerRotator5
   rotator5Active @transformerRotator5Active
  rotator6Switch Switch 0
   rotator6LocateGroup Separator
    rotator6 @transformerRotator6
   rotator6Active @transformerRotator6Active
 scaleSep Separator
  scale1Switch Switch 0
   scale1LocateGroup Separator
    scale1 @transformerScale1
   scale1Active @transformerScale1Active
  scale2Switch Switch 0
   scale2LocateGroup Separator
    scale2 @transformerScale2
   scale2Active @transformerScale2Active
  scale3Switch Switch 0
   scale3LocateGroup Separator
    scale3 @transformerScale3
   scale3Active @transformerScale3Active
  scale4Switch Switch 0
   scale4LocateGroup Separator
    scale4 @transformerScale4
   scale4Active @transformerScale4Active
  scale5Switch Switch 0
   scale5LocateGroup Separator
    scale5 @transformerScale5
   scale5Active @transformerScale5Active
  scale6Switch Switch 0
   scale6LocateGroup Separator
    scale6 @transformerScale6
   scale6Active @transformerScale6Active
  scale7Switch Switch 0
   scale7LocateGroup Separator
    scale7 @transformerScale7
   scale7Active @transformerScale7Active
  scale8Switch Switch 0
   scale8LocateGroup Separator
    scale8 @transformerScale8
   scale8Active @transformerScale8Active
 circleFeedbackSep Separator
  circleFeedbackTransformSwitch Switch -1
   circleFeedbackAntiSquish = AntiSquish { }
   circleFeedbackTransform = Transform { }
  xCircleFeedbackSwitch Switch -1
   xCircleFeedback @transformerXCircleFeedback
  yCircleFeedbackSwitch Switch -1
   yCircleFeedback @transformerYCircleFeedback
  zCircleFeedbackSwitch Switch -1
   zCircleFeedback @transformerZCircleFeedback
)";

DraggerPart parsePart(const std::string& line, std::size_t& depth) {
    depth = line.find_first_not_of(' ');
    std::istringstream words(line.substr(depth));
    DraggerPart part;
    std::string kind;
    words >> part.name >> kind;
    using Kind = DraggerPart::Kind;
    if (kind == "Separator") {
        part.kind = Kind::Separator;
    } else if (kind == "Group") {
        part.kind = Kind::Group;
    } else if (kind == "Switch") {
        part.kind = Kind::Switch;
        words >> part.switchValue;
    } else if (kind == "Motion") {
        part.kind = Kind::Motion;
    } else if (kind == "CenterMatrix") {
        part.kind = Kind::CenterMatrix;
    } else if (kind == "RotationInverse") {
        part.kind = Kind::RotationInverse;
    } else if (kind == "BeamScale") {
        part.kind = Kind::BeamScale;
    } else if (kind == "EdgeScaleCoords") {
        part.kind = Kind::EdgeScaleCoords;
    } else if (kind == "CornerScaleCoords") {
        part.kind = Kind::CornerScaleCoords;
    } else if (kind == "-") {
        part.kind = Kind::Null;
    } else if (kind == "=") {
        part.kind = Kind::Inline;
        std::getline(words, part.value);
    } else if (kind.starts_with('@')) {
        part.kind = Kind::Resource;
        part.value = kind.substr(1);
    } else if (kind.ends_with("Dragger")) {
        part.kind = Kind::ChildDragger;
        part.value = kind;
        for (std::string assignment; words >> assignment;) {
            const auto eq = assignment.find('=');
            if (eq == std::string::npos)
                throw Error("dragger catalog: bad part default " + assignment);
            part.childDefaults.emplace_back(assignment.substr(0, eq), assignment.substr(eq + 1));
        }
    } else {
        throw Error("dragger catalog: unknown part kind '" + kind + "' of " + part.name);
    }
    return part;
}

std::vector<DraggerCatalog> parseCatalogs() {
    std::vector<DraggerCatalog> out;
    std::istringstream lines(catalogText);
    std::vector<int> parents; // the container at each depth
    for (std::string line; std::getline(lines, line);) {
        if (line.find_first_not_of(' ') == std::string::npos) continue;
        if (line[0] == '[') {
            DraggerCatalog catalog;
            std::istringstream words(line.substr(1, line.find(']') - 1));
            std::string flag;
            words >> catalog.typeName >> catalog.resourceFile >> flag;
            catalog.readValuesIgnored = flag == "readValuesIgnored";
            out.push_back(std::move(catalog));
            parents.clear();
            continue;
        }
        std::size_t depth = 0;
        DraggerPart part = parsePart(line, depth);
        auto& parts = out.back().parts;
        const int index = int(parts.size());
        parents.resize(depth);
        if (depth > 0) parts[std::size_t(parents[depth - 1])].children.push_back(index);
        parents.push_back(index);
        parts.push_back(std::move(part));
    }
    return out;
}

} // namespace

const std::vector<DraggerCatalog>& draggerCatalogs() {
    static const std::vector<DraggerCatalog> catalogs = parseCatalogs();
    return catalogs;
}

} // namespace volsg
