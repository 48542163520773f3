// The grouping nodes of Inventor besides Group, Separator and Switch: LOD, LevelOfDetail,
// Array, MultipleCopy, Selection (Annotation and TransformSeparator have their own files'
// worth of nothing: Annotation.h, InventorTransforms.cpp).
#include <volsg/actions/Action.h>
#include <volsg/core/Error.h>
#include <volsg/nodes/Array.h>
#include <volsg/nodes/LOD.h>
#include <volsg/nodes/LevelOfDetail.h>
#include <volsg/nodes/MultipleCopy.h>
#include <volsg/nodes/Selection.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

namespace volsg {

int LOD::childFor(const glm::dvec3& eye, const glm::dmat4& model) const {
    const int n = int(getNumChildren());
    if (n == 0) return -1;
    const glm::dvec3 worldCenter(model * glm::dvec4(glm::dvec3(center()), 1.0));
    const double distance = glm::length(eye - worldCenter);
    int i = 0;
    const int ranges = int(range.size());
    while (i < ranges && !(distance < double(range[std::size_t(i)])))
        ++i;
    return std::min(i, n - 1);
}

glm::ivec2 LevelOfDetail::screenSize(const Box3& localBox, const glm::dmat4& modelViewProjection,
                                     int viewportWidth, int viewportHeight) {
    if (localBox.isEmpty()) return {viewportWidth / 2, viewportHeight / 2};
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-lo);
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 corner((i & 1) ? localBox.min.x : localBox.max.x,
                                (i & 2) ? localBox.min.y : localBox.max.y,
                                (i & 4) ? localBox.min.z : localBox.max.z);
        const glm::dvec4 clip = modelViewProjection * glm::dvec4(corner, 1.0);
        const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
        lo = glm::min(lo, ndc);
        hi = glm::max(hi, ndc);
    }
    // Coin clamps each side to 10 NDC units ("often way off when object intersects the near
    // plane") and keeps the pixel size in a short.
    const auto pixels = [](double ndcSize, int viewport) {
        const double n = std::isfinite(ndcSize) ? std::min(ndcSize, 10.0) : 10.0;
        return int(std::min(32767.0, double(viewport) * 0.5 * n));
    };
    return {pixels(hi.x - lo.x, viewportWidth), pixels(hi.y - lo.y, viewportHeight)};
}

int LevelOfDetail::childFor(double projectedArea) const {
    const int n = int(getNumChildren());
    if (n == 0) return -1;
    if (n == 1 || screenArea.empty()) return 0;
    // Coin multiplies the area by complexity + 0.5; volsg has no Complexity node, and the
    // default complexity 0.5 makes the factor 1.
    const int m = std::min(n, int(screenArea.size()));
    for (int i = 0; i < m; ++i)
        if (projectedArea > double(screenArea[std::size_t(i)])) return i;
    return n - 1;
}

const EnumValues Array::originNames{{"FIRST", FIRST}, {"CENTER", CENTER}, {"LAST", LAST}};

glm::dvec3 Array::offset(int i, int j, int k) const {
    // i counts along separation1 (numElements1), j along 2, k along 3, as Coin's SoArray.
    const auto factor = [this](int index, int count) {
        switch (origin()) {
        case CENTER:
            return -double(count - 1) / 2.0 + double(index);
        case LAST:
            return -double(index);
        default:
            return double(index);
        }
    };
    return glm::dvec3(separation1()) * factor(i, numElements1()) +
           glm::dvec3(separation2()) * factor(j, numElements2()) +
           glm::dvec3(separation3()) * factor(k, numElements3());
}

void Array::doAction(Action& action) {
    const int n1 = std::max(0, numElements1()), n2 = std::max(0, numElements2()),
              n3 = std::max(0, numElements3());
    const std::size_t copies = std::size_t(n1) * std::size_t(n2) * std::size_t(n3);
    if (copies > maxCopies)
        throw Error("Array" + (getName().empty() ? std::string() : " '" + getName() + "'") +
                    " has " + std::to_string(n1) + " x " + std::to_string(n2) + " x " +
                    std::to_string(n3) + " copies; at most " + std::to_string(maxCopies) +
                    " are drawn");
    // No copies or no children: nothing to traverse. The loops below count no instances by
    // themselves, so numElements1 0 with numElements3 2^31-1, or an empty Array of 65536 copies
    // inside another, spun for billions of empty iterations.
    if (copies == 0 || getNumChildren() == 0) return;
    State& state = action.state();
    for (int k = 0; k < n3; ++k)
        for (int j = 0; j < n2; ++j)
            for (int i = 0; i < n1; ++i) {
                if (action.isTerminated()) return;
                state.push();
                state.multModelMatrix(glm::translate(glm::dmat4(1.0), offset(i, j, k)));
                Group::doAction(action);
                state.pop();
            }
}

void MultipleCopy::doAction(Action& action) {
    if (getNumChildren() == 0) return; // as Array: copies of nothing are nothing
    State& state = action.state();
    for (const glm::mat4& m : matrix()) {
        if (action.isTerminated()) return;
        state.push();
        state.multModelMatrix(glm::dmat4(m));
        Group::doAction(action);
        state.pop();
    }
}

const EnumValues Selection::policyNames{
    {"SINGLE", SINGLE}, {"TOGGLE", TOGGLE}, {"SHIFT", SHIFT}, {"DISABLE", DISABLE}};

} // namespace volsg
