// Profiles: their curves, the list in scope (Inventor's profile element) and what NURBS
// surfaces (trim loops) and Text3 (its bevel) make of it.
#include <volsg/nodes/Profile.h>
#include <volsg/nodes/ProfileCoordinate2.h>
#include <volsg/nodes/ProfileCoordinate3.h>

#include <cmath>
#include <string>

#include <volsg/actions/Action.h>
#include <volsg/core/Error.h>
#include <volsg/geometry/MeshKey.h>
#include <volsg/geometry/Nurbs.h>
#include <volsg/state/State.h>

namespace volsg {

const EnumValues Profile::linkageNames{
    {"START_FIRST", START_FIRST}, {"START_NEW", START_NEW}, {"ADD_TO_CURRENT", ADD_TO_CURRENT}};

void ProfileCoordinate2::doAction(Action& action) {
    action.state().add(*this);
}
void ProfileCoordinate3::doAction(Action& action) {
    action.state().add(*this);
}
void Profile::doAction(Action& action) {
    action.state().add(*this);
}

namespace {

/// The homogeneous profile coordinates (x, y, 0, w) of the node (w = 1 for ProfileCoordinate2).
std::vector<glm::dvec4> homogeneous(const Node* coordinates, const char* type) {
    std::vector<glm::dvec4> out;
    if (!coordinates) return out;
    auto check = [type](double v, std::size_t i) {
        if (!std::isfinite(v))
            throw Error(std::string(type) + ": profile coordinate " + std::to_string(i) +
                        " is not a finite number");
    };
    if (coordinates->isA<ProfileCoordinate2>()) {
        const auto& p = static_cast<const ProfileCoordinate2*>(coordinates)->point.getValues();
        out.reserve(p.size());
        for (std::size_t i = 0; i < p.size(); ++i) {
            check(p[i].x, i);
            check(p[i].y, i);
            out.emplace_back(p[i].x, p[i].y, 0.0, 1.0);
        }
    } else if (coordinates->isA<ProfileCoordinate3>()) {
        const auto& p = static_cast<const ProfileCoordinate3*>(coordinates)->point.getValues();
        out.reserve(p.size());
        for (std::size_t i = 0; i < p.size(); ++i) {
            check(p[i].x, i);
            check(p[i].y, i);
            check(p[i].z, i);
            out.emplace_back(p[i].x, p[i].y, 0.0, p[i].z);
        }
    }
    return out;
}

} // namespace

std::vector<glm::dvec2> LinearProfile::curve(const Node* coordinates, float) const {
    const std::vector<glm::dvec4> points = homogeneous(coordinates, typeName);
    std::vector<glm::dvec2> out;
    out.reserve(index.size());
    for (const std::int32_t i : index.getValues()) {
        if (i < 0 || std::size_t(i) >= points.size()) continue;
        const glm::dvec4& p = points[std::size_t(i)];
        out.push_back(p.w != 0.0 ? glm::dvec2(p.x, p.y) / p.w : glm::dvec2(p.x, p.y));
    }
    return out;
}

std::vector<glm::dvec2> NurbsProfile::curve(const Node* coordinates, float complexity) const {
    const std::vector<glm::dvec4> points = homogeneous(coordinates, typeName);
    const auto& knots = knotVector.getValues();
    for (std::size_t i = 0; i < knots.size(); ++i)
        if (!std::isfinite(knots[i]))
            throw Error(std::string(typeName) + ": knot " + std::to_string(i) +
                        " is not a finite number");
    const auto& indices = index.getValues();
    if (!nurbsKnotProblem(std::int64_t(indices.size()), knots).empty()) return {};
    std::vector<glm::dvec4> control;
    control.reserve(indices.size());
    for (const std::int32_t i : indices) {
        if (i < 0 || std::size_t(i) >= points.size()) return {};
        control.push_back(points[std::size_t(i)]);
    }
    NurbsCurveData c;
    c.order = int(knots.size() - indices.size());
    c.knots = knots;
    c.points = control;
    const bool closed = control.front() == control.back();
    const double rate = nurbsCurveRate(int(control.size()), closed,
                                       double(knots.back() - knots.front()), complexity);
    try {
        return sampleNurbsCurve2D(c, rate, std::size_t(1) << 20);
    } catch (const Error& e) {
        throw Error(std::string(typeName) + ": " + e.message());
    }
}

std::uint64_t ProfilesInScope::key() const {
    std::uint64_t key = combineMeshKey(0x51ed27u, reinterpret_cast<std::uintptr_t>(coordinates));
    key = combineMeshKey(key, coordinates ? coordinates->version() : 0);
    for (const Profile* p : profiles) {
        key = combineMeshKey(key, reinterpret_cast<std::uintptr_t>(p));
        key = combineMeshKey(key, p->version());
    }
    return key;
}

ProfilesInScope gatherProfiles(const State& state) {
    ProfilesInScope out;
    for (const StateEntry& e : state.entries()) {
        const Node& node = *e.node;
        if (node.isA<Profile>()) {
            const auto& p = static_cast<const Profile&>(node);
            if (p.linkage() == Profile::START_FIRST) out.profiles.clear();
            out.profiles.push_back(&p);
        } else if (node.isA<ProfileCoordinate2>() || node.isA<ProfileCoordinate3>()) {
            out.coordinates = &node;
        }
    }
    return out;
}

namespace {

/// Appends `points` to `line`, leaving out a first point that repeats the line's last.
void join(std::vector<glm::dvec2>& line, const std::vector<glm::dvec2>& points) {
    for (std::size_t i = 0; i < points.size(); ++i)
        if (i > 0 || line.empty() || line.back() != points[i]) line.push_back(points[i]);
}

} // namespace

TrimLoops trimLoops(const ProfilesInScope& profiles, float complexity) {
    TrimLoops out;
    for (const Profile* p : profiles.profiles) {
        const std::vector<glm::dvec2> points = p->curve(profiles.coordinates, complexity);
        if (points.empty()) out.ok = false;
        if (out.loops.empty() || p->linkage() != Profile::ADD_TO_CURRENT) out.loops.emplace_back();
        join(out.loops.back(), points);
    }
    // Loops close on their own: a last point equal to the first is dropped; a loop with no
    // area cannot wind around anything.
    std::vector<std::vector<glm::dvec2>> kept;
    for (auto& loop : out.loops) {
        while (loop.size() > 1 && loop.back() == loop.front())
            loop.pop_back();
        if (loop.size() >= 3) kept.push_back(std::move(loop));
    }
    out.loops = std::move(kept);
    return out;
}

std::vector<glm::dvec2> textProfile(const ProfilesInScope& profiles, float complexity) {
    std::vector<glm::dvec2> out;
    std::size_t first = profiles.profiles.size();
    for (std::size_t i = 0; i < profiles.profiles.size(); ++i)
        if (profiles.profiles[i]->linkage() == Profile::START_FIRST) {
            first = i;
            break;
        }
    for (std::size_t i = first; i < profiles.profiles.size(); ++i)
        join(out, profiles.profiles[i]->curve(profiles.coordinates, complexity));
    return out;
}

} // namespace volsg
