#include <volsg/actions/Action.h>
#include <volsg/math/TransformParts.h>
#include <volsg/nodes/AntiSquish.h>
#include <volsg/state/State.h>

#include <algorithm>
#include <cmath>

namespace volsg {

const EnumValues AntiSquish::sizingNames{{"X", X},
                                         {"Y", Y},
                                         {"Z", Z},
                                         {"AVERAGE_DIMENSION", AVERAGE_DIMENSION},
                                         {"BIGGEST_DIMENSION", BIGGEST_DIMENSION},
                                         {"SMALLEST_DIMENSION", SMALLEST_DIMENSION},
                                         {"LONGEST_DIAGONAL", LONGEST_DIAGONAL}};

glm::dmat4 AntiSquish::unsquished(const glm::dmat4& model) const {
    TransformParts parts = decomposeTransform(model);
    const glm::dvec3 s = parts.scaleFactor;
    double value = 1.0;
    switch (sizing()) {
    case X:
        value = s.x;
        break;
    case Y:
        value = s.y;
        break;
    case Z:
        value = s.z;
        break;
    case BIGGEST_DIMENSION:
        value = std::max({s.x, s.y, s.z});
        break;
    case SMALLEST_DIMENSION:
        value = std::min({s.x, s.y, s.z});
        break;
    case LONGEST_DIAGONAL: {
        // Coin: half the longest of the cube's four diagonals, transformed.
        double longest = 0.0;
        for (int corner = 0; corner < 4; ++corner) {
            const glm::dvec3 a(corner & 1 ? 1.0 : -1.0, corner & 2 ? 1.0 : -1.0, -1.0);
            const glm::dvec3 d = glm::dmat3(model) * (-a - a);
            longest = std::max(longest, glm::length(d));
        }
        value = 0.5 * longest;
        break;
    }
    default:
        value = (s.x + s.y + s.z) / 3.0;
        break;
    }
    parts.scaleFactor = glm::dvec3(value);
    return composeTransform(parts);
}

void AntiSquish::doAction(Action& action) {
    action.state().setModelMatrix(unsquished(action.state().modelMatrix()));
}

} // namespace volsg
