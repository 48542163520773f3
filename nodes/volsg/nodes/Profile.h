#pragma once
// Profiles (Inventor's SoProfile, SoLinearProfile, SoNurbsProfile): curves through the
// ProfileCoordinate2/3 points in scope. The profiles in scope trim the NURBS surfaces after
// them and bevel the sides of Text3. Each profile joins the list in scope by its linkage:
// START_FIRST replaces the list, START_NEW appends a new curve (for a surface: a new trim
// loop), ADD_TO_CURRENT continues the last one.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include <volsg/core/Node.h>
#include <volsg/fields/Fields.h>

namespace volsg {

class State;

class Profile : public Inherit<Node, Profile> {
public:
    static constexpr const char* typeName = "Profile";
    enum Linkage { START_FIRST, START_NEW, ADD_TO_CURRENT };
    static const EnumValues linkageNames;
    MFInt32 index{this, "index", {0}};
    SFEnum linkage{this, "linkage", linkageNames, START_FIRST};

    void doAction(Action& action) override;

    /// The curve in the plane through the coordinates (a ProfileCoordinate2 or -3, or null):
    /// a polyline; NurbsProfile samples its curve at the rate Complexity gives NURBS curves.
    /// Empty when the profile describes no curve (no coordinates, a bad knot vector). Throws
    /// Error for a coordinate or knot that is not a finite number.
    virtual std::vector<glm::dvec2> curve(const Node* coordinates, float complexity) const = 0;

protected:
    ~Profile() override = default;
};

class LinearProfile : public Inherit<Profile, LinearProfile> {
public:
    static constexpr const char* typeName = "LinearProfile";
    static constexpr bool inventorBuiltin() { return true; }
    /// The indexed points in order; indices out of range are skipped.
    std::vector<glm::dvec2> curve(const Node* coordinates, float complexity) const override;

protected:
    ~LinearProfile() override = default;
};

class NurbsProfile : public Inherit<Profile, NurbsProfile> {
public:
    static constexpr const char* typeName = "NurbsProfile";
    static constexpr bool inventorBuiltin() { return true; }
    MFFloat knotVector{this, "knotVector", {0.0f}};
    std::vector<glm::dvec2> curve(const Node* coordinates, float complexity) const override;

protected:
    ~NurbsProfile() override = default;
};

/// The profiles in scope at a shape, as Inventor's profile element holds them, with the
/// profile coordinates in scope there.
struct ProfilesInScope {
    std::vector<const Profile*> profiles;
    const Node* coordinates = nullptr; ///< ProfileCoordinate2 or -3
    /// Changes when any of them (or their versions) change.
    std::uint64_t key() const;
};
ProfilesInScope gatherProfiles(const State& state);

/// Trim loops for a NURBS surface: each START_FIRST or START_NEW profile begins a loop,
/// ADD_TO_CURRENT ones continue it. `ok` is false when a profile describes no curve (GLU
/// draws no surface then).
struct TrimLoops {
    std::vector<std::vector<glm::dvec2>> loops;
    bool ok = true;
};
TrimLoops trimLoops(const ProfilesInScope& profiles, float complexity);

/// Text3's profile: the profiles from the START_FIRST one on, joined (a profile's first point
/// is dropped when it repeats the previous one's last). Empty without a START_FIRST profile
/// (Coin extrudes then).
std::vector<glm::dvec2> textProfile(const ProfilesInScope& profiles, float complexity);

} // namespace volsg
