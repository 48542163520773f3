#pragma once
// Evaluation of field connections, engines and animated nodes: the push model of
// docs/SCENE-FORMAT.md section 1.10.

#include <cstddef>
#include <functional>
#include <set>
#include <string>

#include <volsg/core/Node.h>

namespace volsg {

/// Brings a scene to a time. Keep one per scene (the viewer's, the renderer's) and call
/// evaluate(root, seconds) once per frame before drawing:
///
/// - every node and engine reachable from `root` (children, SFNode/MFNode values, connection
///   sources) is visited in dependency order: a connection's source before the field's owner;
/// - a connected field takes its source's value (converted between types as Inventor does,
///   fields/Fields.h assignConverted) when the source value differs from the one copied last;
///   engines evaluate after their inputs; global fields named realTime take `seconds`; Rotor,
///   Pendulum, Shuttle and Blinker animate to `seconds`;
/// - a field is set, so its node's version bumped, only when its value changes: caches built
///   from a node rebuild only then;
/// - a cycle of connections is broken at the connection that closes it, which is not
///   evaluated; the warning sink gets one line naming it, once per evaluator.
///
/// Warnings (a cycle, a field that cannot take its source's value, an engine that fails) are
/// one line each, prefixed with the file, line and column of the node they concern when it
/// was read from a file.
///
/// `seconds` is the scene time: 0 when the scene starts playing, growing in real seconds.
class ConnectionEvaluator {
public:
    using WarningSink = std::function<void(const std::string&)>;
    /// Warnings go to `sink` (default: standard error, prefixed "volsg: ").
    explicit ConnectionEvaluator(WarningSink sink = {});

    /// Returns how many fields changed value.
    std::size_t evaluate(Node& root, double seconds);

private:
    void warn(const Node& node, const std::string& message);
    WarningSink sink_;
    std::set<std::string> warned_;
};

/// One evaluation with a fresh evaluator (warnings to standard error each call); a scene
/// evaluated every frame should keep a ConnectionEvaluator instead.
std::size_t evaluateConnections(Node& root, double seconds);

} // namespace volsg
