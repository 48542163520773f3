#include <volsg/shearwarp/VoxelTables.h>

#include <algorithm>
#include <cmath>

#include <volsg/shearwarp/ShadingTable.h>

namespace volsg {

namespace {

/// Opacity of one sample of spacing ds for a slab opacity A over L0 (docs/SCENE-FORMAT.md section
/// 4), with the object's extinction multiplier folded into the exponent.
float corrected(double alpha, double exponent) {
    const double a = std::clamp(alpha, 0.0, 1.0 - 1e-6);
    if (a <= 0.0 || exponent <= 0.0) return 0.0f;
    return float(1.0 - std::pow(1.0 - a, exponent));
}

glm::dvec3 colourAt(const TransferFunction1D& tf, double v) {
    return {tf.evaluate(TransferFunction1D::Red, v), tf.evaluate(TransferFunction1D::Green, v),
            tf.evaluate(TransferFunction1D::Blue, v)};
}

/// LUT1 of the shaded modes: the transfer function's alpha at the centre of the 4-bit value bin.
double binAlpha(const TransferFunction1D& tf, int second4) {
    return tf.evaluate(TransferFunction1D::Alpha, (double(second4) + 0.5) / 16.0);
}

} // namespace

PackedLayout VoxelTables::layoutFor(VoxelRenderMode mode) {
    return mode == VoxelRenderMode::TF || mode == VoxelRenderMode::GradientOpacity
               ? PackedLayout::ValueMagnitude
               : PackedLayout::GradientValue;
}

VoxelTables VoxelTables::build(const ShearWarpObject& object, const VoxelLook& look,
                               double stepRatio, const glm::dmat3& localToEye,
                               const glm::dvec3& light) {
    const TransferFunction1D& tf = object.transferFunction;
    const double exponent = double(look.opacity) * stepRatio;
    VoxelTables t;
    switch (look.mode) {
    case VoxelRenderMode::TF: {
        t.kernel = Kernel::Direct;
        t.mask = 0xFFF;
        t.rgba.resize(4096);
        for (int m = 0; m < 4096; ++m) {
            const double v = double(m) / 4095.0;
            const float a = corrected(tf.evaluate(TransferFunction1D::Alpha, v), exponent);
            t.rgba[std::size_t(m)] = glm::vec4(glm::vec3(colourAt(tf, v)) * a, a);
        }
        break;
    }
    case VoxelRenderMode::GradientOpacity: {
        // LUT1: gradient magnitude (4 bits) -> weight s/15 on the opacity; LUT3: value -> TF.
        t.kernel = Kernel::Direct;
        t.mask = 0xFFFF;
        t.rgba.resize(65536);
        for (int m = 0; m < 4096; ++m) {
            const double v = double(m) / 4095.0;
            const glm::vec3 c(colourAt(tf, v));
            const double alpha = tf.evaluate(TransferFunction1D::Alpha, v);
            for (int s = 0; s < 16; ++s) {
                const float a = corrected(alpha * double(s) / 15.0, exponent);
                t.rgba[std::size_t((s << 12) | m)] = glm::vec4(c * a, a);
            }
        }
        break;
    }
    case VoxelRenderMode::Shaded:
    case VoxelRenderMode::Contour:
    case VoxelRenderMode::ColoredContour: {
        t.kernel = Kernel::TwoStage;
        t.lut2.resize(4096);
        if (look.mode == VoxelRenderMode::Shaded) {
            const auto phong = ShadingTable::phong(localToEye, light, object.shininess);
            for (int i = 0; i < 4096; ++i)
                t.lut2[std::size_t(i)] = std::uint8_t(std::lround(phong[std::size_t(i)] * 255.0f));
        } else if (look.mode == VoxelRenderMode::Contour) {
            const auto contour = ShadingTable::contour(localToEye, object.contourSharpness);
            for (int i = 0; i < 4096; ++i)
                t.lut2[std::size_t(i)] =
                    std::uint8_t(std::lround(contour[std::size_t(i)] * 255.0f));
        } else {
            // Phong in the low 7 bits, "contourness" in the top bit (RTVR 3.4).
            const auto phong = ShadingTable::phong(localToEye, light, object.shininess);
            const auto contour = ShadingTable::contour(localToEye, object.contourSharpness);
            for (int i = 0; i < 4096; ++i)
                t.lut2[std::size_t(i)] = std::uint8_t(std::lround(phong[std::size_t(i)] * 127.0f) +
                                                      (contour[std::size_t(i)] >= 0.5f ? 128 : 0));
        }
        t.rgba.resize(16 * 256);
        for (int s = 0; s < 16; ++s) {
            const double alpha = binAlpha(tf, s);
            for (int i = 0; i < 256; ++i) {
                glm::vec3 c;
                double a = alpha;
                if (look.mode == VoxelRenderMode::Shaded) {
                    c = glm::vec3(colourAt(tf, double(i) / 255.0));
                } else if (look.mode == VoxelRenderMode::Contour) {
                    // Bright outlines: the contour intensity is the colour index AND scales
                    // the opacity, so only the silhouettes stay (RTVR 3.4, figure 1).
                    c = glm::vec3(colourAt(tf, double(i) / 255.0));
                    a = alpha * double(i) / 255.0;
                } else {
                    c = i >= 128 ? object.contourColor : glm::vec3(colourAt(tf, double(i) / 127.0));
                }
                const float ca = corrected(a, exponent);
                t.rgba[std::size_t((s << 8) | i)] = glm::vec4(c * ca, ca);
            }
        }
        break;
    }
    }
    return t;
}

std::vector<std::uint8_t> VoxelTables::contributionMask(const ShearWarpObject& object,
                                                        const VoxelLook& look) {
    std::vector<std::uint8_t> mask(65536, 1);
    const TransferFunction1D& tf = object.transferFunction;
    if (object.compositing == ObjectCompositing::MIP) {
        // MIP resamples values, not colours: removing any voxel could lower a maximum.
        if (look.opacity <= 0.0f) std::fill(mask.begin(), mask.end(), 0);
        return mask;
    }
    for (unsigned attr = 0; attr < 65536; ++attr) {
        const unsigned m = attr & 0xFFF, s = attr >> 12;
        double alpha = 0.0;
        switch (look.mode) {
        case VoxelRenderMode::TF:
            alpha = tf.evaluate(TransferFunction1D::Alpha, double(m) / 4095.0);
            break;
        case VoxelRenderMode::GradientOpacity:
            alpha = tf.evaluate(TransferFunction1D::Alpha, double(m) / 4095.0) * double(s) / 15.0;
            break;
        default: // the shading table changes with the view: only LUT1 decides
            alpha = binAlpha(tf, int(s));
            break;
        }
        mask[attr] = alpha > 0.0 && look.opacity > 0.0f;
    }
    return mask;
}

} // namespace volsg
