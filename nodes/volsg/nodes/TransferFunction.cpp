#include <volsg/nodes/TransferFunction.h>

#include <string>
#include <vector>

#include <volsg/actions/Action.h>
#include <volsg/core/Error.h>
#include <volsg/volume/TransferFunction1D.h>

namespace volsg {

namespace {

std::vector<PiecewiseLinear::Point> pointsOf(const MFVec2f& field) {
    std::vector<PiecewiseLinear::Point> points;
    points.reserve(field.size());
    for (const glm::vec2& p : field.getValues())
        points.push_back({double(p.x), double(p.y)});
    return points;
}

} // namespace

TransferFunction1D TransferFunction::function() const {
    TransferFunction1D tf;
    const std::pair<TransferFunction1D::Channel, const MFVec2f*> channels[] = {
        {TransferFunction1D::Red, &red},
        {TransferFunction1D::Green, &green},
        {TransferFunction1D::Blue, &blue},
        {TransferFunction1D::Alpha, &alpha}};
    for (const auto& [channel, field] : channels) {
        try {
            tf.setChannel(channel, pointsOf(*field));
        } catch (const Error& e) {
            throw Error("TransferFunction (tag " + std::to_string(tag()) + ") " + field->name() +
                        ": " + e.message());
        }
    }
    // Unset, the range is the data type's (resolved against the grid it is applied to).
    if (!dataRange.isDefault()) {
        try {
            tf.setDataRange(dataRange().x, dataRange().y);
        } catch (const Error& e) {
            throw Error("TransferFunction (tag " + std::to_string(tag()) + "): " + e.message());
        }
    }
    return tf;
}

void TransferFunction::doAction(Action& action) {
    action.state().add(*this);
}

} // namespace volsg
