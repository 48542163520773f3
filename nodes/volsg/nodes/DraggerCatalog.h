#pragma once
// The catalogs of Inventor's draggers (Dragger.h): per dragger type, its parts in the order of
// Coin's catalog tree with what each part is at rest.
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace volsg {

/// One part of a dragger's catalog.
struct DraggerPart {
    enum class Kind {
        Separator,         ///< a container: a Separator of its own per dragger
        Group,             ///< a container: a Group
        Switch,            ///< a container: a Switch showing `switchValue` at rest
        Motion,            ///< the motion matrix (motionMatrix)
        Null,              ///< no node unless the file sets the part
        Resource,          ///< the node named `value` in the type's resource file
        ChildDragger,      ///< a dragger of type `value`, at rest
        Inline,            ///< the node that the Inventor text `value` describes
        CenterMatrix,      ///< a MatrixTransform translating by the `center` field (Centerball)
        RotationInverse,   ///< a Rotation undoing the motion matrix's (light draggers)
        BeamScale,         ///< a Scale of tan(angle) in x and y (SpotLightDragger's beamScale)
        EdgeScaleCoords,   ///< a TabPlaneDragger's edge tabs' corners (Coordinate3)
        CornerScaleCoords, ///< its corner tabs' corners
    };
    std::string name;
    Kind kind = Kind::Null;
    std::string value;
    int switchValue = -1;
    /// ChildDragger: defaults for the child's parts (part or dotted path, then `@resource`
    /// of this type's file or `{}`), as Coin's setPartAsDefault on the child.
    std::vector<std::pair<std::string, std::string>> childDefaults;
    std::vector<int> children; ///< indices into the catalog's parts, in traversal order
};

struct DraggerCatalog {
    std::string typeName;           ///< "Translate1Dragger"
    std::string resourceFile;       ///< "translate1Dragger.iv", or empty
    std::vector<DraggerPart> parts; ///< parts[0] is topSeparator
    /// Coin's dragger of this type does not work the value fields read from a file into its
    /// motion matrix (its setUpConnections does not call its field sensor): it stays where
    /// the motionMatrix part puts it until a value field changes.
    bool readValuesIgnored = false;
};

/// The catalogs of every dragger type (parsed once from the table in DraggerCatalog.cpp).
const std::vector<DraggerCatalog>& draggerCatalogs();

/// The text of one of Coin's dragger resource files (draggerDefaults/), embedded in the
/// library at build time; empty for a name it does not have.
std::string_view draggerDefaultFile(std::string_view fileName);

} // namespace volsg
