#pragma once
// What the render and pick methods of Inventor's choosing groups share.
#include <glm/glm.hpp>

namespace volsg {

class LevelOfDetail;
class State;

/// The child a LevelOfDetail draws under a camera (view and projection, viewport in pixels) at
/// the current node of `state`: the box of all its children in its own coordinates, with the
/// state in scope, projected to the screen as Coin does (LevelOfDetail::screenSize). -1 when
/// it has no children.
int levelOfDetailChild(const State& state, LevelOfDetail& node, const glm::dmat4& view,
                       const glm::dmat4& projection, int width, int height);

} // namespace volsg
