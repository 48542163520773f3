#include <volsg/nodes/Volume.h>

#include <volsg/volume/VolumeModel.h>

namespace volsg {

const EnumValues Volume::renderModeNames{
    {"DVR", DVR}, {"MIP", MIP}, {"MINIP", MINIP}, {"AVERAGE", AVERAGE}};
const EnumValues Volume::interpolationNames{{"LINEAR", LINEAR}, {"NEAREST", NEAREST}};

VolumeRenderMode Volume::mode() const {
    switch (renderMode()) {
    case MIP:
        return VolumeRenderMode::MIP;
    case MINIP:
        return VolumeRenderMode::MINIP;
    case AVERAGE:
        return VolumeRenderMode::AVERAGE;
    default:
        return VolumeRenderMode::DVR;
    }
}

} // namespace volsg
