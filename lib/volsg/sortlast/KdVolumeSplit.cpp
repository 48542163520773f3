#include <volsg/sortlast/KdVolumeSplit.h>

#include <algorithm>
#include <cmath>

namespace volsg {

KdVolumeSplit::KdVolumeSplit(glm::ivec3 dimensions, glm::dvec3 spacing, int parts)
    : dims_(glm::max(dimensions, glm::ivec3(1))), spacing_(spacing),
      parts_(std::size_t(std::max(parts, 1))) {
    split(glm::ivec3(0), dims_ - 1, 0, int(parts_.size()));
}

double KdVolumeSplit::localOf(int axis, int voxel, bool upper) const {
    // The outer faces, or the cut between voxel and voxel + 1 (upper) / voxel - 1 and voxel.
    double u;
    if (!upper)
        u = voxel == 0 ? 0.0 : voxel + 0.5;
    else
        u = voxel == dims_[axis] - 1 ? double(dims_[axis]) : voxel + 0.5;
    return u * spacing_[axis] - 0.5 * double(dims_[axis]) * spacing_[axis];
}

int KdVolumeSplit::split(glm::ivec3 first, glm::ivec3 last, int firstPart, int count) {
    const glm::ivec3 cells = last - first;
    int axis = 0;
    for (int a = 1; a < 3; ++a)
        if (double(cells[a]) * spacing_[a] > double(cells[axis]) * spacing_[axis]) axis = a;
    const int node = int(cuts_.size());
    cuts_.emplace_back();
    if (count == 1 || cells[axis] < 2) {
        // A leaf (a part of one cell along its longest axis is not cut: a cut needs a cell on
        // each side); the parts left over own nothing.
        cuts_[std::size_t(node)].part = firstPart;
        Part& p = parts_[std::size_t(firstPart)];
        p.empty = false;
        p.firstVoxel = first;
        p.lastVoxel = last;
        for (int a = 0; a < 3; ++a) {
            p.boxMin[a] = localOf(a, first[a], false);
            p.boxMax[a] = localOf(a, last[a], true);
        }
        return node;
    }
    const int lowParts = count / 2;
    const int at =
        std::clamp(first[axis] + int(std::lround(double(cells[axis]) * lowParts / count)),
                   first[axis] + 1, last[axis] - 1);
    glm::ivec3 lowLast = last, highFirst = first;
    lowLast[axis] = at;
    highFirst[axis] = at;
    const int low = split(first, lowLast, firstPart, lowParts);
    const int high = split(highFirst, last, firstPart + lowParts, count - lowParts);
    Cut& cut = cuts_[std::size_t(node)];
    cut.axis = axis;
    cut.plane = localOf(axis, at, true); // == the high side's boxMin
    cut.low = low;
    cut.high = high;
    return node;
}

void KdVolumeSplit::voxelsWithGhost(int p, int ghost, glm::ivec3& first, glm::ivec3& count) const {
    const Part& part = parts_[std::size_t(p)];
    if (part.empty) {
        first = glm::ivec3(0);
        count = glm::ivec3(0);
        return;
    }
    first = glm::max(part.firstVoxel - ghost, glm::ivec3(0));
    count = glm::min(part.lastVoxel + ghost, dims_ - 1) - first + 1;
}

std::vector<int> KdVolumeSplit::frontToBack(const glm::dvec3& eyeOrDirection,
                                            bool orthographic) const {
    std::vector<int> order;
    std::vector<int> stack{0};
    while (!stack.empty()) {
        const Cut& cut = cuts_[std::size_t(stack.back())];
        stack.pop_back();
        if (cut.axis < 0) {
            order.push_back(cut.part);
            continue;
        }
        const double e = eyeOrDirection[cut.axis];
        // Orthographic: looking towards +axis, the low side is met first.
        const bool lowInFront = orthographic ? e > 0.0 : e < cut.plane;
        // Pushed back first, popped front first.
        stack.push_back(lowInFront ? cut.high : cut.low);
        stack.push_back(lowInFront ? cut.low : cut.high);
    }
    for (int p = 0; p < parts(); ++p)
        if (parts_[std::size_t(p)].empty) order.push_back(p);
    return order;
}

} // namespace volsg
